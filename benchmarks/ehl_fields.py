"""Pressure and film fields of three Annexe D cases, drawn as the thesis draws its solutions: the pressure and the
film along the centre line (the pressure spike and the exit constriction) and the film over the contact (the
horseshoe of the side lobes).

Cases (tests/validation/data/thesis_annexe_d_ehl.csv): 6 (k = 1, 120 N, 2 m/s: a light circular contact), 28 (k = 1,
800 N, 2 m/s: heavier, M = 360) and 12 (k = 5.03, 800 N, 0.5 m/s: a wide contact, M = 3635), each on the solver's
default grid.
Run: python -m benchmarks.ehl_fields -> docs/reports/ehl_fields.md and .png
"""

import numpy as np

from tests.cases.ehl_annexe_d import cases, solve

from .render import cli

CASES = (6, 28, 12)
SPAN = 2.5  # the film map is coloured from the minimum film up to SPAN times it


def solved(case):
    """The case on the default grid: its table row and its three panels (pressure and film on the centre line,
    film over the contact)."""
    solution, seconds = solve(case)
    grid = solution.grid
    X, Y, H = grid.X.tolist(), grid.Y.tolist(), solution.H
    centre = int(np.argmin(np.abs(grid.Y)))
    h_line = solution.H[:, centre].tolist()
    title = f"case {case['n']}: k = {case['k']:g}, {case['w_N']:g} N, {case['ue_m_s']:g} m/s"
    row = [case["n"], case["k"], case["w_N"], case["ue_m_s"], solution.h_c * 1e9, case["hc_nm"], solution.h_min * 1e9]
    row += [case["hm_nm"], "yes" if solution.converged else "no", seconds]
    panels = [
        dict(title=title, xlabel="X = x / b (entrainment along +X)", ylabel="P = p / p_h (centre line)",
             series=[dict(x=X, y=solution.P[:, centre].tolist(), style="k-")]),
        dict(title="film on the centre line", xlabel="X", ylabel="H = h R_x / b^2 (centre line)",
             ylim=[0.0, 3.0 * min(h_line) + 1e-12], series=[dict(x=X, y=h_line, style="b-")]),
        dict(title="film over the contact: the horseshoe", xlabel="X", ylabel="Y = y / a", aspect="equal",
             contour=dict(x=X, y=Y, z=H.T.tolist(), levels=np.linspace(H.min(), SPAN * H.min(), 12).tolist(),
                          label="H")),
    ]  # fmt: skip
    return row, panels


COLUMNS = ["case", "k", "load (N)", "u_e (m/s)", "h_c nm", "thesis", "h_min nm", "thesis", "converged", "solve (s)"]
TEXT = (
    "Figure, one column per case: the pressure and the film on the centre line, and the film over the contact "
    "coloured up to {span:g} times its minimum."
)


def measure():
    table = {c["n"]: c for c in cases()}
    rows, columns = zip(*(solved(table[n]) for n in CASES))
    panels = [column[i] for i in range(3) for column in columns]  # row by row: one column per case
    figure = dict(file="ehl_fields.png", caption="centre-line pressure and film, film map", panels=panels,
                  columns=len(CASES), size=(5.0 * len(CASES), 11.0), dpi=100)  # fmt: skip
    formats = "{} {:g} {:g} {:g} {:.1f} {:g} {:.1f} {:g} {} {:.1f}".split()
    blocks = [{"text": TEXT, "values": dict(span=SPAN)}, {"table": dict(columns=COLUMNS, formats=formats, rows=rows)}]
    title = "Pressure spike and horseshoe of three Annexe D cases"
    about = __doc__.split("\nRun:")[0]
    return dict(name="ehl_fields", title=title, about=about, blocks=blocks + [{"figure": figure}], metrics=[])


def main(argv=None):
    cli(measure, "ehl_fields")


if __name__ == "__main__":
    main()
