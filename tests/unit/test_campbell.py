"""`spindle campbell` (spindle/campbell_cli.py) and the Campbell diagram (spindle/shaft/campbell.py): the diagram
against ShaftModel at each speed, its critical speeds against the synchronous eigen-solution, the gyroscopic splitting
of the default shaft, the refused options and the files written.

Default shaft on two B7214C under 800 N axial, K of the quasi-static bearing at 10 000 rpm unless said. The diagram
calls ShaftModel.evaluate with the same inputs, so its frequencies are equal bit for bit; through the command the seat
K comes from another instance of the quasi-static model, warm-started from another solution, whose equilibrium
tolerance (1e-10) leaves differences of about 1e-11 in K: there they agree within 1e-8. The critical speeds are
bisected to SPEED_TOLERANCE (1e-3 rad/s) and printed to 1e-4 rad/s, so they agree with the synchronous eigen-solution
within 1e-3 rad/s when the seats are undamped (with damping the two definitions differ, section "Campbell diagram"
of docs/shaft.md).
"""

import csv
import math
import re

import numpy as np
import pytest

from spindle.campbell_cli import RPM, bearing_stiffness, quasi_static_bearing
from spindle.cli import EXIT_INVALID, EXIT_OK, main
from spindle.shaft import ShaftModel
from spindle.shaft.campbell import SPEED_TOLERANCE, campbell, forward_below
from spindle.shaft.declarations import K_START
from spindle.shaft.model import WHIRL_AXIAL, WHIRL_BACKWARD, WHIRL_FORWARD

MODES = 6


@pytest.fixture(scope="module")
def qs():
    return quasi_static_bearing("B7214C", "iso_vg68_mineral")


@pytest.fixture(scope="module")
def model():
    return ShaftModel()


@pytest.fixture(scope="module")
def seats(qs):
    """Both seats' K: the B7214C under 800 N axial at 10 000 rpm."""
    return np.array([bearing_stiffness(qs, 10000.0 * RPM, 800.0, 0.0)] * 2)


def run(args, tmp_path, capsys):
    """main() with the options, into tmp_path: (exit code, printed text, CSV rows as dicts)."""
    code = main(["campbell", *args, "--out", str(tmp_path)])
    text = capsys.readouterr()
    paths = list(tmp_path.glob("campbell_*.csv"))
    rows = list(csv.DictReader(paths[0].open())) if paths else []
    return code, text.out + text.err, rows


def printed_critical_speeds(text):
    return [float(x) for x in re.findall(r"critical speed \d+: [\d.]+ rpm = ([\d.]+) rad/s", text)]


def test_the_seat_stiffness_is_bearing_fmu_reference_k(qs):
    """At Bearing.fmu's reference point (10 000 rpm, F_x 500 N, F_z 800 N) the seat K is that FMU's K, which the shaft
    FMU starts from (declarations.K_START, 4 digits): the command's bearing is the product's quasi-static bearing."""
    K = bearing_stiffness(qs, 10000.0 * RPM, 800.0, 500.0)
    for i in range(5):
        for j in range(5):
            assert K[i, j] == pytest.approx(K_START[i][j], rel=6e-4), (i, j)


def test_the_diagram_is_the_model_at_each_speed(model, seats):
    """campbell() at each speed is ShaftModel.evaluate at that speed with the same K and damping, bit for bit."""
    C = np.zeros((2, 5, 5))
    C[:, 0, 0] = C[:, 1, 1] = 2000.0
    speeds = np.linspace(0.0, 4000.0, 9)
    diagram = campbell(model, speeds, lambda omega: seats, C)
    for i, omega in enumerate(speeds):
        out = model.evaluate(omega, seats, C, critical_speeds=False)
        assert np.array_equal(diagram.frequencies[i], out["frequencies"])
        assert np.array_equal(diagram.whirl[i], out["whirl"])
        assert np.array_equal(diagram.damping_ratios[i], out["damping_ratios"])


