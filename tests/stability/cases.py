"""The stability cases: every stiff or extreme case, the fidelities it covers and the tests that state and
check its outcome (each test's docstring says the case and the expected outcome). The report lists this
table; tests/stability/test_cases.py checks that every test named here exists.

Most cases live in this folder; a few are checked where their machinery is: the low-speed run-ups of the
quasi-static solver (tests/unit), the fixed-preload runaway of the closed loop (tests/cosim) and the DEM
time-step monitor (tests/validation).
"""

S = "tests/stability/"
CASES = (
    # (case, fidelities, test file, test function)
    (
        "zero speed",
        "analytic",
        S + "test_speed_extremes.py",
        "test_analytic_at_rest_gives_the_static_load_distribution",
    ),
    (
        "zero speed",
        "quasi-static",
        S + "test_speed_extremes.py",
        "test_quasi_static_at_rest_is_converged_without_torque",
    ),
    (
        "zero speed",
        "DEM",
        S + "test_speed_extremes.py",
        "test_dem_at_rest_carries_the_load_of_the_quasi_static_fidelity",
    ),
    (
        "very low speed, run-up from rest",
        "quasi-static",
        "tests/unit/test_quasistatic_low_speed.py",
        "test_run_up_from_rest_under_load_refuses_no_step",
    ),
    (
        "very low speed",
        "quasi-static",
        "tests/unit/test_quasistatic_low_speed.py",
        "test_low_speed_grid_refuses_no_step",
    ),
    (
        "speed reversal",
        "analytic, quasi-static",
        S + "test_speed_extremes.py",
        "test_speed_reversal_mirrors_the_solution",
    ),
    ("speed reversal", "DEM", S + "test_speed_extremes.py", "test_dem_speed_reversal_runs_through_zero"),
    (
        "very high speed (d_m n >= 2e6 mm.rpm)",
        "quasi-static",
        S + "test_speed_extremes.py",
        "test_quasi_static_at_very_high_speed_is_centrifugal_dominated",
    ),
    (
        "very high speed (d_m n >= 2e6 mm.rpm)",
        "DEM",
        S + "test_speed_extremes.py",
        "test_dem_at_very_high_speed_is_stable_and_slips",
    ),
    ("speed beyond d_m n = 4e6 mm.rpm", "all", S + "test_speed_extremes.py", "test_speed_beyond_the_limit_is_refused"),
    (
        "zero load (balls lose contact, singular stiffness)",
        "quasi-static",
        S + "test_load_and_clearance_extremes.py",
        "test_zero_load_gives_a_finite_centred_unloaded_bearing",
    ),
    (
        "zero load, history",
        "quasi-static",
        "tests/unit/test_quasistatic_low_speed.py",
        "test_zero_load_in_clearance_gives_the_centre_whatever_the_history",
    ),
    ("zero load", "analytic", S + "test_load_and_clearance_extremes.py", "test_analytic_zero_load_has_no_loaded_ball"),
    ("load removed", "DEM", S + "test_dem_steps.py", "test_load_removed_leaves_a_bounded_rattle"),
    (
        "p_max > 4.2 GPa",
        "analytic, quasi-static",
        S + "test_load_and_clearance_extremes.py",
        "test_pressure_beyond_iso_76_is_computed_with_a_warning",
    ),
    (
        "p_max > 6 GPa",
        "analytic, quasi-static",
        S + "test_load_and_clearance_extremes.py",
        "test_load_beyond_the_material_limit_is_refused",
    ),
    (
        "large negative and positive clearance",
        "quasi-static",
        S + "test_load_and_clearance_extremes.py",
        "test_large_clearance_or_interference_converges",
    ),
    (
        "clearance beyond the geometric limits",
        "quasi-static",
        S + "test_load_and_clearance_extremes.py",
        "test_clearance_outside_the_geometric_limits_is_refused",
    ),
    (
        "interference of the whole groove clearance",
        "quasi-static",
        S + "test_load_and_clearance_extremes.py",
        "test_interference_at_the_geometric_limit_is_refused_by_pressure",
    ),
    (
        "clearance at the geometric limit (free angle 58-60 deg)",
        "quasi-static",
        S + "test_load_and_clearance_extremes.py",
        "test_clearance_near_the_geometric_limit_converges_or_says_so",
    ),
    (
        "large free contact angles (P_d 0.3-1.0 A), mostly radial and thrust-dominated loads, 0-1000 rad/s",
        "quasi-static",
        S + "test_large_free_angle_grid.py",
        "test_every_grid_point_converges_or_is_refused_for_a_physical_reason",
    ),
    ("step loads", "DEM", S + "test_dem_steps.py", "test_load_step_settles_on_the_quasi_static_displacement"),
    ("speed steps", "DEM", S + "test_dem_steps.py", "test_speed_step_accelerates_the_cage_without_overshoot"),
    (
        "time step beyond the stability limit",
        "DEM",
        "tests/validation/test_dem_6208.py",
        "test_too_large_time_step_is_detected",
    ),
    (
        "default time step, 0.1-1.7 krad/s, 0.75-7.5 kN",
        "DEM",
        "tests/validation/test_dem_6208.py",
        "test_default_time_step_is_stable_for_0_2_s",
    ),
    (
        "tiny thermal capacities, huge conductances, large steps",
        "thermal",
        S + "test_stiff_network.py",
        "test_step_heat_monotone_no_overshoot",
    ),
    (
        "stiff network: explicit integration fails",
        "thermal",
        S + "test_stiff_network.py",
        "test_forward_euler_blows_up_at_these_steps",
    ),
    (
        "co-simulation step >> fastest time constant",
        "closed loop",
        S + "test_large_communication_steps.py",
        "test_step_of_sixty_seconds_settles_on_the_fine_run",
    ),
    (
        "co-simulation step >> fastest time constant",
        "closed loop",
        S + "test_large_communication_steps.py",
        "test_step_of_five_minutes_stops_with_the_limit_message",
    ),
    (
        "fixed-preload thermal runaway",
        "closed loop",
        "tests/cosim/test_closed_loop.py",
        "test_fixed_10000_runs_away_and_stops_with_a_message",
    ),
    (
        "angular-contact bearing under heavy thrust, 3 000-12 000 rpm, kicked: no ring whirl",
        "DEM",
        "tests/validation/test_dem_thrust_whirl.py",
        "test_orbit_decays_below_one_percent_of_the_axial_deflection",
    ),
    (
        "angular-contact bearing under heavy thrust, 8 000 rpm, kicked: orbit below 0.1 um",
        "DEM",
        "tests/validation/test_dem_thrust_whirl.py",
        "test_orbit_at_8000_rpm_stays_below_a_tenth_of_a_micrometre",
    ),
    (
        "angular-contact bearing, ring free to tilt under combined load: steady, along the quasi-static solution",
        "DEM",
        "tests/validation/test_dem_tilt.py",
        "test_free_ring_matches_the_quasi_static_free_ring",
    ),
    (
        "angular-contact bearing at 10 000 rpm, 800 N thrust: outer-race control, no swing",
        "DEM",
        "tests/validation/test_dem_b7214c.py",
        "test_with_the_ehl_traction_curve_it_is_outer_race_control",
    ),
    (
        "healthy-bearing spectrum: only bearing frequencies",
        "DEM",
        "tests/validation/test_dem_spectrum.py",
        "test_healthy_bearing_spectrum_has_only_bearing_frequencies",
    ),
    (
        "contacts at the shoulder (light thrust, high speed)",
        "quasi-static, DEM",
        "tests/validation/test_shoulder_truncation.py",
        "test_218_dem_light_thrust_high_speed_is_truncated_and_warned_at_entry_and_each_doubling",
    ),
    (
        "stiff film traction (mixed film, 3-6 kN): the dissipated power does not depend on the step",
        "DEM",
        "tests/validation/test_dem_dissipation_step.py",
        "test_torque_does_not_depend_on_the_step",
    ),
    (
        "angular-contact bearing, thrust and combined load, 3 000-15 000 rpm",
        "quasi-static, DEM",
        S + "test_angular_contact_speed_range.py",
        "test_angular_contact_bearing_runs_stable_from_3000_to_15000_rpm",
    ),
    (
        "cold oil start: the film turns full within a communication step",
        "DEM",
        "tests/validation/test_dem_full_film_damping.py",
        "test_automatic_step_follows_the_film_into_full_film",
    ),
    (
        "NaN, inf and out-of-range values on every input and parameter",
        "every FMU",
        "tests/fmu/test_fuzz.py",
        "test_fuzz_fast",
    ),
    (
        "native host: NULL instance or arguments",
        "FMI layer",
        "tests/fmu/test_native_runtime.py",
        "test_every_entry_point_refuses_a_null_instance",
    ),
    (
        "native host: calls out of the FMI call sequence",
        "FMI layer",
        "tests/fmu/test_native_runtime.py",
        "test_calls_out_of_the_fmi_call_sequence_are_refused",
    ),
    (
        "native host: a failed reset, then doStep",
        "FMI layer",
        "tests/fmu/test_native_runtime.py",
        "test_calls_after_a_failed_reset_return_error",
    ),
    (
        "native host: two FMUs set up from two threads at once",
        "FMI layer",
        "tests/fmu/test_native_runtime.py",
        "test_a_native_host_sets_up_two_fmus_from_two_threads",
    ),
    (
        "cold oil outside the lubricant's data",
        "analytic, quasi-static, DEM",
        "tests/unit/test_oil_temperature_range.py",
        "test_analytic_and_dem_warn_once_per_entry",
    ),
)
