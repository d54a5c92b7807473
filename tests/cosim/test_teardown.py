"""Fresh processes that load the FMUs leave through the normal interpreter teardown with exit code 0: the
`spindle run` command (no os._exit) and a Python host stepping two FMUs on two threads. The loops are
tests/cosim/teardown_loops.py's; 5 processes of each (slow)."""

import pytest

from tests.cosim.teardown_loops import demo_command, exit_codes, two_thread_command


@pytest.mark.parametrize("which", ["spindle_run", "two_threads"])
def test_fresh_processes_exit_0_through_the_normal_teardown(which, closed_loop_fmus, tmp_path):
    command = demo_command(tmp_path) if which == "spindle_run" else two_thread_command()
    codes, first_failure = exit_codes(command, 5)
    assert codes == {0: 5}, (dict(codes), first_failure)
    if which == "spindle_run":  # the run wrote its results: 60 steps + the initial point
        assert len((tmp_path / "closed_loop_spring.csv").read_text().splitlines()) == 1 + 61