def test_the_command_csv_is_the_model_at_each_speed(model, seats, tmp_path, capsys):
    """Every CSV row (0 to 30 000 rpm, 7 speeds) is ShaftModel.evaluate at that row's speed with the bearing's K at
    10 000 rpm and the default damping: frequencies and damping ratios within 1e-8, whirl equal."""
    code, text, rows = run(["--points", "7"], tmp_path, capsys)
    assert code == EXIT_OK, text
    assert [float(r["speed_rpm"]) for r in rows] == [0.0, 5000.0, 10000.0, 15000.0, 20000.0, 25000.0, 30000.0]
    C = np.zeros((2, 5, 5))
    C[:, 0, 0] = C[:, 1, 1] = 2000.0
    words = {1: "forward", -1: "backward", 0: "none", 2: "axial"}
    for r in rows:
        out = model.evaluate(float(r["omega_rad_s"]), seats, C, critical_speeds=False)
        assert [float(r[f"f_{k}_Hz"]) for k in range(1, MODES + 1)] == pytest.approx(out["frequencies"], rel=1e-8)
        assert [r[f"whirl_{k}"] for k in range(1, MODES + 1)] == [words[int(w)] for w in out["whirl"]]
        zeta = [float(r[f"zeta_{k}"]) for k in range(1, MODES + 1)]
        # abs: the axial mode, which the seats' radial damping does not reach, has a ratio of round-off (1e-14)
        assert zeta == pytest.approx(out["damping_ratios"], rel=1e-8, abs=1e-12)


def test_speed_mode_recomputes_k_at_each_speed(model, qs, tmp_path, capsys):
    """--stiffness speed: each row is the model with the bearing's K at that row's speed."""
    code, text, rows = run(["--stiffness", "speed", "--points", "4"], tmp_path, capsys)
    assert code == EXIT_OK, text
    C = np.zeros((2, 5, 5))
    C[:, 0, 0] = C[:, 1, 1] = 2000.0
    for r in rows:
        omega = float(r["omega_rad_s"])
        K = np.array([bearing_stiffness(qs, omega, 800.0, 0.0)] * 2)
        out = model.evaluate(omega, K, C, critical_speeds=False)
        assert [float(r[f"f_{k}_Hz"]) for k in range(1, MODES + 1)] == pytest.approx(out["frequencies"], rel=1e-8)
    assert float(rows[0]["f_2_Hz"]) > 1.5 * float(rows[1]["f_2_Hz"])  # 0 -> 10 000 rpm: the bearings soften


def test_printed_critical_speeds_are_the_synchronous_solution(model, seats, tmp_path, capsys):
    """Undamped seats, 0 to 40 000 rpm: the two forward crossings of the 1x line the command prints are
    ShaftModel.critical_speeds at the same K (1856 and 3880 rad/s) within the bisection's bracket."""
    code, text, _ = run(["--damping", "0", "--max-speed", "40000"], tmp_path, capsys)
    assert code == EXIT_OK, text
    printed = printed_critical_speeds(text)
    expected = model.critical_speeds(seats, count=2)
    assert len(printed) == 2
    assert printed == pytest.approx(expected.tolist(), abs=SPEED_TOLERANCE)


def test_damped_critical_speeds_are_crossings_of_the_forward_frequency(model, seats):
    """With damping a critical speed is where a forward damped frequency equals the speed: at each one found, a forward
    mode of ShaftModel.evaluate lies on the 1x line within the bracket's width (its slope is below 1x's)."""
    C = np.zeros((2, 5, 5))
    C[:, 0, 0] = C[:, 1, 1] = 2000.0
    diagram = campbell(model, np.linspace(0.0, 4200.0, 43), lambda omega: seats, C)
    assert diagram.critical_speeds.size == 2
    for omega in diagram.critical_speeds:
        out = model.evaluate(omega, seats, C, critical_speeds=False)
        forward = out["frequencies"][out["whirl"] == WHIRL_FORWARD] * 2.0 * math.pi
        assert np.min(np.abs(forward - omega)) <= SPEED_TOLERANCE


def test_two_crossings_in_one_step_of_the_grid_are_both_found(model, seats):
    """A grid of two speeds, 0 and 4200 rad/s, holds both crossings: the bisection splits the step until each is
    alone, and finds what the fine grid finds."""
    fine = campbell(model, np.linspace(0.0, 4200.0, 43), lambda omega: seats).critical_speeds
    coarse = campbell(model, [0.0, 4200.0], lambda omega: seats).critical_speeds
    assert coarse.size == 2 and coarse == pytest.approx(fine, abs=SPEED_TOLERANCE)
    out = model.evaluate(4200.0, seats, critical_speeds=False)
    assert forward_below(out, 4200.0) == 2


def test_forward_modes_rise_and_backward_modes_fall_with_speed(model, seats):
    """Gyroscopic splitting (Friswell et al. 2010, ch. 5): the spin couples the two bending planes through the disks'
    and the shaft's polar inertia, stiffening forward whirl and softening backward whirl, so with K held each forward
    frequency rises and each backward one falls with speed. On the default shaft at 1 000 to 30 000 rpm: the k-th
    forward (backward) mode at each speed against the k-th at the next."""
    diagram = campbell(model, np.linspace(1000.0, 30000.0, 30) * RPM, lambda omega: seats)
    for whirl, sign in ((WHIRL_FORWARD, 1.0), (WHIRL_BACKWARD, -1.0)):
        branches = [diagram.frequencies[i][diagram.whirl[i] == whirl] for i in range(diagram.speeds.size)]
        count = min(b.size for b in branches)
        assert count >= 2  # the first two bending pairs
        steps = np.diff(np.array([b[:count] for b in branches]), axis=0)
        assert np.all(sign * steps > 0.0), whirl


