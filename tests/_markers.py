"""pytest plugin: markers assigned from a test's folder, so a selection never depends on memory.

    tests/fmu/         -> fmu         (builds and drives the FMUs through fmpy)
    tests/cosim/       -> cosim       (co-simulation masters, closed loops, sweeps)
    tests/validation/  -> validation  (literature and standard cases)
    tests/stability/   -> stability   (stiff and extreme cases)

`slow` marks the tests listed in SLOW (more than ~10 s each on the 2-core reference machine: fresh
processes, hour-long closed loops, a Dask cluster, speed sweeps), kept here beside the folder rule so
every selection is decided in one place. `bare_host` marks the tests listed in BARE_HOST, which set up a
host environment of their own with pip (a virtual environment with only fmpy, numpy and numba: about a
minute with pip's cache, and registry access): `make test` leaves them out, `make test-bare-host` runs
them; likewise `python_hosts` (the FMUs in fmpy and native hosts on every supported Python, 3.10-3.13:
a pip environment per Python, minutes) and `make test-python-hosts`, and `ehl_full` (the numerical EHL
solver's long studies: all 55 Annexe D cases, a heavy contact on the finest grid) and `make test-ehl-full`,
and `ssp_masters` (the exported SSP packages in ecos and OMSimulator: a pip environment with ecospy, minutes of
runs) and `make test-ssp-masters`.
The quick loop while editing kernels and models is `pytest -m "not slow and not fmu and not cosim"`
(about a minute); `make test` runs everything else.
"""

from pathlib import Path

FOLDER_MARKERS = {"fmu": "fmu", "cosim": "cosim", "validation": "validation", "stability": "stability"}
SLOW = {  # test file -> test function names (every parametrisation of them)
    "tests/fmu/test_bearing_analytic_fmu.py": {"test_thirty_fresh_processes_exit_cleanly"},
    "tests/fmu/test_fuzz.py": {"test_fuzz_full", "test_fuzz_inside"},
    "tests/fmu/test_native_runtime.py": {"test_a_hundred_native_hosts_set_up_two_fmus_from_two_threads"},
    "tests/cosim/test_closed_loop.py": {
        "test_fixed_6000_preload_rises_with_temperature_and_settles",
        "test_fixed_10000_runs_away_and_stops_with_a_message",
    },
    "tests/cosim/test_sweep.py": {"test_dask_sweep_equals_sequential_table"},
    "tests/unit/test_film_check.py": {"test_a_contact_its_level_does_not_converge_is_solved_on_the_next_finer"},
    "tests/cosim/test_shaft_transient_run.py": {"test_the_time_domain_run_settles_on_the_static_equilibrium"},
    "tests/cosim/test_libcosim_master.py": {"test_fresh_processes_exit_0"},
    "tests/cosim/test_teardown.py": {"test_fresh_processes_exit_0_through_the_normal_teardown"},
    "tests/validation/test_quasistatic_literature.py": {"test_controlling_race_split_is_discontinuous_in_speed"},
    "tests/validation/test_ehl_annexe_d.py": {"test_grid_convergence_is_second_order_and_level_3_within_2_percent"},
    "tests/validation/test_ehl_hertz_limit.py": {"test_pressure_tends_to_hertz_as_the_speed_vanishes"},
    "tests/validation/test_ehl_thin_films.py": {"test_thin_film_converges_on_the_default_grid_with_a_positive_film"},
    "tests/validation/test_ehl_light_contact.py": {
        "test_light_fast_contact_converges_on_levels_2_to_4_and_level_3_is_within_1_percent",
        "test_large_L_contacts_converge_by_line_relaxation",
    },
    "tests/stability/test_large_free_angle_grid.py": {
        "test_every_grid_point_converges_or_is_refused_for_a_physical_reason"
    },
}
# the numerical EHL solver's long studies (about 4 min of the 55 Annexe D cases, 22 of which fall outside their
# tolerances, docs/ehl_solver.md, a heavy contact on levels 3-5, 1-3 min, and the operating box's sweep, 64 solves on
# levels 3-4): `make test-ehl-full`, outside `make test`
EHL_FULL = {
    "tests/validation/test_ehl_annexe_d.py": {
        "test_every_case_matches_annexe_d",
        "test_the_cases_outside_converge_and_are_those_documented",
    },
    "tests/validation/test_ehl_heavy_contacts.py": {"test_a_heavy_contact_is_solved_on_the_level_its_film_needs"},
    "tests/validation/test_ehl_fine_grids.py": {
        "test_levels_4_and_5_converge_at_wide_contacts_of_large_L",
        "test_a_thin_film_below_L_11_keeps_the_injected_coarse_pressure_on_level_4",
    },
    "tests/validation/test_ehl_thin_films.py": {"test_a_thin_film_is_solved_on_the_level_its_film_needs"},
    "tests/validation/test_ehl_operating_box.py": {
        "test_every_contact_of_the_operating_box_converges_on_its_level",
        "test_the_6208_at_3_kN_converges_at_every_speed_near_1700_rad_s",
    },
}
BARE_HOST = {  # test file -> test function names that build a pip environment of their own
    "tests/fmu/test_bare_host.py": {"test_thermal_fmu_runs_in_a_host_with_only_fmpy_numpy_numba"},
}
# the FMUs on every supported Python (3.10-3.13): a pip environment per Python and FMUs built with kernels for
# each (minutes): `make test-python-hosts`, outside `make test`
PYTHON_HOSTS = {
    "tests/fmu/test_python_hosts.py": {
        "test_fmpy_hosts_on_every_python_give_the_same_outputs_without_compiling",
        "test_native_hosts_start_every_python_with_the_same_outputs",
        "test_a_python_without_the_fmus_kernels_compiles_them_and_says_so",
    },
}

# the exported SSP packages in ecos and OMSimulator (tests/cosim/test_ssp_masters.py: a pip environment with
# ecospy, both run files at full length in each master): `make test-ssp-masters`, outside `make test`
SSP_MASTERS = {
    "tests/cosim/test_ssp_masters.py": {
        "test_ecos_runs_the_package_as_spindle_run",
        "test_libcosim_runs_the_package_as_spindle_run",
        "test_omsimulator_runs_the_package_as_spindle_run",
    },
}

# every list marks its tests slow; all but SLOW also with a marker of their own (the make target's selection)
LISTS = (
    (SLOW, None),
    (EHL_FULL, "ehl_full"),
    (BARE_HOST, "bare_host"),
    (PYTHON_HOSTS, "python_hosts"),
    (SSP_MASTERS, "ssp_masters"),
)


def pytest_collection_modifyitems(config, items):
    import pytest

    root = Path(str(config.rootpath))
    for item in items:
        path = Path(str(item.fspath))
        marker = FOLDER_MARKERS.get(path.parent.name)
        if marker:
            item.add_marker(getattr(pytest.mark, marker))
        name = getattr(item, "originalname", item.name)
        relative = path.relative_to(root).as_posix()
        for listed, own_marker in LISTS:
            if name in listed.get(relative, ()):
                item.add_marker(pytest.mark.slow)
                if own_marker:
                    item.add_marker(getattr(pytest.mark, own_marker))
