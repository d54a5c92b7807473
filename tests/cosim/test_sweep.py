"""Sweeps on Dask: 16 runs of the spring closed loop (runs/closed_loop_spring.toml
shortened to 60 s), one per coolant temperature, on a local Dask cluster of 2 worker processes give
the same table as the same 16 runs one after the other in this process (spindle.cosim.sweep.sequential).

Why equality is exact: every point runs the same code (spindle.cosim.sweep.run_point) on the same inputs
in a fresh FMU instance; nothing in a run depends on the process it runs in (the FMUs hold no global
state between instances, the numba kernels are deterministic), so each row must be identical, and
sweep() returns rows in input order whatever order the workers finish in. Only `wall_time`, a
measurement, may differ. Dask teardown may print noise on stderr; the table must be complete.
"""

import math

import pytest

pytest.importorskip("dask.distributed", reason="dask[distributed] not installed (optional extra 'sweep')")

from spindle.cosim.sweep import sequential, sweep  # noqa: E402
from tests.conftest import ROOT  # noqa: E402

SPRING = ROOT / "runs" / "closed_loop_spring.toml"
PARAM = "spindle.T_coolant"
VALUES = [285.15 + k for k in range(16)]  # K, 12 C to 27 C coolant
EXTRA = {"run.stop": 60.0}


def test_dask_sweep_equals_sequential_table(closed_loop_fmus):
    rows = sweep(SPRING, PARAM, VALUES, n_workers=2, extra=EXTRA)
    reference = sequential(SPRING, PARAM, VALUES, extra=EXTRA)
    assert len(rows) == len(reference) == 16
    for value, row, ref in zip(VALUES, rows, reference):
        assert row[PARAM] == ref[PARAM] == value
        assert row["status"] == "ok" and row["message"] == "", row
        assert row["t_end"] == 60.0
        assert list(row) == list(ref)  # same columns, same order
        assert math.isfinite(row["wall_time"]) and row["wall_time"] > 0.0
        assert {k: v for k, v in row.items() if k != "wall_time"} == {k: v for k, v in ref.items() if k != "wall_time"}
    # the swept value reached the runs: a warmer coolant gives a warmer housing, point by point
    housing = [row["spindle.T_housing"] for row in rows]
    assert all(a < b for a, b in zip(housing, housing[1:]))


def test_sweep_table_quotes_names_and_messages_with_commas(tmp_path):
    """The sweep table is read back by any CSV reader: a matrix entry name (K[3,3]) and a limit
    message contain commas and must be quoted; floats are written with repr, so they read back
    exactly. (Found on the first CLI sweep: an unquoted K[3,3] header shifted every column.)"""
    import csv

    from spindle.cosim.sweep import write_table

    rows = [
        {
            "bearing_1.F_z": 400.0,
            "status": "limit",
            "message": "t = 3 s: x = 1, left [0, 1]",
            "bearing_1.K[3,3]": 2.5e7 / 3.0,
        },
        {"bearing_1.F_z": 800.0, "status": "ok", "message": "", "bearing_1.K[3,3]": 3.1},
    ]
    path = tmp_path / "table.csv"
    write_table(rows, path)
    back = list(csv.DictReader(open(path, newline="")))
    assert [r["status"] for r in back] == ["limit", "ok"]
    assert back[0]["message"] == rows[0]["message"]
    assert float(back[0]["bearing_1.K[3,3]"]) == rows[0]["bearing_1.K[3,3]"]
    assert float(back[1]["bearing_1.F_z"]) == 800.0
