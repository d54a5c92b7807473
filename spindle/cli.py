"""Command line `spindle` (docs/architecture.md): build, run, sweep, info, demo.

    spindle build [--out fmus] [--config FILE]    build every FMU (bearing scenes + SpindleThermal), or the
                                                  configured FMUs of a configuration file (<Name>_<name>.fmu)
    spindle run RUNFILE [--out results] [--set KEY=VALUE ...] [--fmus DIR] [--no-plot] [--progress]
    spindle sweep RUNFILE --param KEY --values V1,V2,... [--scheduler ADDRESS] [--workers N] [--serial]
                  [--set KEY=VALUE ...] [--fmus DIR] [--out results]   Dask if installed, else one after the other
    spindle info [FMU ...]                        what is built: variables, units, parameters
    spindle demo [--out results]                  the closed-loop demo run (runs/closed_loop_spring.toml)
    spindle validate [FMU|RUNFILE ...]            fmpy's validator on the FMUs; run files (.toml) checked
    spindle check [FMU ...] [--ref CSV]           simulate each FMU's reference experiment, compare with <Name>_ref.csv
    spindle export-ssp RUNFILE [--out FILE.ssp]   the run's FMUs, connections and parameters as an SSP 1.0 package
    spindle campbell [--shaft S] [--bearing B] [--preload N] [--radial N] [--speed RPM] [--max-speed RPM]
                     [--points N] [--stiffness operating|speed] [--out results]   Campbell diagram: CSV + PNG
    spindle --version

Exit codes: 0 done; 1 error (message on stderr); 2 usage error or an FMU with validation problems;
3 the run stopped at a limit (e.g. thermal runaway; results up to there are written); 4 `check` found an
output differing from the reference; 141 (128 + SIGPIPE) the output was closed by its reader (`| head`),
the command stopped quietly.
"""

import argparse
import json
import os
import signal
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
IN_CHECKOUT = (ROOT / "pyproject.toml").is_file() and (ROOT / "runs").is_dir()  # source tree, not an installed wheel
RUNS = ROOT / "runs"
# FMUs go to the checkout's fmus/ in a source tree, else to ./fmus of the working directory
FMUS = ROOT / "fmus" if IN_CHECKOUT else Path.cwd() / "fmus"
DEMO_RUN = RUNS / "closed_loop_spring.toml"
EXIT_OK, EXIT_ERROR, EXIT_INVALID, EXIT_LIMIT, EXIT_DIFFERS, EXIT_UNCONVERGED = 0, 1, 2, 3, 4, 5
EXIT_PIPE = 128 + signal.SIGPIPE  # the output was closed by its reader (e.g. `| head`): stopped quietly
EXIT_CODES = f"""exit codes:
  {EXIT_OK}  done
  {EXIT_ERROR}  error (message on stderr)
  {EXIT_INVALID}  usage error, or `validate` found problems in an FMU or a run file
  {EXIT_LIMIT}  a run stopped at a limit (e.g. thermal runaway); results up to there are written
  {EXIT_DIFFERS}  `check`: an FMU's output differs from its reference (the variable is named)
  {EXIT_UNCONVERGED}  `film`: a requested contact's numerical film did not converge (its reason is printed)
  {EXIT_PIPE}  the output was closed by its reader (e.g. `spindle info | head`): stopped quietly"""


def _value(text):
    """Command-line value: number when it parses as one, a table [[t, value], ...] (JSON) when it
    starts with '[', else the string."""
    if text.startswith("["):
        try:
            return json.loads(text)
        except json.JSONDecodeError:
            raise SystemExit(f"{text!r}: a table is written [[t, value], ...], e.g. [[0,0],[2,1047.2]]") from None
    try:
        return int(text)
    except ValueError:
        try:
            return float(text)
        except ValueError:
            return text


def _overrides(pairs):
    out = {}
    for pair in pairs or []:
        key, sep, value = pair.partition("=")
        if not sep:
            raise SystemExit(f"--set {pair!r}: write KEY=VALUE, e.g. --set run.step=0.5")
        out[key.strip()] = _value(value.strip())
    return out


