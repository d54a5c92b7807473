"""Virtual environments of the supported Pythons (3.10-3.13) with only numpy, numba and fmpy.

The FMU build uses them to compile each FMU's kernels once per Python version (numba's cache entries
are per Python version: bearing_fmu.compiled_code), and the `python_hosts` tests run the FMUs in them as
fmpy hosts. A base interpreter of each version is found as `python3.X` on PATH or under pyenv's
versions directory; each environment is made with `python -m venv` and pip once and kept under the
system temporary directory (a marker file says it is complete), with numba and fmpy at the versions of
the running interpreter (so every version's compiled code is built by the same numba) and the newest
numpy not newer than the running one that supports that Python.

    python -m bearing_fmu_common.runtime.host_pythons [--others] [3.X ...]   # their pythons, one a line
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

SUPPORTED = ((3, 10), (3, 11), (3, 12), (3, 13))  # the Python versions the FMUs are built and tested for
PACKAGES = ("numpy", "numba", "fmpy")


class HostPythonError(RuntimeError):
    """A host environment cannot be made (no base interpreter of that version, pip failed)."""


def _version_of(python):
    """(major, minor) of an interpreter, or None if it does not run."""
    try:
        out = subprocess.run(
            [str(python), "-c", "import sys; print(*sys.version_info[:2])"], capture_output=True, text=True, timeout=60
        )
    except OSError:
        return None
    parts = out.stdout.split()
    return (int(parts[0]), int(parts[1])) if out.returncode == 0 and len(parts) == 2 else None


def _pyenv_versions():
    root = os.environ.get("PYENV_ROOT") or os.path.expanduser("~/.pyenv")
    return sorted(Path(root, "versions").glob("3.*/bin/python3"), reverse=True)


def base_python(wanted):
    """A base interpreter of Python `wanted` ((3, X)): python3.X on PATH, else the newest pyenv version.
    Its own base if it is a virtual environment (a venv is made from the base)."""
    candidates = [shutil.which(f"python{wanted[0]}.{wanted[1]}")]
    pattern = rf"{wanted[0]}\.{wanted[1]}\.\d+"
    candidates += [p for p in _pyenv_versions() if re.fullmatch(pattern, p.parent.parent.name)]
    for candidate in candidates:
        if candidate and _version_of(candidate) == wanted:
            out = subprocess.run(
                [str(candidate), "-c", "import sys; print(getattr(sys, '_base_executable', sys.executable))"],
                capture_output=True,
                text=True,
            )
            return Path(out.stdout.strip() or candidate)
    return None


def pins():
    """pip requirements: numba and fmpy as in this interpreter, numpy at most this one's (older Pythons
    have no wheel of the newest numpy)."""
    out = []
    for name in PACKAGES:
        try:
            installed = version(name)
        except PackageNotFoundError:
            out.append(name)
            continue
        out.append(f"{name}<={installed}" if name == "numpy" else f"{name}=={installed}")
    return out


def host_python(wanted, root=None):
    """python of the environment of Python `wanted`, made (pip, a few minutes) if it is not complete."""
    requirements = pins()
    tag = "-".join(re.sub(r"[<=>]+", "", p) for p in requirements)
    home = Path(root or tempfile.gettempdir()) / f"bearing_fmu-host-py{wanted[0]}.{wanted[1]}-{tag}"
    python = home / "bin" / "python"
    if (home / ".complete").is_file():
        return python
    base = base_python(wanted)
    if base is None:
        raise HostPythonError(f"no Python {wanted[0]}.{wanted[1]} found (python{wanted[0]}.{wanted[1]} on PATH, pyenv)")
    made = subprocess.run([str(base), "-m", "venv", "--clear", str(home)], capture_output=True, text=True)
    if made.returncode != 0:
        raise HostPythonError(f"{base} -m venv {home} failed: {made.stderr[-1000:]}")
    pip = subprocess.run(
        [str(python), "-m", "pip", "install", "-q", *requirements], capture_output=True, text=True, timeout=1800
    )
    if pip.returncode != 0:
        raise HostPythonError(f"pip install {' '.join(requirements)} for Python {base} failed: {pip.stderr[-1000:]}")
    (home / ".complete").write_text(" ".join(requirements) + "\n")
    return python


def main(argv=None):
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("versions", nargs="*", help="3.X (default: every supported version)")
    parser.add_argument("--others", action="store_true", help="leave out this interpreter's version")
    args = parser.parse_args(argv)
    wanted = [tuple(int(x) for x in v.split(".")) for v in args.versions] or list(SUPPORTED)
    if args.others:
        wanted = [w for w in wanted if w != sys.version_info[:2]]
    failed = False
    for w in wanted:
        try:
            print(host_python(w))
        except HostPythonError as error:
            print(f"host_pythons: {error}", file=sys.stderr)
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
