"""The `spindle` command line: version, validate, run with an FMU folder, and its exit codes."""

import csv
import json
import shutil
import subprocess
import sys

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


def test_run_help_lists_the_exit_codes(capsys):
    with pytest.raises(SystemExit):
        cli.main(["run", "--help"])
    out = capsys.readouterr().out
    for code in (cli.EXIT_OK, cli.EXIT_ERROR, cli.EXIT_INVALID, cli.EXIT_LIMIT):
        assert f"  {code}  " in out
    assert "connected input is refused" in out


@pytest.mark.parametrize(
    "override,message",
    [
        ("run.stpo=5", "override 'run.stpo': unknown run key 'stpo'; allowed ['algorithm', "),
        (
            "bearing_1.T_oil=1000",
            "override 'bearing_1.T_oil': bearing_1.T_oil is a connected input (from spindle.T_oil_1)",
        ),
    ],
)
def test_set_refuses_an_unknown_run_key_and_a_connected_input(override, message, tmp_path, capsys):
    """Refused before any FMU is loaded, with exit code 1 and the reason on stderr (an unknown key used
    to be ignored, a connected input silently overwritten by its connection)."""
    args = ["run", str(DEMO), "--set", override, "--no-plot", "--out", str(tmp_path)]
    assert cli.main(args) == cli.EXIT_ERROR
    assert message in capsys.readouterr().err
    assert not any(tmp_path.iterdir())  # nothing run, nothing written


def test_set_on_an_unknown_variable_lists_every_variable(closed_loop_fmus, tmp_path, capsys):
    from fmpy import read_model_description

    folder = closed_loop_fmus["Bearing"].parent
    args = ["run", str(DEMO), "--fmus", str(folder), "--set", "bearing_1.stpo=5", "--no-plot", "--out", str(tmp_path)]
    assert cli.main(args) == cli.EXIT_ERROR
    err = capsys.readouterr().err
    assert "bearing_1: no variable 'stpo'; the FMU's variables: " in err
    names = [v.name for v in read_model_description(str(closed_loop_fmus["Bearing"])).modelVariables]
    assert len(names) > 40 and all(name in err for name in names)


def test_info_prints_every_variable_and_the_ranges(closed_loop_fmus, capsys):
    from fmpy import read_model_description

    path = closed_loop_fmus["Bearing"]
    md = read_model_description(str(path))
    assert cli.main(["info"]) == cli.EXIT_OK
    summary = capsys.readouterr().out
    outputs = [v.name for v in md.modelVariables if v.causality == "output"]
    assert f"outputs ({len(outputs)}): {', '.join(outputs)}\n" in summary
    assert cli.main(["info", str(path)]) == cli.EXIT_OK
    detail = capsys.readouterr().out
    assert "input     omega                [rad/s] range [-100000, 100000]" in detail


def _fmu_folder(closed_loop_fmus, tmp_path):
    folder = tmp_path / "elsewhere"
    folder.mkdir()
    for name in ("Bearing", "SpindleThermal"):
        shutil.copy2(closed_loop_fmus[name], folder)
    return folder


