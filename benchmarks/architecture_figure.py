"""Draw docs/architecture.png from the code: the layers of tests/unit/test_import_graph.py.LAYERS, each with its
modules as the import graph finds them, the number of imports from each layer to each one below, and where a new
fidelity, block, parameter and output go.

    python -m benchmarks.architecture_figure          # writes docs/architecture.png
"""

import argparse
from collections import Counter
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from tests.unit.test_import_graph import LAYERS, import_graph, layer_of  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "docs" / "architecture.png"
# where a change goes (docs/architecture.md, section 1): shown beside the layer it starts in
WHERE = {
    "fidelity registry": "new fidelity: its FIDELITY beside its facade, one entry here,\n"
    "its scene rules in scene.FIDELITY_RULES; FMU layer and build unchanged",
    "models (facades, declarations, scenes, parameter files)": "new parameter or output: one Variable in\n"
    "models/declarations.py (range, unit, source slot); new block: its packing\n"
    "function ('off': the null block) and one write_blocks pair per fidelity",
    "kernels": "new array entry: one Layout slot (no number written); new block: its Layout\n"
    "in the kernel that reads it, one slot of its size per fidelity;\n"
    "every jitted kernel has a plain-Python twin in tests/reference",
}


def _short(module, prefixes):
    """The module's name without its bearing_fmu package (models., kernels.), for the box."""
    for prefix in sorted(prefixes, key=len, reverse=True):
        if module.startswith(prefix + ".") and prefix.startswith("bearing_fmu."):
            return module[len(prefix) + 1 :]
    return module


def _module_text(modules, prefixes, width=100):
    names = sorted(_short(m, prefixes) for m in modules)
    lines, line = [], ""
    for name in names:
        if len(line) + len(name) + 2 > width:
            lines.append(line)
            line = ""
        line += (", " if line else "") + name
    return "\n".join(lines + [line])


def draw(out=OUT):
    graph = import_graph()
    members = {i: [m for m in graph if layer_of(m) == i] for i in range(len(LAYERS))}
    edges = Counter((layer_of(m), layer_of(e)) for m, targets in graph.items() for e in targets)
    heights = [1.0 + 0.32 * _module_text(members[i], LAYERS[i][1]).count("\n") for i in range(len(LAYERS))]
    gap = 0.9
    total = sum(heights) + gap * (len(LAYERS) - 1)
    fig, ax = plt.subplots(figsize=(18, 0.62 * total + 1.0))
    ax.set_xlim(0, 18)
    ax.set_ylim(0, total)
    ax.axis("off")
    tops, y = {}, total
    for i, (name, prefixes) in enumerate(LAYERS):
        h = heights[i]
        ax.add_patch(plt.Rectangle((0.2, y - h), 9.4, h, fill=True, facecolor="#eef3f8", edgecolor="#34495e"))
        ax.text(0.35, y - 0.25, f"{name}  ({len(members[i])} modules)", fontsize=10, weight="bold", va="top")
        ax.text(0.35, y - 0.6, _module_text(members[i], prefixes), fontsize=7, va="top", family="monospace")
        if name in WHERE:
            ax.text(12.6, y - 0.2, WHERE[name], fontsize=8, va="top", color="#7b241c")
        tops[i] = (y, y - h)
        y -= h + gap
    for (a, b), n in sorted(edges.items()):
        if a == b:
            continue
        x = 9.8 + 0.4 * (b - a - 1) + 0.12 * a
        ax.annotate("", xy=(x, tops[b][0]), xytext=(x, tops[a][1]), arrowprops={"arrowstyle": "->", "color": "#555"})
        ax.text(x + 0.05, tops[a][1] - 0.2, str(n), fontsize=7, color="#555", va="top")
    ax.set_title(
        "Layers of the product, drawn from its imports (arrows: imports from a layer to one below, with their count;"
        " none points up)",
        fontsize=10,
    )
    fig.savefig(out, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(OUT))
    print(f"wrote {draw(Path(parser.parse_args(argv).out))}")


if __name__ == "__main__":
    main()
