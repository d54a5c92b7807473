"""What an FMU carries of the product (bearing_fmu.bundle, docs/fmu_runtime.md, What an FMU carries): the modules its
entry runs and their data, nothing of the build, the offline film-table solver, the command line or the master."""

import ast
from pathlib import Path

from bearing_fmu.build import BEARING_BUNDLE, COMMON_DIR, PACKAGE_DIR
from bearing_fmu.bundle import run_modules
from spindle.all_fmus import SHAFT_BUNDLE, THERMAL_BUNDLE

# modules an FMU never runs: building FMUs and film tables, the numerical EHL solver, the native layer's build and
# its hosts, the command line, the master
OFFLINE = (
    "bearing_fmu/build.py",
    "bearing_fmu/bundle.py",
    "bearing_fmu/compiled_code.py",
    "bearing_fmu/models/film_table_build.py",
    "bearing_fmu/models/ehl_numerical.py",
    "bearing_fmu/models/film_check.py",
    "bearing_fmu/kernels/ehl_solver.py",
    "bearing_fmu_common/runtime/binaries.py",
    "bearing_fmu_common/runtime/fmi2_python.c",
    "spindle/cli.py",
    "spindle/cosim/master.py",
)


def carried(bundle):
    return {dest for _, dest in bundle}


def test_a_bearing_fmu_carries_what_it_runs_and_nothing_offline():
    files = carried(BEARING_BUNDLE)
    assert not files & set(OFFLINE)
    for module in ("bearing_fmu/fmu.py", "bearing_fmu/models/dem/model.py", "bearing_fmu/models/film_table.py"):
        assert module in files
    assert "bearing_fmu/params/bearings/B7214C.toml" in files and "bearing_fmu/params/dem_model.toml" in files
    assert not any(f.startswith("bearing_fmu/scenes/") for f in files)  # the scene is written into its class


def test_a_thermal_fmu_carries_no_bearing_model_nor_master():
    files = carried(THERMAL_BUNDLE)
    assert not files & set(OFFLINE)
    assert not any(f.startswith("bearing_fmu/") for f in files)
    assert "spindle/thermal/fmu.py" in files and ("spindle/thermal/bearings" in files)


def test_the_shaft_and_thermal_fmus_carry_one_copy_of_spindle():
    """A process keeps one `spindle`, the first FMU's: the shaft FMU set up after a thermal FMU (the warm-up system in
    a host such as ecos) must find its own files there, so both carry the same copy: the two FMU models and their
    catalogues, no bearing model, nothing offline, not the master or the command line."""

    def spindle_files(bundle):
        return {dest for _, dest in bundle if dest.startswith("spindle/")}

    assert spindle_files(SHAFT_BUNDLE) == spindle_files(THERMAL_BUNDLE)
    files = carried(SHAFT_BUNDLE)
    assert not files & set(OFFLINE)
    assert not any(f.startswith(("bearing_fmu/", "spindle/cosim/")) for f in files) and "spindle/cli.py" not in files
    assert {"spindle/shaft/fmu.py", "spindle/shaft/model.py", "spindle/shaft/beam.py"} <= files
    assert "spindle/thermal/fmu.py" in files
    assert "spindle/shaft/params/rabreau_b7214c.toml" in files


def test_every_fmu_carries_the_same_files_of_the_shared_package():
    """A process keeps one bearing_fmu_common, the first FMU's: an FMU of another kind set up after it must find the
    same files there (the layer refuses it otherwise, docs/fmu_runtime.md, Its own code)."""

    def common(bundle):
        return {dest for _, dest in bundle if dest.startswith("bearing_fmu_common/")}

    assert common(BEARING_BUNDLE) == common(THERMAL_BUNDLE) == common(SHAFT_BUNDLE)
    assert "bearing_fmu_common/layout.py" in common(THERMAL_BUNDLE)  # the bearing FMUs run it, the thermal ones not


def test_the_modules_run_are_the_imports_at_any_depth_with_the_packages_above():
    """models.film_table imports the catalogue (bearing_fmu.params) only inside a function: it is carried; so is
    each package's __init__.py above a carried module; the film-table solver, which nothing of it imports, is not."""
    packages = ((PACKAGE_DIR, "bearing_fmu"), (COMMON_DIR, "bearing_fmu_common"))
    modules = run_modules(packages, ("bearing_fmu.models.film_table",))
    assert {"bearing_fmu.params", "bearing_fmu", "bearing_fmu.models", "bearing_fmu.kernels"} <= set(modules)
    assert "bearing_fmu.models.film_table_build" not in modules and "bearing_fmu.kernels.ehl_solver" not in modules
    top = ast.parse(Path(modules["bearing_fmu.models.film_table"]).read_text())
    assert not any(isinstance(n, ast.ImportFrom) and n.module == "params" for n in top.body), (
        "not a lazy import any more"
    )
