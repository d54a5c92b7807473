"""Fresh processes for the tests that must not share this interpreter's state (imports, caches, umask)."""

import json
import os
import subprocess


def run_checked(args, env, cwd=None, umask=None, timeout=None):
    """The finished process of args (text output captured) with the environment env, in cwd, under umask if
    given; it must exit 0 (the end of its stderr shown if not)."""
    proc = subprocess.run(
        [str(a) for a in args],
        env=env,
        cwd=cwd,
        capture_output=True,
        text=True,
        check=False,
        timeout=timeout,
        preexec_fn=(lambda: os.umask(umask)) if umask is not None else None,
    )
    assert proc.returncode == 0, f"{args[0]}: exit {proc.returncode}\n{proc.stderr[-3000:]}"
    return proc


def run_in_host(python, args, cache, timeout):
    """(the JSON of its stdout's line 'RESULT ...', its stdout) of `python args` in a fresh process that sees
    nothing of the source tree (no PYTHONPATH, run from /tmp), with the user cache `cache`."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "NUMBA_CACHE_DIR")}
    env["BEARING_FMU_CACHE"] = str(cache)
    proc = run_checked([python, *args], env, cwd="/tmp", timeout=timeout)
    line = next(x for x in proc.stdout.splitlines() if x.startswith("RESULT "))
    return json.loads(line[len("RESULT ") :]), proc.stdout
