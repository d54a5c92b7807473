"""bearing_fmu_common.blas_threads: one BLAS thread during the block, the count before it restored after it (also
after an error), and blocks that overlap in two threads keep one thread until the last ends, then restore the
count before the first. Read back through OpenBLAS's setter, which returns the count it replaces. Skipped where
numpy does not carry an OpenBLAS with that setter."""

import threading

import pytest

from bearing_fmu_common import blas_threads
from bearing_fmu_common.blas_threads import single_blas_thread

pytestmark = pytest.mark.skipif(blas_threads._SETTER is None, reason="numpy's BLAS has no thread-local setter")


def current():
    """OpenBLAS's thread count now."""
    previous = blas_threads._SETTER(1)
    blas_threads._SETTER(previous)
    return previous


@pytest.fixture
def three_threads():
    before = blas_threads._SETTER(3)
    yield
    blas_threads._SETTER(before)


def test_one_thread_inside_and_the_count_restored_after(three_threads):
    with single_blas_thread():
        assert current() == 1
    assert current() == 3
    with pytest.raises(RuntimeError), single_blas_thread():
        raise RuntimeError("an error inside the block")
    assert current() == 3


def test_overlapping_blocks_in_two_threads_restore_the_first_count(three_threads):
    entered, leave = threading.Event(), threading.Event()

    def other_block():
        with single_blas_thread():
            entered.set()
            leave.wait(10)

    other = threading.Thread(target=other_block)
    with single_blas_thread():
        other.start()
        assert entered.wait(10)
    assert current() == 1  # the other thread's block still runs
    leave.set()
    other.join()
    assert current() == 3
