"""The plot of a run streamed to a CSV file (`spindle run`'s default): read row by row, reduced, not loaded.

A 360 000-step run's CSV (233 MB) took the plot to a peak of 816 MB (the whole file parsed into Python
floats); the plot now keeps, per plotted column, the smallest and largest value of each of at most
MAX_BUCKETS buckets of consecutive rows (spindle.cosim.plots.read_plot_columns), so its memory does not
depend on the run's length and a spike one row long still shows.
"""

import tracemalloc

import numpy as np
import pytest

from spindle.cosim import master, plots

N_ROWS = 120_000
SPIKE = 77_777  # the row of the torque spike in a file of N_ROWS rows


def _write_csv(path, n_rows=N_ROWS):
    """A result CSV as the master writes it: time, two temperatures, a torque with a one-row spike, an
    unplotted column."""
    t = np.arange(n_rows) * 0.01
    torque = np.full(n_rows, 0.5)
    torque[SPIKE * n_rows // N_ROWS] = 9.0  # one row: must survive the reduction
    with open(path, "w") as fh:
        fh.write('time [s],spindle.T_shaft [K],spindle.T_housing [K],bearing_1.torque [N.m],"bearing_1.K[3,3] [N/m]"\n')
        for k in range(n_rows):
            tk = float(t[k])
            fh.write(f"{tk!r},{300.0 + tk / 100.0!r},293.15,{float(torque[k])!r},1e8\n")
    return t, torque


def test_a_long_csv_is_plotted_from_a_reduced_envelope_in_bounded_memory(tmp_path):
    path = tmp_path / "run.csv"
    t, torque = _write_csv(path)
    tracemalloc.start()
    lines = plots.read_plot_columns(path)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    # the reduced data: 3 columns x (t, y) x at most 2 x MAX_BUCKETS points, as Python floats (32 B each in a
    # list) and as arrays (8 B): about 2 MB at most (1.3 MB measured); loading the file (master.read_csv) peaks
    # at 38 MB. 4 MB bounds the first with room and stays far below the second.
    assert peak < 4e6, peak
    assert set(lines) == {"spindle.T_shaft", "spindle.T_housing", "bearing_1.torque"}  # plotted columns only
    for q, (tq, yq) in lines.items():
        assert len(tq) == len(yq) <= 2 * plots.MAX_BUCKETS, q
        assert np.all(np.diff(tq) > 0.0), q  # time order
    tq, yq = lines["bearing_1.torque"]
    assert yq.max() == 9.0 and tq[np.argmax(yq)] == t[SPIKE]  # the spike, at its time
    ts, ys = lines["spindle.T_shaft"]
    assert ts[0] == 0.0 and ts[-1] == t[-1] and ys[-1] == pytest.approx(300.0 + t[-1] / 100.0)


def test_plot_run_of_a_streamed_run_does_not_load_the_file(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib", reason="matplotlib not installed (optional extra 'plot')")

    def refuse(*args, **kwargs):
        raise AssertionError("the plot loaded the whole CSV")

    path = tmp_path / "run.csv"
    _write_csv(path, 5000)
    monkeypatch.setattr(master, "read_csv", refuse)
    result = master.RunResult(columns={}, units={}, csv_path=str(path))
    assert plots.plot_run(result, tmp_path / "run.png", title="t").is_file()


def test_envelope_keeps_each_buckets_extremes_in_time_order():
    t = np.arange(10.0)
    y = np.array([3.0, 1.0, 2.0, 5.0, 4.0, 0.0, 6.0, 6.0, 2.0, 1.0])
    tt, yy = plots.envelope(t, y, 4)
    assert tt.tolist() == [1.0, 3.0, 5.0, 6.0, 8.0, 9.0]
    assert yy.tolist() == [1.0, 5.0, 0.0, 6.0, 2.0, 1.0]