def test_sweep_without_dask_runs_the_points_here_with_an_fmu_folder(closed_loop_fmus, tmp_path, monkeypatch, capsys):
    """dask is the optional extra `sweep`: without it `spindle sweep` says so and runs the points one after the
    other in this process (the same table, spindle.cosim.sweep.sequential), with `--fmus` as `spindle run`."""
    monkeypatch.setitem(sys.modules, "dask", None)  # import dask / dask.distributed raise ImportError
    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    out = tmp_path / "results"
    folder = _fmu_folder(closed_loop_fmus, tmp_path)
    args = ["sweep", str(DEMO), "--param", "spindle.T_coolant", "--values", "283.15,303.15", "--set", "run.stop=3"]
    assert cli.main([*args, "--fmus", str(folder), "--out", str(out)]) == cli.EXIT_OK
    captured = capsys.readouterr()
    assert "dask[distributed]" in captured.err and "one after the other" in captured.err
    assert "Traceback" not in captured.err
    with open(out / "closed_loop_spring_sweep_spindle_T_coolant.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [float(r["spindle.T_coolant"]) for r in rows] == [283.15, 303.15]
    assert [r["status"] for r in rows] == ["ok", "ok"] and [float(r["t_end"]) for r in rows] == [3.0, 3.0]
    assert float(rows[0]["spindle.T_housing"]) < float(rows[1]["spindle.T_housing"])  # the value reached the run
    # a cluster asked for without dask: an error naming the missing package, nothing run here
    assert cli.main([*args, "--fmus", str(folder), "--scheduler", "tcp://127.0.0.1:1"]) == cli.EXIT_ERROR
    assert "pip install 'bearing-fmu[sweep]'" in capsys.readouterr().err


def test_a_closed_output_ends_the_command_quietly(closed_loop_fmus):
    """`spindle info | head`: the reader closes the pipe while the command still writes. The command stops as
    a Unix tool does, without a traceback, with exit status 128 + SIGPIPE. The child waits for a byte on
    stdin, sent once its output is closed, so it always writes into a closed pipe."""
    child = "import os, sys; from spindle import cli; os.read(0, 1); sys.argv = ['spindle', 'info']; cli.run()"
    proc = subprocess.Popen(
        [sys.executable, "-c", child], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE
    )
    proc.stdout.close()
    proc.stdin.write(b"x")
    proc.stdin.close()
    status = proc.wait(timeout=120)
    assert proc.stderr.read().decode() == ""
    assert status == 141 == getattr(cli, "EXIT_PIPE", None)


def test_a_runs_overrides_are_recorded_beside_its_csv_and_in_its_plot_title(closed_loop_fmus, tmp_path, monkeypatch):
    """A run with --set is another case than its run file's description says (a 6000 rpm run of the 10 000 rpm
    file): the overrides go into <stem>.run.json beside the CSV and into the plot's title."""
    from spindle.cosim import plots

    titles = []
    monkeypatch.setattr(plots, "plot_run", lambda result, path, title="": titles.append(title) or path)
    out = tmp_path / "results"
    sets = ["--set", "run.stop=3", "--set", "spindle.T_coolant=300.0"]
    folder = _fmu_folder(closed_loop_fmus, tmp_path)
    assert cli.main(["run", str(DEMO), *sets, "--fmus", str(folder), "--out", str(out)]) == cli.EXIT_OK
    record = json.loads((out / "closed_loop_spring.run.json").read_text())
    assert record["overrides"] == {"run.stop": 3, "spindle.T_coolant": 300.0}
    assert record["run_file"] == str(DEMO) and record["stop"] == 3.0 and record["status"] == "ok"
    assert len(titles) == 1
    assert "10 000 rpm" in titles[0]  # the run file's description, then what this run changed
    assert "run.stop = 3" in titles[0] and "spindle.T_coolant = 300.0" in titles[0]


def test_build_config_with_bearing_and_lubricant_files(tmp_path, capsys):
    """`spindle build --config` with the bearing given as a TOML file relative to the configuration file and the
    lubricant as an absolute path (docs/parameters.md, configured FMUs): exit 0, the FMU carries both files in its
    catalogue under their names, and run without any parameter set it computes the bearing of the file with the
    oil of the file (one step of 8.9 kN at 8 000 rpm: the Python model on the same files, to rounding)."""
    import math

    from fmpy import read_model_description

    from bearing_fmu.build import SCENES_DIR
    from bearing_fmu.models.quasi_static import QuasiStaticModel
    from bearing_fmu.params import CATALOGUE
    from bearing_fmu.scene import Scene

    folder = tmp_path / "config"
    folder.mkdir()
    shutil.copy(cli.ROOT / "tests/validation/data/angular_218_textbook.toml", folder / "my_218.toml")
    oil = tmp_path / "my_oil.toml"
    shutil.copy(CATALOGUE / "lubricants" / "guessasma_oil.toml", oil)
    config = folder / "rig.toml"
    config.write_text(
        f'[configuration]\nname = "mine"\nbearing = "my_218.toml"\nlubricant = "{oil}"\nfmus = ["Bearing"]\n'
    )
    assert cli.main(["build", "--config", str(config), "--out", str(tmp_path / "out")]) == cli.EXIT_OK
    fmu = tmp_path / "out" / "Bearing_mine.fmu"
    starts = {v.name: v.start for v in read_model_description(str(fmu)).modelVariables}
    assert (starts["bearing"], starts["lubricant"]) == ("my_218", "my_oil")
    omega = 8000.0 * math.pi / 30.0
    # in a fresh process, as a master runs it: this one has imported the package, whose catalogue the FMU would use
    script = (
        "import sys, numpy as np; from fmpy import simulate_fmu\n"
        "inputs = np.array([(0.0, float(sys.argv[2]), 8900.0)], dtype=[('time', float), ('omega', float), "
        "('F_z', float)])\n"
        "r = simulate_fmu(sys.argv[1], stop_time=1.0, output_interval=1.0, input=inputs, output=['omega_cage', 'z'])\n"
        "print(repr(float(r['omega_cage'][-1])), repr(float(r['z'][-1])))\n"
    )
    run = subprocess.run(
        [sys.executable, "-c", script, str(fmu), repr(omega)], capture_output=True, text=True, cwd=tmp_path, timeout=600
    )
    assert run.returncode == 0, run.stderr[-2000:]
    omega_cage, z = map(float, run.stdout.split()[-2:])
    scene = Scene.from_toml(SCENES_DIR / "quasi_static.toml")
    model = QuasiStaticModel(str(folder / "my_218.toml"), str(oil), scene=scene)
    expected = model.evaluate(omega=omega, F_z=8900.0)
    assert omega_cage == pytest.approx(expected["omega_cage"], rel=1e-8)
    assert z == pytest.approx(expected["z"], rel=1e-6, abs=1e-12)
