"""Input schedules in run files (spindle/cosim/runfile.py, `schedules`): a piecewise-linear table
[[t, u], ...] for an unconnected input, read and checked with messages naming the key, and applied by the
master through FMI as u(t) before every communication step [t, t + h] (halves of a rejected step included).

The expected values are written from the definition (linear interpolation between the points, held
outside them) by hand, not with the code under test."""

import math

import numpy as np
import pytest

from spindle import cli
from spindle.cosim.master import Master, run
from spindle.cosim.runfile import RunFileError, Schedule, load_run, parse_run

RAMP = [[0.0, 0.0], [1.0, 10.0]]  # u = 10 t up to 1 s, then 10


def clock_doc(clock, schedules, **run_keys):
    return {
        "run": {"start": 0.0, "stop": 2.0, "step": 0.25, "record": ["c.u", "c.x", "c.t_start"], **run_keys},
        "fmus": {"clock": str(clock)},
        "instances": {"c": {"fmu": "clock", "schedules": schedules}},
    }


def test_schedule_interpolates_and_holds_outside_the_table():
    u = Schedule.from_table([[1.0, 2.0], [3.0, 6.0], [4.0, 0.0]], "k")
    assert [u(t) for t in (0.0, 1.0, 2.0, 2.5, 3.0, 3.5, 4.0, 9.0)] == [2.0, 2.0, 4.0, 5.0, 6.0, 3.0, 0.0, 0.0]
    assert Schedule.from_table([[0, 5]], "k")(123.0) == 5.0  # one point: a constant


def test_schedule_equals_numpy_interp_bit_for_bit():
    """The schedule evaluates numpy.interp's formula itself (no array conversion per call): the same doubles,
    before, on, between and after the points, and NaN for a NaN time."""
    rng = np.random.default_rng(7)
    for n in (1, 2, 5, 40):
        times = np.cumsum(rng.uniform(0.01, 2.0, n)) - 1.0
        table = [[float(t), float(v)] for t, v in zip(times, rng.normal(0.0, 1e3, n))]
        u = Schedule.from_table(table, "k")
        ts = np.concatenate([times, rng.uniform(times[0] - 1.0, times[-1] + 1.0, 500)])
        expected = np.interp(ts, u.times, u.values)
        assert [u(float(t)) for t in ts] == expected.tolist()
    assert math.isnan(Schedule.from_table([[0.0, 1.0], [1.0, 2.0]], "k")(math.nan))


@pytest.mark.parametrize(
    "table, message",
    [
        ([], "write a table [[t, value], ...]"),
        (5.0, "got 5.0"),
        ([[0.0, 1.0], [1.0]], "point 1 is [1.0]"),
        ([[0.0, "fast"]], "point 0 is [0.0, 'fast']"),
        ([[0.0, float("nan")]], "point 0 is [0.0, nan]"),
        ([[0.0, True]], "point 0 is [0.0, True]"),
        ([[0.0, 1.0], [2.0, 2.0], [2.0, 3.0]], "t = 2.0 s at point 2 does not follow t = 2.0 s"),
        ([[1.0, 1.0], [0.5, 2.0]], "t = 0.5 s at point 1 does not follow t = 1.0 s"),
    ],
)
def test_bad_table_is_refused_naming_the_key(table, message, tmp_path):
    doc = clock_doc("clock.fmu", {"u": table})
    with pytest.raises(RunFileError) as err:
        parse_run(doc, tmp_path / "r.toml")
    assert "instances.c.schedules.u" in str(err.value) and message in str(err.value)


def test_schedule_at_the_end_of_the_step_and_its_bad_values(tmp_path):
    u = Schedule.from_entry({"table": RAMP, "at": "end"}, "k")
    assert u.for_step(0.25, 0.25) == 5.0 and Schedule.from_entry(RAMP, "k").for_step(0.25, 0.25) == 2.5
    for entry, message in (
        ({"table": RAMP, "at": "middle"}, "instances.c.schedules.u.at = 'middle': allowed ['start', 'end']"),
        ({"table": [[1, 0], [0, 1]], "at": "end"}, "instances.c.schedules.u.table: write a table"),
        ({"points": RAMP}, "instances.c.schedules.u: unknown key(s) ['points']"),
    ):
        with pytest.raises(RunFileError) as err:
            parse_run(clock_doc("clock.fmu", {"u": entry}), tmp_path / "r.toml")
        assert message in str(err.value)


def test_scheduled_input_that_is_also_constant_or_connected_is_refused(tmp_path):
    doc = clock_doc("clock.fmu", {"u": RAMP})
    doc["instances"]["c"]["inputs"] = {"u": 1.0}
    with pytest.raises(RunFileError, match="u is both scheduled and in inputs/parameters"):
        parse_run(doc, tmp_path / "r.toml")
    doc = clock_doc("clock.fmu", {"u": RAMP})
    doc["connections"] = [{"from": "c.x", "to": "c.u"}]
    with pytest.raises(RunFileError, match=r"instances.c.schedules.u: the input is connected"):
        parse_run(doc, tmp_path / "r.toml")
    doc = clock_doc("clock.fmu", {"u": [[0, 1]]})
    doc["instances"]["c"]["schedules"] = [[0, 1]]
    with pytest.raises(RunFileError, match=r"instances.c.schedules: write schedules = \{ input"):
        parse_run(doc, tmp_path / "r.toml")


