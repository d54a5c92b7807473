"""Exit codes of fresh processes that load the FMUs and leave through the interpreter's normal teardown.

Two loops, each of N fresh processes (default 100):
- `spindle run` of the closed-loop demo (runs/closed_loop_spring.toml, shortened to 60 s = 60 steps,
  no plot): the command line, which leaves through sys.exit (no os._exit);
- a Python host stepping Bearing.fmu and SpindleThermal.fmu at the same time from two threads
  (fmpy's simulate_fmu in each thread, 200 steps each), then returning normally.
A teardown abort shows as a non-zero exit code (134 for "corrupted double-linked list").
"""

import collections
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
FMUS = ROOT / "fmus"
DEMO = ROOT / "runs" / "closed_loop_spring.toml"

TWO_THREAD_HOST = """
import sys, threading
from fmpy import read_model_description, simulate_fmu

fmus = sys.argv[1:]
results, errors = {}, []
# validated here, one after the other: fmpy's schema validation (lxml) fails now and then when two
# threads parse the schema at once ("Document is not valid XML Schema"), a host problem
for path in fmus:
    read_model_description(path, validate=True)

def simulate(path):
    try:
        results[path] = simulate_fmu(path, validate=False, stop_time=2.0, step_size=0.01, output_interval=0.01)
    except BaseException as exc:  # reported below: the process must exit non-zero
        errors.append(f"{path}: {exc!r}")

threads = [threading.Thread(target=simulate, args=(p,)) for p in fmus]
for t in threads:
    t.start()
for t in threads:
    t.join()
if errors or any(len(r) != 201 for r in results.values()):
    sys.exit("; ".join(errors) or "wrong number of rows")
"""


def demo_command(out_dir):
    """`spindle run` of the demo, 60 s (60 steps of 1 s), CSV only."""
    return [
        sys.executable,
        "-m",
        "spindle.cli",
        "run",
        str(DEMO),
        "--set",
        "run.stop=60",
        "--no-plot",
        "--out",
        str(out_dir),
        "--fmus",
        str(FMUS),
    ]


def two_thread_command():
    """A Python host stepping Bearing.fmu and SpindleThermal.fmu on two threads at once."""
    return [sys.executable, "-c", TWO_THREAD_HOST, str(FMUS / "Bearing.fmu"), str(FMUS / "SpindleThermal.fmu")]


def failure_text(proc):
    """What a failing process said: the end of its stderr (the host's own error) and the first FMU error
    message (fmpy prints the FMU's log to stdout; the layer puts the Python exception before its traceback)."""
    k = proc.stdout.find("[ERROR]")
    fmu_log = proc.stdout[k : k + 3000] if k >= 0 else proc.stdout[-1000:]
    return f"exit code {proc.returncode}\nstderr: {proc.stderr[-1500:]}\nFMU log: {fmu_log}"


def exit_codes(command, n):
    """Exit codes of n fresh processes of `command` (run one after the other) and what the first failing
    one said (failure_text)."""
    codes, first_failure = collections.Counter(), ""
    for _ in range(n):
        proc = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
        codes[proc.returncode] += 1
        if proc.returncode != 0 and not first_failure:
            first_failure = failure_text(proc)
    return codes, first_failure
