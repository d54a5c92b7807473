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


def _stale(path, folders):
    """Whether the FMU at `path` is missing or older than any source it bundles (.py, .toml, .c, .h below
    `folders`)."""
    newest_source = max(
        p.stat().st_mtime for d in folders for p in d.rglob("*") if p.suffix in (".py", ".toml", ".c", ".h")
    )
    return not path.is_file() or path.stat().st_mtime < newest_source


def _fmu(name, scene_file):
    """Path of fmus/<name>.fmu; built from the current sources if it is missing or stale."""
    from bearing_fmu.build import COMMON_DIR, PACKAGE_DIR, SCENES_DIR, build_fmu

    path = FMU_DIR / f"{name}.fmu"
    if _stale(path, (PACKAGE_DIR, COMMON_DIR)):
        build_fmu(SCENES_DIR / scene_file, FMU_DIR)
    return path


def _thermal_fmu(name):
    """Path of fmus/<name>.fmu (a thermal spindle FMU of spindle.all_fmus.THERMAL_FMUS); rebuilt if it is
    missing or older than any source it bundles (the spindle and bearing_fmu packages)."""
    from bearing_fmu.build import COMMON_DIR, PACKAGE_DIR
    from spindle.all_fmus import SPINDLE_DIR, THERMAL_FMUS, build_thermal_fmu

    path = FMU_DIR / f"{name}.fmu"
    if _stale(path, (PACKAGE_DIR, COMMON_DIR, SPINDLE_DIR)):
        network, axial_float = THERMAL_FMUS[name]
        build_thermal_fmu(name, network, axial_float, FMU_DIR)
    return path


def _shaft_fmu(name="SpindleShaft"):
    """Path of fmus/<name>.fmu (a shaft FMU of spindle.all_fmus.SHAFT_FMUS); rebuilt if it is missing or older than
    any source it bundles (the spindle package and the shared one)."""
    from bearing_fmu.build import COMMON_DIR
    from spindle.all_fmus import SPINDLE_DIR, build_shaft_fmu

    path = FMU_DIR / f"{name}.fmu"
    if _stale(path, (COMMON_DIR, SPINDLE_DIR)):
        build_shaft_fmu(FMU_DIR, name=name)
    return path


def _session_fixture(doc, path_of, *args):
    """A session fixture (its docstring: doc) giving path_of(*args): the path of an FMU, built at most once."""

    def fixture():
        return path_of(*args)

    fixture.__doc__ = doc
    return pytest.fixture(scope="session")(fixture)


# The FMUs of the product's scenes and networks; each fixture is named by the variable that holds it.
analytic_fmu = _session_fixture("The analytic BearingAnalytic.fmu.", _fmu, "BearingAnalytic", "analytic.toml")
bearing_fmu = _session_fixture("The quasi-static, load-driven Bearing.fmu.", _fmu, "Bearing", "quasi_static.toml")
bearing_disp_fmu = _session_fixture(
    "The quasi-static, displacement-driven BearingDisp.fmu.", _fmu, "BearingDisp", "quasi_static_displacement.toml"
)
bearing_fixed_fmu = _session_fixture(
    "The quasi-static BearingFixed.fmu (fixed axial position: fixed-preload pairs).",
    _fmu,
    "BearingFixed",
    "quasi_static_fixed_preload.toml",
)
dem_disp_fmu = _session_fixture(
    "The DEM BearingDEMDisp.fmu (the inner ring's motion prescribed).", _fmu, "BearingDEMDisp", "dem_displacement.toml"
)
spindle_thermal_fmu = _session_fixture(
    "SpindleThermal.fmu: the default spindle network without the axial-float inputs (spring preload).",
    _thermal_fmu,
    "SpindleThermal",
)
spindle_thermal_fixed_fmu = _session_fixture(
    "SpindleThermalFixed.fmu: the default network with the axial-float inputs (fixed preload).",
    _thermal_fmu,
    "SpindleThermalFixed",
)

spindle_shaft_fmu = _session_fixture(
    "SpindleShaft.fmu: the default shaft's rotor model with its two bearing seats.", _shaft_fmu
)
spindle_shaft_transient_fmu = _session_fixture(
    "SpindleShaftTransient.fmu: the default shaft's time-domain mode with its two bearing seats.",
    _shaft_fmu,
    "SpindleShaftTransient",
)


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