def cmd_build(args):
    from .all_fmus import build_all

    if args.config:
        from .configured import ConfigurationError, build_configured

        try:
            paths, notes = build_configured(args.config, args.out)
        except ConfigurationError as exc:
            print(f"spindle build: {exc}", file=sys.stderr)
            return EXIT_ERROR
        for note in notes:
            print(note)
    else:
        paths = build_all(args.out)
    for path in paths:
        print(f"built {path}")
    return 0


def cmd_run(args):
    from .cosim.master import run
    from .cosim.runfile import load_run

    overrides = _overrides(args.set)
    spec = load_run(args.runfile, overrides, fmu_dir=args.fmus)
    missing = sorted({inst.fmu for inst in spec.instances.values() if not Path(inst.fmu).is_file()})
    if missing:
        print(
            f"spindle run: FMU not found: {', '.join(missing)}. Build the FMUs with `spindle build` "
            f"(default folder {FMUS}) or name their folder with --fmus DIR",
            file=sys.stderr,
        )
        return EXIT_ERROR
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    stem = Path(args.runfile).stem
    csv_path = out / f"{stem}.csv"
    # rows go to the CSV as the run goes (memory flat in run length); the plot reads the file row by row
    result = run(spec, progress=args.progress, record_interval=args.record_interval, csv_path=csv_path)
    written = [csv_path, _write_run_record(out / f"{stem}.run.json", args.runfile, spec, overrides, result)]
    if not args.no_plot:
        try:
            from .cosim.plots import plot_run, plot_title

            title = plot_title(stem, spec.description, overrides)
            written.append(plot_run(result, out / f"{stem}.png", title=title))
        except ImportError as exc:  # matplotlib is the optional extra `plot`
            print(f"plot skipped ({exc}): pip install 'bearing-fmu[plot]' for the PNG", file=sys.stderr)
    print(
        f"{stem}: {result.n_steps} steps of {spec.step} s ({spec.algorithm}) in {result.wall_time:.2f} s wall "
        f"(+ {result.setup_time:.2f} s set-up); rejected steps: {result.rejected_steps}"
    )
    print("wrote " + ", ".join(str(p) for p in written))
    if result.status == "limit":
        print(f"STOPPED: {result.message}", file=sys.stderr)
        return EXIT_LIMIT
    return 0


def _write_run_record(path, runfile, spec, overrides, result):
    """The side-car of a run's CSV (<stem>.run.json): which run file, with which --set overrides, produced it,
    so a result never passes for the run file's own case (a 6000 rpm run of a 10 000 rpm file)."""
    from bearing_fmu import __version__

    record = {
        "run_file": str(Path(runfile).resolve()),
        "description": spec.description,
        "overrides": overrides,
        "start": spec.start,
        "stop": spec.stop,
        "step": spec.step,
        "algorithm": spec.algorithm,
        "status": result.status,
        "message": result.message,
        "steps": result.n_steps,
        "version": __version__,
    }
    Path(path).write_text(json.dumps(record, indent=2) + "\n")
    return path


def cmd_sweep(args):
    from .cosim.runfile import load_run
    from .cosim.sweep import DaskMissing, sequential, sweep, write_table

    values = [_value(v) for v in args.values.split(",") if v.strip()]
    extra = _overrides(args.set)
    # an unreadable run file or a bad [run] key: one message before any run, not one failed row per point
    load_run(args.runfile, {**extra, args.param: values[0]} if values else extra, fmu_dir=args.fmus)
    try:
        if args.serial:
            raise DaskMissing("--serial")
        rows = sweep(
            args.runfile,
            args.param,
            values,
            scheduler=args.scheduler,
            n_workers=args.workers,
            extra=extra,
            fmu_dir=args.fmus,
        )
    except DaskMissing as exc:
        if args.scheduler is not None:  # a cluster was asked for: running here instead would surprise
            print(f"spindle sweep: {exc}; --scheduler needs it", file=sys.stderr)
            return EXIT_ERROR
        if not args.serial:
            print(f"spindle sweep: {exc}; running the {len(values)} points one after the other here", file=sys.stderr)
        rows = sequential(args.runfile, args.param, values, extra=extra, fmu_dir=args.fmus)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    path = out / f"{Path(args.runfile).stem}_sweep_{args.param.replace('.', '_')}.csv"
    write_table(rows, path)
    failed = [r for r in rows if r["status"] != "ok"]
    print(f"{len(rows)} runs, {len(failed)} not ok; wrote {path}")
    for r in failed:
        print(f"  {args.param} = {r[args.param]}: {r['status']}: {r['message']}")
    return 0


