"""What an FMU carries beside its model: the modelDescription's product data (version, licence,
copyright, default experiment) and, in documentation/, its variable list as HTML and its reference
result in the layout of the FMI cross-check (<Name>_in.csv, <Name>_ref.csv, <Name>_ref.opt).

The HTML page is made from the same text as fmus/<Name>.md (bearing_fmu.build.variables_markdown),
so the two cannot differ. Cross-check files: comma-separated, a `time` column first; <Name>_in.csv holds
the inputs a master sets at each time (held until the next row), <Name>_ref.csv the outputs the FMU
gives at each time when run from 0 with those inputs and <Name>_ref.opt's step.
"""

import html
import re
import shutil
import zipfile
from pathlib import Path

from . import __version__

LICENSE = "MIT"  # as pyproject.toml's [project] license
COPYRIGHT = "Copyright (c) the bearing_fmu developers"

ENTRY_METADATA = """version = {version!r}
    license = {license!r}
    copyright = {copyright!r}
    default_experiment = DefaultExperiment(start_time=0.0, stop_time={stop!r}, step_size={step!r})
"""


def entry_metadata(stop, step):
    """Class attributes of a generated slave class that pythonfmu writes into modelDescription.xml: the
    product's version, licence and copyright, and the reference experiment as DefaultExperiment."""
    return ENTRY_METADATA.format(version=__version__, license=LICENSE, copyright=COPYRIGHT, stop=stop, step=step)


def _inline(text):
    """HTML of a table cell or paragraph: `code` spans, '\\|' as '|', everything else escaped."""
    parts = re.split(r"(`[^`]*`)", text.replace("\\|", "|"))
    return "".join(
        f"<code>{html.escape(p[1:-1])}</code>" if p.startswith("`") and p.endswith("`") else html.escape(p)
        for p in parts
    )


def _cells(line):
    return [c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]


def markdown_html(text):
    """The HTML page of a variable list as variables_markdown writes it: a '# ' title, paragraphs and one
    table (the subset of Markdown it uses)."""
    lines = text.splitlines()
    title = lines[0][2:] if lines and lines[0].startswith("# ") else "FMU"
    body, table = [], []
    for line in lines[1:] + [""]:
        if line.startswith("|"):
            table.append(line)
            continue
        if table:
            head, rows = _cells(table[0]), [_cells(r) for r in table[2:]]
            body.append("<table>")
            body.append("<tr>" + "".join(f"<th>{_inline(c)}</th>" for c in head) + "</tr>")
            body += ["<tr>" + "".join(f"<td>{_inline(c)}</td>" for c in r) + "</tr>" for r in rows]
            body.append("</table>")
            table = []
        if line.strip():
            body.append(f"<p>{_inline(line)}</p>")
    return (
        f'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n<title>{html.escape(title)}</title>\n'
        "<style>table { border-collapse: collapse } td, th { border: 1px solid #999; padding: 2px 6px }</style>\n"
        f"</head>\n<body>\n<h1>{html.escape(title)}</h1>\n" + "\n".join(body) + "\n</body>\n</html>\n"
    )


def crosscheck_opt(stop, step):
    """<Name>_ref.opt of the FMI cross-check: the experiment's settings."""
    return f"StartTime, 0.0\nStopTime, {stop!r}\nStepSize, {step!r}\nRelTol, 1e-06\n"


def add_files(fmu_path, files):
    """Add (or replace) files in the FMU: {path in the archive: text}."""
    fmu_path = Path(fmu_path)
    staged = fmu_path.with_suffix(".fmu.files")
    with zipfile.ZipFile(fmu_path) as source, zipfile.ZipFile(staged, "w", zipfile.ZIP_DEFLATED) as target:
        for item in source.infolist():
            if item.filename not in files:
                target.writestr(item, source.read(item))
        for name, text in files.items():
            target.writestr(name, text.encode())
    shutil.move(staged, fmu_path)
    return fmu_path


def add_documentation(fmu_path, name, markdown, inputs_csv, reference_csv, stop, step):
    """documentation/index.html (from the variable list's Markdown) and the cross-check files."""
    return add_files(
        fmu_path,
        {
            "documentation/index.html": markdown_html(markdown),
            f"documentation/{name}_in.csv": inputs_csv,
            f"documentation/{name}_ref.csv": reference_csv,
            f"documentation/{name}_ref.opt": crosscheck_opt(stop, step),
        },
    )


def _time(t):
    return round(t, 12)  # k * step without the round-off of the product (0.30000000000000004)


def crosscheck_tables(rows, input_names, step, start_values=None):
    """(<Name>_in.csv rows, <Name>_ref.csv rows, stop time) of a reference experiment in the cross-check's
    reading: a master sets the inputs of time t, steps from t to t + step and reads the outputs at t + step.

    rows: the reference, one dict of inputs and outputs per point. Without a `time` key (the algebraic
    bearing models) row k is the model at row k's inputs: the FMU initialised with row 0 and stepped from
    k step with row k's inputs gives row k's outputs at (k + 1) step. With `time` (the DEM) row k's inputs
    hold over the step that ends at its time, from the FMU initialised with its start values
    (`start_values`): the inputs file starts with the start values at t = 0 and, at the same time (an
    event: a master takes the later row for the step), the first row's inputs."""
    names = [n for n in rows[0] if n in input_names]
    outputs = [n for n in rows[0] if n not in input_names and n != "time"]
    if "time" not in rows[0]:
        inputs = [{"time": _time(k * step), **{n: row[n] for n in names}} for k, row in enumerate(rows)]
        points = [0.0] + [_time((k + 1) * step) for k in range(len(rows))]
        reference = [{"time": t, **{n: row[n] for n in outputs}} for t, row in zip(points, [rows[0], *rows])]
        return inputs, reference, points[-1]
    starts = [0.0] + [row["time"] for row in rows[:-1]]
    inputs = [{"time": 0.0, **{n: start_values[n] for n in names}}]
    inputs += [{"time": _time(t), **{n: row[n] for n in names}} for t, row in zip(starts, rows)]
    reference = [{"time": row["time"], **{n: row[n] for n in outputs}} for row in rows]
    return inputs, reference, rows[-1]["time"]
