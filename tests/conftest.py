"""Shared fixtures: paths to the reference data and the built FMUs (built once if missing)."""
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SHARED = ROOT.parent / "shared"
FMU_DIR = ROOT / "fmus"


@pytest.fixture(scope="session")
def annexe_d_path():
    path = SHARED / "reference" / "thesis_annexe_d_ehl.csv"
    if not path.is_file():
        pytest.fail(f"reference data missing: {path} (shared/ must sit beside the checkout)")
    return path


def _fmu(name, scene_file):
    """Path of fmus/<name>.fmu; built from the current sources if it is missing or stale."""
    from bearing_fmu.build import build_fmu, SCENES_DIR, PACKAGE_DIR
    path = FMU_DIR / f"{name}.fmu"
    newest_source = max(p.stat().st_mtime for p in PACKAGE_DIR.rglob("*") if p.suffix in (".py", ".toml"))
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