def cmd_info(args):
    from fmpy import read_model_description

    paths = [Path(p) for p in args.fmus] or sorted(FMUS.glob("*.fmu"))
    if not paths:
        print(f"no FMUs in {FMUS}: run `spindle build`")
        return 1
    for path in paths:
        md = read_model_description(str(path))
        groups = {}
        for v in md.modelVariables:
            groups.setdefault(v.causality, []).append(v)
        print(f"{path.name}: FMI {md.fmiVersion} co-simulation, {len(md.modelVariables)} variables")
        print(f"  {md.description}")
        for causality in ("parameter", "input", "output"):
            for v in groups.get(causality, []) if args.fmus else []:
                allowed = (
                    f" range [{float(v.min):g}, {float(v.max):g}]" if v.min is not None and v.max is not None else ""
                )
                print(f"  {causality:9s} {v.name:20s} [{v.unit or '-'}]{allowed} {v.description or ''}")
            if not args.fmus:  # every name: a list cut short hides the variable a user looks for
                names = [v.name for v in groups.get(causality, [])]
                print(f"  {causality}s ({len(names)}): {', '.join(names)}")
    return 0


def cmd_demo(args):
    if not DEMO_RUN.is_file():
        print(
            f"spindle demo: the demo run file {DEMO_RUN} is part of the source tree; outside it use "
            f"`spindle run <clone>/runs/closed_loop_spring.toml --fmus {FMUS}`",
            file=sys.stderr,
        )
        return EXIT_ERROR
    args.runfile = str(DEMO_RUN)
    args.set, args.no_plot, args.progress, args.fmus, args.record_interval = [], False, False, None, None
    return cmd_run(args)


def cmd_validate(args):
    """fmpy's validator on each FMU (default: every FMU in the FMU folder); a run file (.toml) is read
    and checked (keys, step, connections, input schedules) instead; problems are printed."""
    from fmpy.validation import validate_fmu

    from .cosim.runfile import RunFileError, load_run

    paths = [Path(p) for p in args.fmus] or sorted(FMUS.glob("*.fmu"))
    if not paths:
        print(f"spindle validate: no FMUs in {FMUS}: run `spindle build` or name the FMUs", file=sys.stderr)
        return EXIT_ERROR
    bad = 0
    for path in paths:
        try:
            if path.suffix == ".toml":
                try:
                    load_run(path)
                    problems = []
                except RunFileError as exc:
                    problems = [str(exc)]
            else:
                problems = validate_fmu(str(path))
        except Exception as exc:  # not an FMU at all (missing, not a zip archive, no modelDescription.xml)
            problems = [f"cannot be read as an FMU: {type(exc).__name__}: {exc}"]
        bad += bool(problems)
        print(f"{path.name}: " + ("valid" if not problems else f"{len(problems)} problem(s)"))
        for problem in problems:
            print(f"  {problem}")
    return EXIT_INVALID if bad else EXIT_OK


