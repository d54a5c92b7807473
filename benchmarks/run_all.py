"""Run every benchmark and rewrite the reports in docs/reports/ (make bench)."""

from . import (
    closed_loop,
    cosim_error,
    dem_closed_loop,
    dem_closed_loop_steps,
    dem_figures,
    dem_fmu,
    dem_steps,
    dem_timing,
    ehl_fields,
    ehl_film_table,
    fidelity_ladder,
    film_check,
    first_start,
    fixed_preload_stability,
    fmu_startup,
    hertz_approximation,
    kernel_timing,
    master_memory,
    option_cost,
    portable_cost,
    quasistatic_low_speed,
    quasistatic_timing,
    rabreau_preload,
    rabreau_torque_sensitivity,
    solver_tolerance,
    torque_palmgren,
)


def main():
    for module in (
        kernel_timing,
        hertz_approximation,
        ehl_fields,
        ehl_film_table,
        fmu_startup,
        first_start,
        portable_cost,
        torque_palmgren,
        quasistatic_timing,
        quasistatic_low_speed,
        solver_tolerance,
        option_cost,
        rabreau_preload,
        rabreau_torque_sensitivity,
        closed_loop,
        cosim_error,
        fixed_preload_stability,
        dem_timing,
        dem_steps,
        film_check,
        dem_figures,
        dem_fmu,
        dem_closed_loop,
        dem_closed_loop_steps,
        fidelity_ladder,
        master_memory,
    ):
        module.main()


if __name__ == "__main__":
    main()
