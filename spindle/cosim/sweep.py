"""Sweeps (docs/architecture.md): many runs of one run file with one value changed, on Dask.

Each point is a full co-simulation in a Dask worker (its own process: pythonfmu FMUs run Python in
the host process, so workers use processes, one thread each). Local cluster by default; pass the
address of a running scheduler to use a cluster. Results are gathered into one table: the swept
value, the status and message, the wall time and the final value of every recorded variable.
Dask is the optional extra `sweep`; without it `sweep()` raises DaskMissing, and `sequential()` gives
the same table in this process (what `spindle sweep` then does).
"""

import csv
import math

from .master import run
from .runfile import load_run


class DaskMissing(ImportError):
    """dask.distributed is not installed (the optional extra `sweep`)."""


def run_point(runfile, overrides, fmu_dir=None):
    """One run; returns a summary row (dict). Never raises: a failed run is a row with its message.
    fmu_dir: folder of the FMUs the run file names (None: the paths in the run file)."""
    row = {"status": "error", "message": "", "wall_time": math.nan}
    try:
        result = run(load_run(runfile, overrides, fmu_dir=fmu_dir))
    except Exception as exc:  # a failed point must not lose the others
        row["message"] = f"{type(exc).__name__}: {exc}"
        return row
    row.update(
        status=result.status,
        message=result.message,
        wall_time=result.wall_time,
        t_end=float(result.columns["time"][-1]),
    )
    for name, values in result.columns.items():
        if name != "time":
            row[name] = float(values[-1])
    return row


def sweep(runfile, param, values, scheduler=None, n_workers=2, extra=None, fmu_dir=None):
    """Run `runfile` once per value of `param` (a dotted override key) on Dask; rows in input order.

    scheduler: None = a LocalCluster with n_workers processes (closed afterwards), or the address
    of an existing scheduler ("tcp://host:8786"). fmu_dir: folder of the FMUs (None: the run file's
    paths). Raises DaskMissing if dask.distributed is not installed."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError as exc:
        raise DaskMissing(f"sweeps on Dask need dask[distributed] ({exc}): pip install 'bearing-fmu[sweep]'") from None

    points = [{**(extra or {}), param: v} for v in values]
    cluster = None
    if scheduler is None:
        cluster = LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
    else:
        client = Client(scheduler)
    try:
        n = len(points)
        futures = client.map(run_point, [str(runfile)] * n, points, [fmu_dir] * n, pure=False)
        rows = client.gather(futures)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    return [{param: v, **row} for v, row in zip(values, rows)]


def sequential(runfile, param, values, extra=None, fmu_dir=None):
    """The same table computed in this process, one run after the other (the check of sweep(), and the
    sweep without Dask)."""
    return [{param: v, **run_point(str(runfile), {**(extra or {}), param: v}, fmu_dir)} for v in values]


def write_table(rows, path):
    """CSV of the rows (csv module: names such as K[3,3] and messages are quoted); floats as repr."""
    names = []
    for row in rows:
        names += [k for k in row if k not in names]
    with open(path, "w", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(names)
        for row in rows:
            writer.writerow([_cell(row.get(k, "")) for k in names])


def _cell(value):
    return repr(value) if isinstance(value, float) else value