def cmd_check(args):
    """Each FMU (default: every FMU in the FMU folder) against its reference result."""
    from .check import ATOL_SCALE, RTOL, check_fmu

    paths = [Path(p) for p in args.fmus] or sorted(FMUS.glob("*.fmu"))
    if not paths:
        print(f"spindle check: no FMUs in {FMUS}: run `spindle build` or name the FMUs", file=sys.stderr)
        return EXIT_ERROR
    if args.ref and len(paths) != 1:
        print("spindle check: --ref needs exactly one FMU", file=sys.stderr)
        return EXIT_INVALID
    failed = 0
    for path in paths:
        result = check_fmu(path, args.ref)
        failed += not result.passed
        verdict = "ok" if result.passed else f"DIFFERS in {len(result.differences)} output(s)"
        print(
            f"{path.name}: {verdict} ({result.rows} points, {result.outputs} outputs; "
            f"largest difference {result.worst:.3g} x tolerance)"
        )
        for line in result.differences:
            print(f"  {line}")
    print(f"tolerance: {RTOL:g} relative, floor {ATOL_SCALE * RTOL:g} x the column's largest magnitude")
    return EXIT_DIFFERS if failed else EXIT_OK


def cmd_export_ssp(args):
    from .cosim.runfile import load_run
    from .cosim.ssp import export_ssp

    spec = load_run(args.runfile, _overrides(args.set), fmu_dir=args.fmus)
    out = Path(args.out) if args.out else Path(args.runfile).with_suffix(".ssp").name
    notes = []
    print(f"wrote {export_ssp(spec, out, notes)}")
    for note in notes:
        print(f"note: {note}", file=sys.stderr)
    if spec.algorithm != "jacobi":
        print(
            f"note: the run file steps {spec.algorithm}; libcosim and most SSP masters exchange Jacobi-style, "
            "which `spindle run --set run.algorithm=jacobi` reproduces to the bit",
            file=sys.stderr,
        )
    return EXIT_OK


def cmd_film(args):
    """The film at the most loaded inner and outer contacts of a quasi-static operating point: every film formula
    against the numerical EHL solver (bearing_fmu.models.film_check); over a range of one input (A:B:N) a film map.
    Exit EXIT_UNCONVERGED when a contact's numerical film did not converge."""
    from bearing_fmu.models.limits import T_OIL_RANGE, InputError
    from bearing_fmu_common.paramfile import ParameterError

    from .film_map import film_map, operating_points

    low, high = T_OIL_RANGE
    if not low <= args.T_oil <= high:
        raise SystemExit(
            f"spindle film: --T-oil = {args.T_oil:g} K is outside the allowed range [{low:g}, {high:g}] K (kelvin: "
            f"40 C is 313.15 K)"
        )
    try:
        points, swept = operating_points(args)
    except ValueError as exc:
        raise SystemExit(f"spindle film: {exc}") from None
    if _kernels_not_compiled("ehl_solver"):
        print("note: the first run compiles the film solver's kernels (about a minute); later runs reuse them",
              file=sys.stderr)  # fmt: skip
    try:
        converged = film_map(args, points, swept)
    except (InputError, ParameterError) as exc:
        print(f"spindle film: {exc}", file=sys.stderr)
        return EXIT_ERROR
    return EXIT_OK if converged else EXIT_UNCONVERGED


def cmd_campbell(args):
    """The shaft's Campbell diagram on quasi-static bearings (spindle.campbell_cli): CSV, PNG, critical speeds."""
    from bearing_fmu.models.limits import InputError
    from bearing_fmu_common.paramfile import ParameterError

    from .campbell_cli import OptionError, campbell_command

    if _kernels_not_compiled("jones_harris"):
        print("note: the first run compiles the quasi-static bearing's kernels (a few minutes); later runs reuse them",
              file=sys.stderr)  # fmt: skip
    try:
        return campbell_command(args)
    except OptionError as exc:
        print(f"spindle campbell: {exc}", file=sys.stderr)
        return EXIT_INVALID
    except (InputError, ParameterError) as exc:
        print(f"spindle campbell: {exc}", file=sys.stderr)
        return EXIT_ERROR


def _kernels_not_compiled(module):
    """Whether the user cache holds no compiled kernel of bearing_fmu.kernels.<module> (a first run compiles)."""
    from bearing_fmu_common.jit import user_cache_dir

    try:
        folder = user_cache_dir() / "bearing_fmu" / "kernels"
    except OSError:
        return True
    return not any(folder.glob(f"{module}.*.nbi"))


