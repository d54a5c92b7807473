"""`spindle campbell`: the Campbell diagram of a shaft on quasi-static bearings (docs/shaft.md, "Campbell diagram").

The seats' stiffness is each bearing's own 5x5 K (dF/dd of the inner ring, bearing_fmu's K[i,j] outputs) from the
quasi-static model under the axial preload and the radial load, passed to ShaftModel as the bearing gives it.
`operating`: K at the operating speed, held over the range (the classical diagram); `speed`: K recomputed at each
speed (the bearings' stiffness changes with the balls' centrifugal force and gyroscopic moment). The diagram itself
is spindle.shaft.campbell; this module checks the options, builds the seats' K and writes the CSV and the figure.
`--floating SEAT` frees a seat's outer ring axially (a spring- or actuator-preloaded ring: ShaftModel's floating).
"""

import csv
import math
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

RPM = math.pi / 30.0  # rad/s per rpm
POINTS_RANGE = (2, 1000)
STIFFNESS_MODES = ("operating", "speed")


class OptionError(ValueError):
    """An option of the command is outside its allowed range (the message names it, its value and the range)."""


def quasi_static_bearing(bearing, lubricant):
    """The quasi-static model that gives a seat's K: the physics of Bearing.fmu's scene (load-controlled, the balls'
    centrifugal force and gyroscopic moment, its tolerance) without the outputs the diagram does not use (they cost
    time and change no K)."""
    import bearing_fmu
    from bearing_fmu import QuasiStaticModel, Scene

    scene = Scene.from_toml(Path(bearing_fmu.__file__).parent / "scenes" / "quasi_static.toml")
    scene = replace(scene, name="campbell", torque=False, capacitance=False, life=False, thermal_inputs=False)
    return QuasiStaticModel(bearing, lubricant, scene=scene)


def bearing_stiffness(qs, omega, preload, radial):
    """The bearing's 5x5 K (row dF_i, column d_j) at speed omega (rad/s) under F_z = preload and F_x = radial (N)."""
    out = qs.evaluate(omega=omega, F_x=radial, F_z=preload)
    return np.array([[out[f"K[{i + 1},{j + 1}]"] for j in range(5)] for i in range(5)])


def check_options(args, qs, shaft_omega_max):
    """OptionError naming the first option outside its allowed range (its value, the range, why)."""
    speed_max = min(qs.omega_max, shaft_omega_max) / RPM
    limit = f"the {qs.bearing.name}'s d_m n limit or the shaft model's"
    checks = (
        ("--speed", args.speed, "rpm", 0.0, speed_max, False, limit),
        ("--max-speed", args.max_speed, "rpm", 0.0, speed_max, True, limit),
        ("--preload", args.preload, "N", 0.0, qs.load_limit, True, "an angular-contact bearing needs thrust"),
        ("--radial", args.radial, "N", 0.0, qs.load_limit, False, "the bearing's material limit"),
        ("--damping", args.damping, "N.s/m", 0.0, 1e8, False, "1e8 N.s/m is far above a bearing's"),
    )
    for option, value, unit, low, high, open_low, why in checks:
        if not (low < value if open_low else low <= value) or not value <= high:
            bracket = "(" if open_low else "["
            raise OptionError(
                f"{option} = {value:g} {unit} is outside the allowed range {bracket}{low:g}, {high:.6g}] {unit} ({why})"
            )
    low, high = POINTS_RANGE
    if not low <= args.points <= high:
        raise OptionError(f"--points = {args.points} is outside the allowed range [{low}, {high}] (a whole number)")


def seat_damping(n_seats, damping):
    """Each seat's damping matrix: `damping` (N.s/m) on x and y, as SpindleShaft.fmu's c_s."""
    C = np.zeros((n_seats, 5, 5))
    C[:, 0, 0] = C[:, 1, 1] = damping
    return C


def stiffness_function(args, qs, n_seats):
    """omega -> the seats' K (n_seats, 5, 5): held at --speed (operating) or recomputed at each speed."""
    if args.stiffness == "operating":
        K = np.array([bearing_stiffness(qs, args.speed * RPM, args.preload, args.radial)] * n_seats)
        return lambda omega: K
    return lambda omega: np.array([bearing_stiffness(qs, omega, args.preload, args.radial)] * n_seats)


def floating_seats(args, model):
    """Per seat whether --floating names it (by name or number from 1); OptionError for a seat the shaft lacks."""
    names = model.shaft.seat_names
    flags = [False] * len(names)
    for given in args.floating or ():
        k = int(given) - 1 if given.isdigit() else (names.index(given) if given in names else -1)
        if not 0 <= k < len(names):
            seats = ", ".join(f"{i + 1} = {name}" for i, name in enumerate(names))
            raise OptionError(f"--floating = {given} is not a seat of the shaft (its seats: {seats})")
        flags[k] = True
    return flags


