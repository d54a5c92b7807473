"""Fixtures of the co-simulation tests: the FMUs of the closed-loop run files and a clock probe FMU."""

import subprocess
import sys
from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def closed_loop_fmus(bearing_fmu, bearing_fixed_fmu, spindle_thermal_fmu, spindle_thermal_fixed_fmu):
    """The four FMUs runs/closed_loop_*.toml load from fmus/ (built or rebuilt if stale)."""
    return {
        "Bearing": bearing_fmu,
        "BearingFixed": bearing_fixed_fmu,
        "SpindleThermal": spindle_thermal_fmu,
        "SpindleThermalFixed": spindle_thermal_fixed_fmu,
    }


def build_test_fmu(script, model_name, tmp_path_factory):
    """Build a small pythonfmu test FMU from tests/cosim/<script> into a fresh temporary directory."""
    out = tmp_path_factory.mktemp(model_name.lower())
    proc = subprocess.run(
        [sys.executable, "-m", "pythonfmu", "build", "-f", str(Path(__file__).with_name(script)), "-d", str(out)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 0, proc.stderr
    return out / f"{model_name}.fmu"


@pytest.fixture(scope="session")
def clock_fmu(tmp_path_factory):
    """ClockSlave.fmu built from tests/cosim/clock_slave.py (see its docstring)."""
    return build_test_fmu("clock_slave.py", "ClockSlave", tmp_path_factory)