def _level(text):
    """--level: a grid level of the numerical EHL solver, 0 to its finest."""
    from bearing_fmu.models.ehl_numerical import FINEST_LEVEL

    try:
        level = int(text)
    except ValueError:
        level = None
    if level is None or not 0 <= level <= FINEST_LEVEL:
        raise argparse.ArgumentTypeError(
            f"--level = {text} is outside the allowed range [0, {FINEST_LEVEL}] (a whole number; leave it out for the "
            "level each contact's film needs)"
        )
    return level


def cmd_film_table(args):
    """Build the film correction table of a bearing and lubricant into the cache (models.film_table_build)."""
    from bearing_fmu.models.film_table import table_path
    from bearing_fmu.models.film_table_build import build_film_table
    from bearing_fmu.params import load_bearing, load_lubricant

    print(
        f"film table of {args.bearing} with {args.lubricant}: solving each node on the grid level its film needs "
        f"with {args.jobs} process(es)"
    )
    table = build_film_table(args.bearing, args.lubricant, jobs=args.jobs, log=True)
    nodes = [node for race in table.races for node in race.nodes]
    late = sum(not node["converged"] for node in nodes)
    path = table_path(load_bearing(args.bearing), load_lubricant(args.lubricant))
    print(f"built in {table.seconds:.0f} s ({len(nodes)} nodes, {late} not converged): {path}")
    return EXIT_OK


class _Version(argparse.Action):
    """--version: imports bearing_fmu (the one place of the version) only when asked, so that a command that
    runs FMUs leaves each bearing FMU its own bundled package (docs/fmu_runtime.md, "The master")."""

    def __init__(self, option_strings, dest, **kwargs):
        super().__init__(option_strings, dest, nargs=0, help="show the version and exit")

    def __call__(self, parser, namespace, values, option_string=None):
        from bearing_fmu import __version__

        print(f"{parser.prog} {__version__}")
        parser.exit()


def _parser():
    """The command line: the `spindle` parser and its subcommands."""
    parser = argparse.ArgumentParser(
        prog="spindle",
        description="bearing/spindle co-simulation tools",
        epilog=EXIT_CODES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action=_Version)
    sub = parser.add_subparsers(dest="command", required=True)
    raw = argparse.RawDescriptionHelpFormatter
    _add_run_commands(sub, raw)
    _add_fmu_commands(sub)
    _add_film_commands(sub)
    _add_shaft_commands(sub)
    return parser


def _add_run_commands(sub, raw):
    """build, run and sweep."""
    p = sub.add_parser("build", help=f"build every FMU into {FMUS}, or the configured FMUs of --config")
    p.add_argument("--out", default=str(FMUS))
    p.add_argument(
        "--config",
        metavar="FILE",
        help="a configuration file (bearing, lubricant, race control, network, shaft): build the FMUs whose start "
        "values they are, named <Name>_<name>.fmu (docs/parameters.md, configured FMUs)",
    )
    p = sub.add_parser("run", help="run a run file; write CSV and PNG", epilog=EXIT_CODES, formatter_class=raw)
    p.add_argument("runfile")
    p.add_argument("--out", default="results")
    p.add_argument(
        "--set",
        action="append",
        metavar="KEY=VALUE",
        help="override a [run] key or an instance's parameter or unconnected input, e.g. run.step=0.5 "
        "(an unknown key or a connected input is refused)",
    )
    p.add_argument("--no-plot", action="store_true")
    p.add_argument("--progress", action="store_true", help="progress bar on stderr")
    p.add_argument("--fmus", default=None, metavar="DIR", help="folder of the FMUs the run file names")
    p.add_argument(
        "--record-interval",
        type=float,
        default=None,
        metavar="SECONDS",
        help="record every this many seconds (a multiple of the step; default every step)",
    )
    p = sub.add_parser(
        "sweep",
        help="many runs of a run file on Dask (without dask: one after the other); one table",
        epilog=EXIT_CODES,
        formatter_class=raw,
    )
    p.add_argument("runfile")
    p.add_argument("--param", required=True, help="dotted key, e.g. bearing_1.F_z or run.step")
    p.add_argument("--values", required=True, help="comma-separated values")
    p.add_argument("--set", action="append", metavar="KEY=VALUE", help="fixed overrides for every run")
    p.add_argument("--scheduler", default=None, help="address of a Dask scheduler (default: local cluster)")
    p.add_argument("--workers", type=int, default=2, help="local cluster worker processes")
    p.add_argument("--fmus", default=None, metavar="DIR", help="folder of the FMUs the run file names")
    p.add_argument(
        "--serial",
        action="store_true",
        help="run the points one after the other in this process, without Dask (also what happens, with a "
        "note, when dask is not installed and no --scheduler is given)",
    )
    p.add_argument("--out", default="results")


