"""The one renderer of the benchmarks: every table, figure and report page of docs/reports is drawn here from
the dict a benchmark's measure() returns, and docs/report.md is assembled from the same dicts.

A benchmark only measures. Its measure() returns a result:

    {
        "name": "solver_tolerance",                  # file stem in docs/reports
        "title": "Quasi-static solver tolerance: error against run time",
        "about": "what is measured, on what, against which reference",   # prose without numbers
        "blocks": [                                  # the page, in order
            {"text": "the default {default:g} costs {ratio:.2f} x ...", "values": {"default": 1e-10, "ratio": 1.2}},
            {"table": {"columns": ["tolerance", "error"], "formats": ["{:g}", "{:.3g}"], "rows": [[1e-3, 2.6e-4]]}},
            {"figure": {"file": "solver_tolerance.png", "caption": "...", "panels": [PANEL, ...]}},
        ],
        "metrics": [                                 # the headline numbers docs/report.md quotes and judges
            {"key": "...", "value": 1.0, "unit": "s", "kind": "timing", "target": None, "side_by_side": False},
        ],
        "defaults": [                                # optional: a default of the product chosen from this result
            {"setting": "...", "default": "...", "why": "text with {fields}", "values": {...}},
        ],
    }

Numbers reach prose only through a text block's "values" (formatted here), never written into the text.
A PANEL is {"title", "xlabel", "ylabel", "xscale", "yscale", "series": [{"x", "y", "label", "style",
"annotate"}], "hlines": [{"y", "label", "style"}]}; "annotate" labels each point of a series. Optional panel keys:
"contour" {"x", "y", "z" (z[j][i] at y[j], x[i]), "levels", "label"} (filled, with a colour bar), "aspect"
(e.g. "equal"), "ylim" [low, high].

write(result) writes docs/reports/<name>.md, its figures and <name>.json (the result, for `--reuse` and for
the report) and records its metrics in docs/reports/metrics.json (benchmarks.common.record).
"""

import json
import math
import os
import platform
import time

from . import common

MISSING = "–"


def fill(block):
    """A text block's text with its values formatted in."""
    return block["text"].format(**block.get("values", {}))


def cell(value, form):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return MISSING
    if isinstance(value, str) or form is None:
        return str(value)
    return form.format(value)


def table(spec):
    """Markdown lines of a table spec {"columns", "rows", "formats" (one per column, None = str)}."""
    columns = spec["columns"]
    formats = spec.get("formats") or [None] * len(columns)
    lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    for row in spec["rows"]:
        lines.append("| " + " | ".join(cell(v, f) for v, f in zip(row, formats)) + " |")
    return lines


