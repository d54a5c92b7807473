"""Tell the host when an FMU compiles its kernels, and how long that took.

An FMU carries its kernels compiled for each Python version of its build, by one numba version
(resources/numba_portable/target.json, ``builds``: {"3.11": "0.68.1", ...}; bearing_fmu.compiled_code).
numba's cache entries serve only the Python and numba versions that wrote them, so a host with another
combination compiles every kernel the FMU calls at first use (about 30 s of CPU time for Bearing.fmu), then
keeps them in its user cache. That is logged as a warning when the slave is made (so a long first step is
not taken for a hang) and, after the call that compiled, the time it took. Nothing is logged when the FMU's
compiled code applies, or when the user cache already holds this FMU's kernels for this Python (a later
start).
"""

import json
import re
import sys
import time
from pathlib import Path

from numba.core import event
from pythonfmu.enums import Fmi2Status

from .jit import TARGET_FILE, user_cache_dir

_ENTRY_TAG = re.compile(r"\.py\d+\.nbi$")  # numba's index files carry the Python version: <name>.py311.nbi


class _CompileClock(event.Listener):
    """Wall time spent in numba's outermost compilations since the last report."""

    def __init__(self):
        self.depth, self.started, self.seconds = 0, 0.0, 0.0

    def on_start(self, ev):
        if self.depth == 0:
            self.started = time.perf_counter()
        self.depth += 1

    def on_end(self, ev):
        self.depth -= 1
        if self.depth == 0:
            self.seconds += time.perf_counter() - self.started


_clock = None  # made when a note is due: no listener otherwise
_where = None  # the user cache the compiled kernels go to


def note(compiled_dir):
    """The warning for a host whose Python and numba the FMU's compiled code does not serve, or None."""
    import numba

    compiled_dir = Path(compiled_dir)
    if not compiled_dir.is_dir():  # the build importing the entry script before the code is added
        return None
    try:
        builds = json.loads((compiled_dir / TARGET_FILE).read_text()).get("builds", {})
    except (OSError, ValueError):
        builds = {}
    here = f"{sys.version_info[0]}.{sys.version_info[1]}"
    if builds.get(here) == numba.__version__:
        return None
    tag = f".py{sys.version_info[0]}{sys.version_info[1]}.nbi"
    wanted, where = set(), None
    for key_dir in (d for d in compiled_dir.iterdir() if d.is_dir()):
        names = {_ENTRY_TAG.sub(tag, p.relative_to(key_dir).as_posix()) for p in key_dir.rglob("*.nbi")}
        try:
            where = user_cache_dir(key_dir.name)
        except OSError:  # no home directory: the kernels are compiled into a temporary directory
            break
        wanted |= {name for name in names if not (where / name).is_file()}
    if where is not None and not wanted:
        return None  # compiled at an earlier start
    carried = ", ".join(f"Python {v} with numba {n}" for v, n in sorted(builds.items())) or "no Python"
    global _clock, _where
    if _clock is None:
        _clock, _where = _CompileClock(), where
        event.register("numba:compile", _clock)
    return (
        f"this FMU carries its kernels compiled for {carried}; this host runs Python {here} with numba "
        f"{numba.__version__}, so the first steps compile them (tens of seconds of CPU time for the quasi-static "
        f"and DEM FMUs, a few for the others) and keep them in {where or 'a temporary directory'} for later starts"
    )


def report(slave):
    """Log, through the slave, how long numba compiled since the last report (if a note was due)."""
    if _clock is not None and _clock.depth == 0 and _clock.seconds > 0.0:
        seconds, _clock.seconds = _clock.seconds, 0.0
        slave.log(
            f"{slave.instance_name}: compiled kernels for {seconds:.1f} s (wall time) in this call; kept in "
            f"{_where or 'a temporary directory'}",
            Fmi2Status.warning,
        )