def _add_fmu_commands(sub):
    """info, demo, validate, check and export-ssp."""
    p = sub.add_parser("info", help="what the FMUs expose")
    p.add_argument("fmus", nargs="*")
    p = sub.add_parser("demo", help="closed-loop demo (runs/closed_loop_spring.toml): CSV + PNG")
    p.add_argument("--out", default="results")
    p = sub.add_parser(
        "validate", help="check FMUs with fmpy's validator, or run files (.toml) (exit 2 on any problem)"
    )
    p.add_argument("fmus", nargs="*")
    p = sub.add_parser(
        "check",
        help="simulate each FMU's reference experiment and compare with <Name>_ref.csv (exit 4 on a difference)",
    )
    p.add_argument("fmus", nargs="*")
    p.add_argument("--ref", default=None, metavar="CSV", help="reference CSV (default: <Name>_ref.csv beside the FMU)")
    p = sub.add_parser("export-ssp", help="write a run file's system as an SSP 1.0 package (.ssp) for other masters")
    p.add_argument("runfile")
    p.add_argument("--out", default=None, metavar="FILE", help="the .ssp file (default: <runfile stem>.ssp here)")
    p.add_argument("--set", action="append", metavar="KEY=VALUE", help="override, e.g. bearing_1.F_z=1000")
    p.add_argument("--fmus", default=None, metavar="DIR", help="folder of the FMUs the run file names")


def _add_film_commands(sub):
    """film and film-table: the film formulas against the numerical EHL solver, the film correction table."""
    p = sub.add_parser(
        "film",
        help="film formulas against the numerical EHL solver at the most loaded contacts of an operating point",
    )
    p.add_argument("bearing", help="bearing name or file (e.g. 6208, B7214C)")
    p.add_argument("--lubricant", required=True, help="lubricant name or file (e.g. iso_vg68_mineral)")
    span = " or a range A:B:N (N values from A to B: a film map)"
    p.add_argument("--speed", "--speeds", required=True, metavar="RPM", help="inner-ring speed (rpm)" + span)
    axes = (
        ("Fx", "N", "radial load on the inner ring along x (a positive F_x loads the ball at psi = 0)"),
        ("Fy", "N", "radial load on the inner ring along y"),
        ("Fz", "N", "axial load on the inner ring along z (+z: the thrust a single angular-contact bearing carries)"),
        ("Mx", "N.m", "moment on the inner ring about x"),
        ("My", "N.m", "moment on the inner ring about y"),
    )
    for name, unit, text in axes:
        p.add_argument(f"--{name}", default="0", metavar=unit, help=f"{text} ({unit}, default 0; docs/conventions.md)"
                       + span)  # fmt: skip
    p.add_argument("--T-oil", dest="T_oil", type=float, default=313.15, metavar="K",
                   help="oil temperature (K, default 313.15 K = 40 C)")  # fmt: skip
    p.add_argument(
        "--level",
        type=_level,
        default=None,
        help="grid level of the numerical solver, 0-5 (default: the level each contact's film needs, 3-5, within "
        "~2 %% of the grid-converged film, or the next finer where that one does not converge; docs/ehl_solver.md)",
    )
    p.add_argument("--plot", default="film_map.png", metavar="PNG",
                   help="the film map's figure, written when one input is a range (default film_map.png)")  # fmt: skip
    p = sub.add_parser(
        "film-table",
        help="build the film correction table of a bearing and lubricant (scene option film_correction = 'table')",
    )
    p.add_argument("bearing", help="bearing name or file (e.g. 6208, B7214C)")
    p.add_argument("--lubricant", required=True, help="lubricant name or file (e.g. iso_vg68_mineral)")
    p.add_argument("--jobs", type=int, default=1, help="processes solving the nodes (default 1)")