def figure(spec, folder):
    """Draw a figure spec into folder / spec["file"] (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = spec["panels"]
    columns = spec.get("columns", min(len(panels), 2))
    rows = math.ceil(len(panels) / columns)
    width, height = spec.get("size", (6.0 * columns, 4.0 * rows))
    fig, axes = plt.subplots(rows, columns, figsize=(width, height), squeeze=False)
    for ax, panel in zip(axes.flat, panels):
        draw_panel(ax, panel)
    for ax in list(axes.flat)[len(panels) :]:
        ax.set_visible(False)
    if spec.get("title"):
        fig.suptitle(spec["title"], fontsize=10)
    fig.tight_layout()
    fig.savefig(folder / spec["file"], dpi=spec.get("dpi", 120))
    plt.close(fig)


def draw_panel(ax, panel):
    for series in panel.get("series", []):
        ax.plot(series["x"], series["y"], series.get("style", "o-"), label=series.get("label"), ms=4)
        for x, y, text in zip(series["x"], series["y"], series.get("annotate", [])):
            ax.annotate(text, (x, y), fontsize=7, xytext=(4, 2), textcoords="offset points")
    for line in panel.get("hlines", []):
        ax.axhline(line["y"], ls=line.get("style", "--"), color="grey", lw=0.8, label=line.get("label"))
    if "contour" in panel:
        c = panel["contour"]
        filled = ax.contourf(c["x"], c["y"], c["z"], levels=c.get("levels", 12), extend="max", cmap="viridis")
        ax.figure.colorbar(filled, ax=ax, label=c.get("label", ""))
    if "aspect" in panel:
        ax.set_aspect(panel["aspect"])
    if panel.get("ylim"):
        ax.set_ylim(*panel["ylim"])
    ax.set_xscale(panel.get("xscale", "linear"))
    ax.set_yscale(panel.get("yscale", "linear"))
    ax.set_xlabel(panel.get("xlabel", ""))
    ax.set_ylabel(panel.get("ylabel", ""))
    ax.set_title(panel.get("title", ""), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if any(s.get("label") for s in panel.get("series", [])) or panel.get("hlines"):
        ax.legend(fontsize=7)


def page(result, image_prefix=""):
    """Markdown lines of a result's blocks (its tables, figures and texts)."""
    lines = []
    for block in result["blocks"]:
        if "text" in block:
            lines += [fill(block), ""]
        elif "table" in block:
            caption = block["table"].get("caption")
            lines += ([caption, ""] if caption else []) + table(block["table"]) + [""]
        elif "figure" in block:
            spec = block["figure"]
            lines += [f"![{spec.get('caption', spec['file'])}]({image_prefix}{spec['file']})", ""]
    return lines


def markdown(result):
    """The report page of a result."""
    run = result.get("run", {})
    lines = [f"# {result['title']}", ""]
    if run:
        lines += [
            f"Generated by `{run['command']}` on {run['machine']}, {run['cores']} cores; load average "
            f"{run['load']:.2f} at the start; {run['seconds']:.0f} s in total.",
            "",
        ]
    lines += [result["about"].strip(), ""] + page(result)
    return "\n".join(lines).rstrip() + "\n"


def measured(measure, name, command=None, **options):
    """Call measure(**options) and stamp the result with how it was run (command: the command line that makes the
    same result, where it is not `python -m benchmarks.<name>`)."""
    load_average, t0 = os.getloadavg()[0], time.perf_counter()
    result = measure(**options)
    result["run"] = dict(
        command=command or f"python -m benchmarks.{name}",
        machine=f"{platform.processor() or platform.machine()}, Python {platform.python_version()}",
        cores=os.cpu_count(),
        load=load_average,
        seconds=time.perf_counter() - t0,
    )
    return result


def write(result):
    """Write a result's page, figures and JSON into docs/reports and record its metrics; returns the page's path."""
    folder = common.REPORTS
    folder.mkdir(parents=True, exist_ok=True)
    for block in result["blocks"]:
        if "figure" in block:
            figure(block["figure"], folder)
    (folder / f"{result['name']}.json").write_text(json.dumps(result, indent=1, default=float) + "\n")
    path = folder / f"{result['name']}.md"
    path.write_text(markdown(result))
    common.forget(result["name"])
    for m in result.get("metrics", []):
        common.record(
            result["name"],
            m["key"],
            m["value"],
            m["unit"],
            kind=m["kind"],
            target=m.get("target"),
            note=m.get("note", ""),
            side_by_side=m.get("side_by_side", False),
        )
    print(f"wrote {path}")
    return path


def last_result(name):
    """The result a benchmark last wrote (docs/reports/<name>.json), or None."""
    path = common.REPORTS / f"{name}.json"
    return json.loads(path.read_text()) if path.exists() else None


def cli(measure, name, command=None, **options):
    """A benchmark's command line: measure, write, done."""
    return write(measured(measure, name, command, **options))


def metric(key, value, unit, kind, target=None, side_by_side=False, note=""):
    return dict(key=key, value=float(value), unit=unit, kind=kind, target=target, side_by_side=side_by_side, note=note)