@pytest.mark.parametrize(
    "options, words",
    [
        (["--points", "1"], ("--points = 1", "[2, 1000]")),
        (["--max-speed", "0"], ("--max-speed = 0 rpm", "(0, 41025.6] rpm")),
        (["--max-speed", "50000"], ("--max-speed = 50000 rpm", "(0, 41025.6] rpm")),
        (["--speed", "-1"], ("--speed = -1 rpm", "[0, 41025.6] rpm")),
        (["--preload", "0"], ("--preload = 0 N", "(0, ")),
        (["--radial", "-5"], ("--radial = -5 N", "[0, ")),
        (["--damping", "-1"], ("--damping = -1 N.s/m", "[0, 1e+08] N.s/m")),
    ],
)
def test_bad_options_are_refused_naming_option_value_and_range(options, words, tmp_path, capsys):
    code, text, rows = run(options, tmp_path, capsys)
    assert code == EXIT_INVALID and all(w in text for w in words), text
    assert "Traceback" not in text and not rows and not list(tmp_path.iterdir())


def test_a_stiffness_mode_outside_the_choices_is_refused(tmp_path, capsys):
    with pytest.raises(SystemExit) as stop:
        main(["campbell", "--stiffness", "rigid", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert stop.value.code == 2 and "--stiffness" in err and "'rigid'" in err and "'operating', 'speed'" in err


def test_the_command_writes_the_csv_and_the_png(tmp_path, capsys):
    code, text, rows = run(["--points", "11"], tmp_path, capsys)
    assert code == EXIT_OK, text
    csv_path = tmp_path / "campbell_rabreau_b7214c_operating.csv"
    png = tmp_path / "campbell_rabreau_b7214c_operating.png"
    assert len(rows) == 11 and png.stat().st_size > 10000
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert f"wrote {csv_path}, {png}" in text
    assert len(printed_critical_speeds(text)) == 1  # 1593 rad/s (15 209 rpm) below 30 000 rpm, the second above


def test_a_first_run_says_it_compiles(tmp_path, capsys, monkeypatch):
    """Without the quasi-static kernels in the compiled-code cache the command says that it compiles them first."""
    from spindle import cli

    monkeypatch.setattr(cli, "_kernels_not_compiled", lambda module: module == "jones_harris")
    code, text, _ = run(["--points", "1"], tmp_path, capsys)
    assert code == EXIT_INVALID and "first run compiles the quasi-static bearing's kernels" in text


def test_a_floating_seat_is_the_model_with_that_seat_floating(seats, tmp_path, capsys):
    """--floating rear_bearing (and its number, 2): every CSV row is ShaftModel.evaluate with the rear seat floating
    (its axial stiffness condensed out), whose axial mode lies below the fixed seats' (the front bearing alone holds
    the shaft axially)."""
    floating = ShaftModel(floating=(False, True))
    fixed = ShaftModel()
    C = np.zeros((2, 5, 5))
    C[:, 0, 0] = C[:, 1, 1] = 2000.0
    for given in ("rear_bearing", "2"):
        code, text, rows = run(["--points", "3", "--floating", given], tmp_path, capsys)
        assert code == EXIT_OK, text
        assert "floating: " + given in text
        for r in rows:
            out = floating.evaluate(float(r["omega_rad_s"]), seats, C, critical_speeds=False)
            assert [float(r[f"f_{k}_Hz"]) for k in range(1, MODES + 1)] == pytest.approx(out["frequencies"], rel=1e-8)
    axial = [m.evaluate(0.0, seats, critical_speeds=False) for m in (floating, fixed)]
    f_axial = [out["frequencies"][out["whirl"] == WHIRL_AXIAL] for out in axial]
    assert f_axial[0].size and f_axial[1].size and f_axial[0][0] < f_axial[1][0]


def test_a_floating_seat_the_shaft_lacks_is_refused(tmp_path, capsys):
    code, text, _ = run(["--floating", "middle"], tmp_path, capsys)
    assert code == EXIT_INVALID
    assert "--floating = middle is not a seat of the shaft (its seats: 1 = front_bearing, 2 = rear_bearing)" in text