def _add_shaft_commands(sub):
    """campbell: the shaft's natural frequencies over speed on quasi-static bearings."""
    from .campbell_cli import STIFFNESS_MODES

    p = sub.add_parser(
        "campbell",
        help="Campbell diagram of the shaft on quasi-static bearings: first six frequencies with their whirl over "
        "speed, the 1x line and the forward critical speeds (CSV + PNG)",
    )
    p.add_argument("--shaft", default=None, help="shaft name or file (default: the default shaft, rabreau_b7214c)")
    p.add_argument("--bearing", default="B7214C", help="bearing at every seat, name or file (default B7214C)")
    p.add_argument("--lubricant", default="iso_vg68_mineral", help="lubricant name or file (default iso_vg68_mineral)")
    p.add_argument("--preload", type=float, default=800.0, metavar="N",
                   help="axial load F_z on each bearing (N, default 800)")  # fmt: skip
    p.add_argument("--radial", type=float, default=0.0, metavar="N",
                   help="radial load F_x on each bearing (N, default 0)")  # fmt: skip
    p.add_argument("--damping", type=float, default=2000.0, metavar="N.s/m",
                   help="viscous damping of each seat in x and y (N.s/m, default 2000 as SpindleShaft.fmu's c_s; "
                   "0: undamped)")  # fmt: skip
    p.add_argument("--speed", type=float, default=10000.0, metavar="RPM",
                   help="operating speed at which the bearings' K is computed (rpm, default 10000)")  # fmt: skip
    p.add_argument("--max-speed", type=float, default=30000.0, metavar="RPM",
                   help="end of the speed range, from 0 (rpm, default 30000)")  # fmt: skip
    p.add_argument("--points", type=int, default=61, help="speeds in the range (default 61)")
    p.add_argument(
        "--stiffness",
        choices=STIFFNESS_MODES,
        default="operating",
        help="operating: K at --speed held over the range (the classical diagram); speed: K recomputed by the "
        "quasi-static bearing at each speed",
    )
    p.add_argument("--floating", action="append", metavar="SEAT",
                   help="a seat (name or number from 1) whose outer ring floats axially, preloaded by springs or an "
                   "actuator: its axial stiffness is condensed out (repeatable; default: none)")  # fmt: skip
    p.add_argument("--out", default="results", help="folder of the CSV and PNG (default results)")


def main(argv=None):
    parser = _parser()
    args = parser.parse_args(argv)
    handler = {
        "build": cmd_build,
        "run": cmd_run,
        "sweep": cmd_sweep,
        "info": cmd_info,
        "demo": cmd_demo,
        "validate": cmd_validate,
        "check": cmd_check,
        "export-ssp": cmd_export_ssp,
        "film": cmd_film,
        "film-table": cmd_film_table,
        "campbell": cmd_campbell,
    }
    try:
        return handler[args.command](args)
    except Exception as exc:  # a clear one-line message, not a traceback, for user errors
        from .cosim.master import MasterError
        from .cosim.runfile import RunFileError

        if isinstance(exc, (MasterError, RunFileError, FileNotFoundError)):
            print(f"spindle {args.command}: {exc}", file=sys.stderr)
            return EXIT_ERROR
        raise


def run():
    """Console-script entry `spindle`: main()'s return value is the exit code. A reader that closes the output
    early (`spindle info | head`) ends the command quietly, as it ends a Unix tool: no traceback, exit status
    128 + SIGPIPE (the shell's status of a tool stopped by SIGPIPE)."""
    try:
        code = main()
        sys.stdout.flush()  # a closed pipe shows here rather than at interpreter exit
    except BrokenPipeError:
        # Python would flush stdout again at exit and report the closed pipe: point it at /dev/null first
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        code = EXIT_PIPE
    sys.exit(code)


if __name__ == "__main__":
    run()
