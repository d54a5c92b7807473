"""The one jit policy of every numba kernel in the product.

``@kernel`` is ``numba.njit`` with:
- ``cache=True``: compiled code is kept on disk, so a later process (and a later FMU instance)
  starts without compiling;
- ``fastmath=False``: IEEE semantics, so NaN checks keep working and a kernel agrees with its
  plain-Python twin to rounding.

The on-disk cache lives in ``<base>/numba/<hash of the kernel sources>`` unless NUMBA_CACHE_DIR is
set, with ``<base>`` = $BEARING_FMU_CACHE or ``<user cache>/bearing_fmu``, the directory where the
FMUs keep their stable copy of the bundled packages (bearing_fmu.build). numba checks only the source
file of a cached kernel, not those of the kernels it calls, so an edit to a callee would otherwise be
served stale; with the directory keyed on every kernel source file, any edit starts a fresh cache.
The directory is set here, before any kernel is defined (numba picks a kernel's cache location when
it is decorated). Where that directory cannot be written, the system temporary directory is tried;
if that fails too, numba falls back to its own locations.

Kernels never read module globals that change at run time (numba freezes globals into the cache);
options reach them as integer codes.
"""

import hashlib
import os
import sys
import tempfile
from pathlib import Path

import numba
from numba import njit

JIT_OPTIONS = {"cache": True, "fastmath": False}

_ROOT = Path(__file__).resolve().parent.parent
# every module that defines kernels (the FMU bundles carry the ones they need; absent ones are skipped)
KERNEL_SOURCES = ("bearing_fmu/kernels/*.py", "bearing_fmu_common/*.py", "spindle/thermal/network.py")


def kernel_source_hash(root=_ROOT):
    """SHA-256 (hex) of the kernel source files under root (relative names and bytes)."""
    digest = hashlib.sha256()
    for pattern in KERNEL_SOURCES:
        for path in sorted(root.glob(pattern)):
            digest.update(path.relative_to(root).as_posix().encode())
            digest.update(path.read_bytes())
    return digest.hexdigest()


def cache_base():
    """$BEARING_FMU_CACHE, else bearing_fmu in the per-user cache directory (XDG_CACHE_HOME or ~/.cache;
    ~/Library/Caches on macOS, LOCALAPPDATA on Windows)."""
    if os.environ.get("BEARING_FMU_CACHE"):
        return Path(os.environ["BEARING_FMU_CACHE"])
    if sys.platform == "win32":
        user = Path(os.environ.get("LOCALAPPDATA") or Path.home() / "AppData" / "Local")
    elif sys.platform == "darwin":
        user = Path.home() / "Library" / "Caches"
    else:
        user = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return user / "bearing_fmu"


def _writable_dir(path):
    """path if it can be created and written to, else None."""
    try:
        path.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=path):
            pass
    except OSError:
        return None
    return path


def _set_cache_dir():
    if numba.config.CACHE_DIR:  # NUMBA_CACHE_DIR set by the user: theirs
        return
    key = kernel_source_hash()
    user = os.getuid() if hasattr(os, "getuid") else os.environ.get("USERNAME", "user")
    for base in (cache_base(), Path(tempfile.gettempdir()) / f"bearing_fmu-{user}"):
        path = _writable_dir(base.absolute() / "numba" / key)
        if path is not None:
            numba.config.CACHE_DIR = str(path)
            return


_set_cache_dir()


def kernel(function=None, **overrides):
    """Decorate a kernel with the product's jit policy (``@kernel`` or ``@kernel(inline="always")``)."""
    options = {**JIT_OPTIONS, **overrides}
    if function is None:
        return lambda f: njit(**options)(f)
    return njit(**options)(function)