def compute(args):
    """(ShaftModel, CampbellDiagram, seconds) of the command's options; OptionError naming a bad option."""
    from .shaft import ShaftModel
    from .shaft.campbell import campbell
    from .shaft.model import OMEGA_MAX
    from .shaft.params import DEFAULT_SHAFT

    start = time.perf_counter()
    args.shaft = args.shaft or DEFAULT_SHAFT
    model = ShaftModel(args.shaft)
    model.set_floating(floating_seats(args, model))
    qs = quasi_static_bearing(args.bearing, args.lubricant)
    check_options(args, qs, OMEGA_MAX)
    n_seats = len(model.shaft.seat_nodes)
    speeds = np.linspace(0.0, args.max_speed * RPM, args.points)
    C = seat_damping(n_seats, args.damping) if args.damping else None
    diagram = campbell(model, speeds, stiffness_function(args, qs, n_seats), C)
    return model, diagram, time.perf_counter() - start


def write_csv(diagram, path):
    from .shaft.campbell import rows

    with open(path, "w", newline="") as fh:
        csv.writer(fh).writerows(rows(diagram))
    return path


def title(args):
    held = f"K at {args.speed:g} rpm" if args.stiffness == "operating" else "K at each speed"
    floating = f", floating: {', '.join(args.floating)}" if args.floating else ""
    return (
        f"{Path(args.shaft).stem}: {args.bearing} seats, {args.preload:g} N axial, {args.radial:g} N radial, "
        f"{args.damping:g} N.s/m{floating}; {held}"
    )


def plot(diagram, path, text, operating_rpm=None):
    """Frequencies against speed: forward modes red, backward blue, others grey; the 1x line; each critical speed
    marked on it; the speed K was computed at (operating mode)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .shaft.model import WHIRL_BACKWARD, WHIRL_FORWARD

    rpm = diagram.speeds / RPM
    fig, ax = plt.subplots(figsize=(8, 5.5))
    ax.plot(rpm, diagram.frequencies, "-", color="0.8", lw=0.8, zorder=1)
    styles = ((WHIRL_FORWARD, "^", "C3", "forward"), (WHIRL_BACKWARD, "v", "C0", "backward"))
    for whirl, marker, colour, label in styles:
        pick = diagram.whirl == whirl
        x = np.broadcast_to(rpm[:, None], pick.shape)[pick]
        ax.plot(x, diagram.frequencies[pick], marker, color=colour, ms=3.5, ls="none", label=label, zorder=2)
    other = (diagram.whirl != WHIRL_FORWARD) & (diagram.whirl != WHIRL_BACKWARD)
    x = np.broadcast_to(rpm[:, None], other.shape)[other]
    ax.plot(x, diagram.frequencies[other], "o", color="0.5", ms=2.5, ls="none", label="axial or at rest", zorder=2)
    ax.plot(rpm, rpm / 60.0, "k--", lw=1.2, label="1x (speed / 60)")
    for k, omega in enumerate(diagram.critical_speeds, start=1):
        n = omega / RPM
        ax.plot([n], [n / 60.0], "ko", mfc="none", ms=9, zorder=3)
        ax.annotate(f"critical {k}: {n:,.0f} rpm", (n, n / 60.0), xytext=(6, -14), textcoords="offset points")
    if operating_rpm is not None:
        ax.axvline(operating_rpm, color="C2", ls=":", lw=1.2, label=f"K computed at {operating_rpm:g} rpm")
    ax.set_xlabel("speed (rpm)")
    ax.set_ylabel("natural frequency (Hz)")
    ax.set_xlim(rpm[0], rpm[-1])
    ax.set_ylim(0.0, 1.05 * max(np.nanmax(diagram.frequencies), rpm[-1] / 60.0))
    ax.set_title(text, fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def campbell_command(args):
    """Compute, write the CSV and the PNG to --out, print the critical speeds; the exit code."""
    model, diagram, seconds = compute(args)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    stem = f"campbell_{Path(args.shaft).stem}_{args.stiffness}"
    written = [write_csv(diagram, out / f"{stem}.csv")]
    try:
        operating = args.speed if args.stiffness == "operating" else None
        written.append(plot(diagram, out / f"{stem}.png", title(args), operating))
    except ImportError as exc:  # matplotlib is the optional extra `plot`
        print(f"plot skipped ({exc}): pip install 'bearing-fmu[plot]' for the PNG", file=sys.stderr)
    print(f"{title(args)}; {args.points} speeds from 0 to {args.max_speed:g} rpm in {seconds:.2f} s")
    for line in critical_lines(diagram, args.max_speed):
        print(line)
    print("wrote " + ", ".join(str(p) for p in written))
    return 0


def critical_lines(diagram, max_rpm):
    """The printed critical speeds: rpm, rad/s and Hz, or that none lies in the range."""
    if not diagram.critical_speeds.size:
        return [f"no forward critical speed from 0 to {max_rpm:g} rpm"]
    return [
        f"critical speed {k}: {omega / RPM:.2f} rpm = {omega:.4f} rad/s = {omega / (2.0 * math.pi):.3f} Hz (forward)"
        for k, omega in enumerate(diagram.critical_speeds, start=1)
    ]
