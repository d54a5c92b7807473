"""pytest plugin: markers assigned from a test's folder, so a selection never depends on memory.

    tests/fmu/         -> fmu         (builds and drives the FMUs through fmpy)
    tests/cosim/       -> cosim       (co-simulation masters, closed loops, sweeps)
    tests/validation/  -> validation  (literature and standard cases)
    tests/stability/   -> stability   (stiff and extreme cases)

`slow` is set by hand on tests that take more than a few seconds each. The quick loop while
editing kernels and models is `pytest -m "not slow and not fmu and not cosim"`; `make test` runs
everything.
"""

from pathlib import Path

FOLDER_MARKERS = {"fmu": "fmu", "cosim": "cosim", "validation": "validation", "stability": "stability"}


def pytest_collection_modifyitems(config, items):
    import pytest

    for item in items:
        folder = Path(str(item.fspath)).parent.name
        marker = FOLDER_MARKERS.get(folder)
        if marker:
            item.add_marker(getattr(pytest.mark, marker))
