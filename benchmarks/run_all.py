"""Run every benchmark and rewrite the reports in docs/reports/ (make bench)."""
from . import (ehl_film_table, fmu_startup, hertz_approximation, kernel_timing, quasistatic_timing,
               rabreau_preload, torque_palmgren)


def main():
    for module in (kernel_timing, hertz_approximation, ehl_film_table, fmu_startup, torque_palmgren,
                   quasistatic_timing, rabreau_preload):
        module.main()


if __name__ == "__main__":
    main()
