"""The FMUs' Python code imports without scipy: a host's Python need only have numpy and numba beside the FMU
(docs/fmu_runtime.md), so the modules an FMU loads must not pull in scipy, e.g. through the numerical EHL solver
that the film table's builder uses. `make test-python-hosts` runs the FMUs in such hosts; this checks the import
chain on every `make test`."""

import subprocess
import sys

CHILD = """
import sys
sys.modules["scipy"] = None  # as in a host without scipy: importing it raises ImportError (numba copes)
import bearing_fmu.fmu  # what an FMU's entry module imports
"""


def test_the_fmu_modules_import_without_scipy():
    proc = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr[-2000:]
