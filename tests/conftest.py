"""Shared fixtures: paths to the reference data and the built FMUs (built once if missing)."""

import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "tests" / "validation" / "data"
FMU_DIR = ROOT / "fmus"


@pytest.fixture(scope="session")
def annexe_d_path():
    path = DATA / "thesis_annexe_d_ehl.csv"
    if not path.is_file():
        pytest.fail(f"reference data missing: {path}")
    return path


def _fmu(name, scene_file):
    """Path of fmus/<name>.fmu; built from the current sources if it is missing or stale."""
    from bearing_fmu.build import COMMON_DIR, PACKAGE_DIR, SCENES_DIR, build_fmu

    path = FMU_DIR / f"{name}.fmu"
    newest_source = max(
        p.stat().st_mtime for d in (PACKAGE_DIR, COMMON_DIR) for p in d.rglob("*") if p.suffix in (".py", ".toml", ".c")
    )
    if not path.is_file() or path.stat().st_mtime < newest_source:
        build_fmu(SCENES_DIR / scene_file, FMU_DIR)
    return path


@pytest.fixture(scope="session")
def analytic_fmu():
    return _fmu("BearingAnalytic", "analytic.toml")


@pytest.fixture(scope="session")
def bearing_fmu():
    """The quasi-static, load-driven Bearing.fmu."""
    return _fmu("Bearing", "quasi_static.toml")


@pytest.fixture(scope="session")
def bearing_disp_fmu():
    """The quasi-static, displacement-driven BearingDisp.fmu."""
    return _fmu("BearingDisp", "quasi_static_displacement.toml")


@pytest.fixture(scope="session")
def bearing_fixed_fmu():
    """The quasi-static BearingFixed.fmu (fixed axial position: fixed-preload pairs)."""
    return _fmu("BearingFixed", "quasi_static_fixed_preload.toml")


def _thermal_fmu(name):
    """Path of fmus/<name>.fmu (a thermal spindle FMU of spindle.all_fmus.THERMAL_FMUS); rebuilt if it is
    missing or older than any source it bundles (the spindle and bearing_fmu packages)."""
    from bearing_fmu.build import COMMON_DIR, PACKAGE_DIR
    from spindle.all_fmus import SPINDLE_DIR, THERMAL_FMUS, build_thermal_fmu

    path = FMU_DIR / f"{name}.fmu"
    newest_source = max(
        p.stat().st_mtime
        for d in (PACKAGE_DIR, COMMON_DIR, SPINDLE_DIR)
        for p in d.rglob("*")
        if p.suffix in (".py", ".toml", ".c")
    )
    if not path.is_file() or path.stat().st_mtime < newest_source:
        network, axial_float = THERMAL_FMUS[name]
        build_thermal_fmu(name, network, axial_float, FMU_DIR)
    return path


@pytest.fixture(scope="session")
def spindle_thermal_fmu():
    """SpindleThermal.fmu: the default spindle network without the axial-float inputs (spring preload)."""
    return _thermal_fmu("SpindleThermal")


@pytest.fixture(scope="session")
def spindle_thermal_fixed_fmu():
    """SpindleThermalFixed.fmu: the default network with the axial-float inputs (fixed preload)."""
    return _thermal_fmu("SpindleThermalFixed")


CONFIGURED = ("BearingDEM", "Bearing", "SpindleThermal")  # the configured FMUs the tests build (of every kind)


@pytest.fixture(scope="session")
def configured_fmus(tmp_path_factory):
    """The configured FMUs of configs/rabreau_rig.toml (`spindle build --config`), those of CONFIGURED, built
    once per session into a temporary folder: name (e.g. BearingDEM_B7214C) -> path."""
    from spindle.configured import build_configured

    out = tmp_path_factory.mktemp("configured_fmus")
    config = out / "rabreau_rig.toml"
    config.write_text((ROOT / "configs" / "rabreau_rig.toml").read_text() + f"fmus = {list(CONFIGURED)!r}\n")
    paths, _ = build_configured(config, out)
    return {path.stem: path for path in map(Path, paths)}


def pip_environment(name, pins):
    """python of a virtual environment /tmp/bearing_fmu-<name>-py3X-<pins> with the packages `pins` ("pkg==1.2"),
    made with pip on first use and kept between runs (a marker file says it is complete); the test is skipped
    when pip cannot make it (no registry here: not a product failure)."""
    tag = "-".join(pins).replace("==", "")
    home = Path("/tmp") / f"bearing_fmu-{name}-py{sys.version_info.major}{sys.version_info.minor}-{tag}"
    python = home / "bin" / "python"
    if not (home / ".complete").is_file():
        base = getattr(sys, "_base_executable", sys.executable)
        subprocess.run([base, "-m", "venv", "--clear", str(home)], check=True, capture_output=True)
        pip = subprocess.run(
            [str(python), "-m", "pip", "install", "-q", *pins], capture_output=True, text=True, timeout=1800
        )
        if pip.returncode != 0:
            pytest.skip(f"pip install {' '.join(pins)} failed: {pip.stderr[-500:]}")
        (home / ".complete").write_text(" ".join(pins))
    return python