def test_overrides_switch_between_constant_and_scheduled(tmp_path):
    spec = parse_run(clock_doc("clock.fmu", {"u": RAMP}), tmp_path / "r.toml", {"c.u": 3.0})
    assert spec.instances["c"].inputs == {"u": 3.0} and spec.instances["c"].schedules == {}
    spec = parse_run(clock_doc("clock.fmu", {}), tmp_path / "r.toml", {"c.u": [[0, 1], [2, 3]]})
    assert spec.instances["c"].inputs == {} and spec.instances["c"].schedules["u"](1.0) == 2.0
    with pytest.raises(RunFileError, match="override 'c.u'"):
        parse_run(clock_doc("clock.fmu", {}), tmp_path / "r.toml", {"c.u": [[1, 1], [0, 3]]})


def test_spindle_validate_checks_run_files(tmp_path, capsys):
    good = cli.RUNS / "startup_dem.toml"
    assert cli.main(["validate", str(good)]) == cli.EXIT_OK
    bad = tmp_path / "bad.toml"
    bad.write_text(good.read_text().replace("[[0.0, 0.0], [2.0, 1047.1975511965977]]", "[[0.0, 0.0], [0.0, 1.0]]", 1))
    assert cli.main(["validate", str(bad)]) == cli.EXIT_INVALID
    out = capsys.readouterr().out
    assert "instances.bearing_1.schedules.omega" in out and "does not follow t = 0.0 s" in out


def test_master_sets_the_scheduled_value_at_the_start_of_each_step(clock_fmu, tmp_path):
    """The clock FMU integrates x += u h: with u(t) = 10 t up to 1 s (then 10) sampled at the start of
    each 0.25 s step, x(2 s) = 0.25 (0 + 2.5 + 5 + 7.5 + 10 + 10 + 10 + 10) = 13.75; the input read back
    at t_n is u(t_{n-1}) (the value the FMU held over the step just done), u(0) = 0 after initialisation."""
    result = run(parse_run(clock_doc(clock_fmu, {"u": RAMP}), tmp_path / "r.toml"))
    assert list(result.columns["c.u"]) == [0.0, 0.0, 2.5, 5.0, 7.5, 10.0, 10.0, 10.0, 10.0]
    assert result.columns["c.x"][-1] == 13.75


def test_master_sets_the_value_at_the_end_of_each_step_when_asked(clock_fmu, tmp_path):
    """at = "end": the FMU gets u(t + h) for the step [t, t + h]: x(2 s) = 0.25 (2.5 + 5 + 7.5 + 5 x 10) = 16.25;
    initialisation still sets u(start) = 0."""
    result = run(parse_run(clock_doc(clock_fmu, {"u": {"table": RAMP, "at": "end"}}), tmp_path / "r.toml"))
    assert list(result.columns["c.u"]) == [0.0, 2.5, 5.0, 7.5, 10.0, 10.0, 10.0, 10.0, 10.0]
    assert result.columns["c.x"][-1] == 16.25


def test_halves_of_a_rejected_step_get_their_own_scheduled_values(clock_fmu, tmp_path):
    """h_max = 0.125 s refuses every 0.25 s step, so each is redone as two halves, each starting with
    u at its own start: x(2 s) = 0.125 (0 + 1.25 + ... + 8.75 + 8 x 10) = 0.125 (35 + 80) = 14.375."""
    doc = clock_doc(clock_fmu, {"u": RAMP}, rollback=True, max_halvings=1)
    doc["instances"]["c"]["parameters"] = {"h_max": 0.125}
    with Master(parse_run(doc, tmp_path / "r.toml")) as master:
        result = master.run()
    assert result.rejected_steps == 8
    assert result.columns["c.x"][-1] == 14.375


def test_startup_run_files_ramp_every_speed_input():
    """Both start-up runs and the demo give the same ramp 0 -> 10 000 rpm (1047.2 rad/s) over 2 s to the
    bearings and to the spindle (its convection and centrifugal growth follow the speed). In the start-up
    runs the bearings get the value at the end of each step (BearingDEM.fmu moves its speed linearly over
    the step to it; the quasi-static run does the same for a like-for-like comparison)."""
    for name in ("startup_dem.toml", "startup_qs.toml", "closed_loop_spring.toml"):
        spec = load_run(cli.RUNS / name)
        for inst_name, inst in spec.instances.items():
            omega = inst.schedules["omega"]
            assert omega(0.0) == 0.0 and omega(1.0) == pytest.approx(523.5987755982989, rel=1e-15)
            assert omega(2.0) == omega(10.0) == 1047.1975511965977
            expected = "end" if name.startswith("startup") and inst_name.startswith("bearing") else "start"
            assert omega.at == expected, (name, inst_name)
