"""`spindle film`: the films at a bearing's most loaded contacts, at one operating point or over a range of one input
(a film map: speed or one load from A to B in N values), every formula of the product against the numerical EHL
solver, each numerical film with its grid level and whether it converged (bearing_fmu.models.film_check)."""

import math
import sys

# option -> (quasi-static input, unit); speed in rpm on the command line, rad/s for the model
INPUTS = {
    "speed": ("omega", "rpm"),
    "Fx": ("F_x", "N"),
    "Fy": ("F_y", "N"),
    "Fz": ("F_z", "N"),
    "Mx": ("M_x", "N.m"),
    "My": ("M_y", "N.m"),
}
MAP_POINTS = 200  # a map's largest number of points


def values_of(option, text):
    """The values of --option: a number, or A:B:N (N values evenly from A to B, N >= 2). ValueError names the option."""
    parts = str(text).split(":")
    try:
        numbers = [float(p) for p in parts]
    except ValueError:
        numbers = None
    if numbers is None or len(parts) not in (1, 3) or not all(math.isfinite(x) for x in numbers):
        raise ValueError(f"--{option} = {text!r} is not a number nor a range A:B:N (e.g. 3000:15000:7)")
    if len(parts) == 1:
        return numbers
    a, b, n = numbers
    if n != int(n) or not 2 <= n <= MAP_POINTS:
        raise ValueError(f"--{option} = {text!r}: N = {n:g} is outside the allowed range [2, {MAP_POINTS}] (whole)")
    n = int(n)
    return [a + (b - a) * k / (n - 1) for k in range(n)]


def operating_points(args):
    """The operating points of the command, [(rpm, loads dict)], and the swept option (None at a single point).
    ValueError when more than one input is a range."""
    given = {option: values_of(option, getattr(args, option)) for option in INPUTS}
    ranges = [option for option, values in given.items() if len(values) > 1]
    if len(ranges) > 1:
        raise ValueError(f"one input at a time can be a range: {', '.join('--' + r for r in ranges)} are")
    swept = ranges[0] if ranges else None
    points = []
    for k in range(len(given[swept]) if swept else 1):
        values = {option: v[k] if option == swept else v[0] for option, v in given.items()}
        loads = {INPUTS[o][0]: values[o] for o in INPUTS if o != "speed" and values[o]}
        points.append((values["speed"], loads))
    return points, swept


def film_map(args, points, swept):
    """Print the films of every point (and plot them over a range); True when every numerical film converged."""
    from bearing_fmu.models.film_check import film_check, format_film_check

    level = f"grid level {args.level}" if args.level is not None else "the grid level each contact's film needs"
    if swept is None:
        rpm, loads = points[0]
        omega = rpm * math.pi / 30.0
        print(
            f"{args.bearing} with {args.lubricant} at {rpm:g} rpm ({omega:.2f} rad/s), oil at {args.T_oil:g} K, "
            f"loads {loads or 'none'} (N, N.m); numerical solver on {level}"
        )
        checks = film_check(args.bearing, args.lubricant, omega, loads, args.T_oil, args.level)
        print(format_film_check(checks))
        return all(c.converged for c in checks)
    name, unit = INPUTS[swept]
    print(f"{args.bearing} with {args.lubricant}, oil at {args.T_oil:g} K; film map over {swept} ({unit}); "
          f"numerical solver on {level}; films in nm")  # fmt: skip
    rows = []
    for rpm, loads in points:
        checks = film_check(args.bearing, args.lubricant, rpm * math.pi / 30.0, loads, args.T_oil, args.level)
        x = rpm if swept == "speed" else loads.get(name, 0.0)
        rows.append((x, checks))
        for c in checks:
            print(_map_line(swept, x, c), flush=True)
    _plot(args, swept, unit, rows)
    return all(c.converged for _, checks in rows for c in checks)


def _map_line(swept, x, c):
    """One point's line of the map: the input, race, level, convergence, numerical and formula films (nm)."""
    n = c.numerical
    numerical = "no film" if n is None else f"h_c {n.h_c * 1e9:8.1f} h_min {n.h_min * 1e9:8.1f}"
    state = "converged" if c.converged else f"NOT converged ({c.reason})"
    formulas = "  ".join(f"{k} {f.h_c * 1e9:.1f}/{f.h_min * 1e9:.1f}" for k, f in c.formulas.items())
    head = f"{swept} {x:10.6g} {c.race:<5} level {c.level}"
    return f"{head}: numerical {numerical}  [{state}]  formulas h_c/h_min {formulas}"


def _plot(args, swept, unit, rows):
    """The film map's figure: per race, the numerical h_c and h_min (filled where converged, open where not) and every
    formula's, over the swept input."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("note: matplotlib is not installed (pip install bearing_fmu[plot]): no figure", file=sys.stderr)
        return
    races = [race for race in ("inner", "outer") if any(c.race == race for _, checks in rows for c in checks)]
    fig, axes = plt.subplots(1, len(races), figsize=(6 * len(races), 4.5), squeeze=False)
    for ax, race in zip(axes[0], races):
        points = [(x, c) for x, checks in rows for c in checks if c.race == race]
        for key, style in (("h_c", "C0"), ("h_min", "C1")):
            for converged, marker in ((True, "o"), (False, "x")):
                got = [
                    (x, 1e9 * getattr(c.numerical, key)) for x, c in points if c.numerical and c.converged == converged
                ]
                if got:
                    label = f"numerical {key}" + ("" if converged else " (not converged)")
                    ax.plot(*zip(*got), marker, color=style, label=label)
            for k, formula in enumerate(points[0][1].formulas):
                xs = [x for x, _ in points]
                ax.plot(xs, [1e9 * getattr(c.formulas[formula], key) for _, c in points], "-" if key == "h_c" else "--",
                        color=f"C{k + 2}", label=f"{formula} {key}")  # fmt: skip
        ax.set_title(f"{args.bearing}, most loaded {race} contact")
        ax.set_xlabel(f"{swept} ({unit})")
        ax.set_ylabel("film (nm)")
        ax.set_yscale("log")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.plot, dpi=120)
    plt.close(fig)
    print(f"wrote {args.plot}")
