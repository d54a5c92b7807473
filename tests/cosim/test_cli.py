"""The `spindle` command line: version, validate, run with an FMU folder, and its exit codes."""

import shutil

import pytest

from bearing_fmu import __version__
from spindle import cli

DEMO = cli.RUNS / "closed_loop_spring.toml"


def test_version_is_the_package_version(capsys):
    with pytest.raises(SystemExit) as exc:
        cli.main(["--version"])
    assert exc.value.code == 0
    assert capsys.readouterr().out.strip() == f"spindle {__version__}"


def test_help_lists_the_exit_codes(capsys):
    with pytest.raises(SystemExit):
        cli.main(["--help"])
    out = capsys.readouterr().out
    for code in (cli.EXIT_OK, cli.EXIT_ERROR, cli.EXIT_INVALID, cli.EXIT_LIMIT):
        assert f"  {code}  " in out


def test_validate_accepts_a_built_fmu_and_rejects_a_broken_one(bearing_fmu, tmp_path, capsys):
    assert cli.main(["validate", str(bearing_fmu)]) == cli.EXIT_OK
    assert f"{bearing_fmu.name}: valid" in capsys.readouterr().out
    broken = tmp_path / "Broken.fmu"
    broken.write_bytes(b"not a zip archive")
    assert cli.main(["validate", str(broken)]) == cli.EXIT_INVALID
    assert "Broken.fmu: " in capsys.readouterr().out


def test_run_with_an_fmu_folder(closed_loop_fmus, tmp_path):
    """`--fmus DIR` takes the run file's FMU file names from DIR (an installed package has no fmus/ beside
    the run file); 3 steps of the demo give a CSV with a row per communication point."""
    folder = tmp_path / "elsewhere"
    folder.mkdir()
    for name in ("Bearing", "SpindleThermal"):
        shutil.copy2(closed_loop_fmus[name], folder)
    out = tmp_path / "results"
    args = ["run", str(DEMO), "--fmus", str(folder), "--set", "run.stop=3", "--no-plot", "--out", str(out)]
    assert cli.main(args) == cli.EXIT_OK
    rows = (out / "closed_loop_spring.csv").read_text().strip().splitlines()
    assert len(rows) == 1 + 4  # header + t = 0, 1, 2, 3 s


def test_run_names_a_missing_fmu(tmp_path, capsys):
    args = ["run", str(DEMO), "--fmus", str(tmp_path), "--set", "run.stop=3", "--no-plot", "--out", str(tmp_path)]
    assert cli.main(args) == cli.EXIT_ERROR
    err = capsys.readouterr().err
    assert "FMU not found" in err and str(tmp_path / "Bearing.fmu") in err and "spindle build" in err
