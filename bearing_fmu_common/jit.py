"""The one jit policy of every numba kernel in the product.

``@kernel`` is ``numba.njit`` with:
- an on-disk cache (below), so a later process (and a later FMU instance) starts without compiling;
- ``fastmath=False``: IEEE semantics, so NaN checks keep working and a kernel agrees with its
  plain-Python twin to rounding.

Cache (docs/fmu_runtime.md, "Compiled code"): a kernel is looked up, in order,
1. in the user cache ``<base>/numba/<hash of the kernel sources>``, ``<base>`` = $BEARING_FMU_CACHE or
   ``<user cache>/bearing_fmu`` ($NUMBA_CACHE_DIR, if set, replaces ``<base>/numba``), also when that
   directory is read-only (a cache filled by an administrator);
2. in the compiled-code directories registered with ``add_compiled_dir`` (an FMU's portable code,
   built for the ``generic`` CPU of its platform at FMU build time);
and compiled on a miss, into the user cache, or, where that cannot be written (read-only, another
user's, no home), into a private per-user temporary directory, with a logged warning.

Entries are filed under the kernel's path relative to the root of its source tree (the directory its
top-level package is in) and stamped with a hash of its source file's contents, so a cache serves any
copy of the sources wherever it is unpacked and whatever its file times. Each source tree has its own
tiers, keyed on its own kernel sources: a host process may run kernels from several trees at once (the
co-simulation master's own `spindle.thermal` beside the bearing FMU's bundled `bearing_fmu`, two FMUs of
which the first brought this module), and each kernel is looked up under the key of the tree it was
imported from, with every registered compiled-code directory (``same_sources_entries``).

numba checks only the source file of a cached kernel, not those of the kernels it calls, so an edit
to a callee would otherwise be served stale; with the directory keyed on every kernel source file, any
edit starts a fresh cache. The cache is attached to each kernel when it is decorated; numba's global
cache settings are left alone (other numba code in a host process is not affected).

Kernels never read module globals that change at run time (numba freezes globals into the cache);
options reach them as integer codes.
"""

import hashlib
import json
import logging
import os
import stat
import sys
import tempfile
from pathlib import Path

from numba import njit
from numba.core import caching

logger = logging.getLogger(__name__)

JIT_OPTIONS = {"cache": True, "fastmath": False}

_ROOT = Path(__file__).resolve().parent.parent
# every module that defines kernels (the FMU bundles carry the ones they need; absent ones are skipped)
KERNEL_SOURCES = (
    "bearing_fmu/kernels/**/*.py",
    "bearing_fmu_common/*.py",
    "spindle/thermal/network.py",
    "spindle/shaft/beam.py",
)
PORTABLE_CPU = "generic"  # the CPU name of the compiled code shipped in the FMUs
TARGET_FILE = "target.json"  # in a compiled-code directory: numba's codegen description it was built with


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
    ~/Library/Caches on macOS, LOCALAPPDATA on Windows). OSError if there is no home directory."""
    if os.environ.get("BEARING_FMU_CACHE"):
        return Path(os.environ["BEARING_FMU_CACHE"])
    try:
        Path.home()
    except RuntimeError as error:  # no HOME and no password entry
        raise FileNotFoundError(f"no home directory ({error})") from None
    if sys.platform == "win32":
        user = Path(os.environ.get("LOCALAPPDATA") or Path.home() / "AppData" / "Local")
    elif sys.platform == "darwin":
        user = Path.home() / "Library" / "Caches"
    else:
        user = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return user / "bearing_fmu"


def user_cache_dir(key=None):
    """The user cache of the kernels of this source tree (see the module text)."""
    key = key or kernel_source_hash()
    if os.environ.get("NUMBA_CACHE_DIR"):
        return Path(os.environ["NUMBA_CACHE_DIR"]).absolute() / f"bearing_fmu-{key}"
    return cache_base().absolute() / "numba" / key


def writable_dir(path):
    """path if it can be created (mode 0777 less the umask: a shared base stays shared) and written to,
    else None and the reason."""
    try:
        path.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=path):
            pass
    except OSError as error:
        return None, error
    return path, None


def private_temp_dir(key):
    """A per-user directory under the system temporary directory, created 0700 and used only if this user
    owns it and nobody else can write to it (another user's files there could run code when unpickled)."""
    user = os.getuid() if hasattr(os, "getuid") else os.environ.get("USERNAME", "user")
    path = Path(tempfile.gettempdir()) / f"bearing_fmu-{user}" / "numba" / key
    try:
        path.mkdir(mode=0o700, parents=True, exist_ok=True)
        for part in (path.parent.parent, path.parent, path):
            info = part.lstat()
            if hasattr(os, "getuid") and (info.st_uid != os.getuid() or info.st_mode & (stat.S_IWGRP | stat.S_IWOTH)):
                raise PermissionError(f"{part} is not this user's private directory")
        with tempfile.TemporaryFile(dir=path):
            pass
        return path
    except OSError:
        return Path(tempfile.mkdtemp(prefix=f"bearing_fmu-numba-{key[:12]}-"))


class CacheTiers:
    """Where the kernels of one source tree (root) are looked up (read: [(directory, codegen description or
    None for this host's)]) and where new compilations are saved (write)."""

    def __init__(self, key=None, root=_ROOT):
        self.root = Path(root)
        self.key = key or kernel_source_hash(self.root)
        try:
            user = user_cache_dir(self.key)
        except OSError as error:
            user, self.write, self.read, failure = None, None, [], error
        else:
            self.write, failure = writable_dir(user)
            self.read = [(user, None)]
        if self.write is None:
            filled = user is not None and user.is_dir()
            self.write = private_temp_dir(self.key)
            self.read.append((self.write, None))
            logger.warning(
                "bearing_fmu: numba cache %s cannot be written (%s); kernels compiled here are kept in %s%s",
                user or "in the home directory",
                failure,
                self.write,
                " (its existing entries are still used)" if filled else "",
            )

    def add_compiled_dir(self, path):
        """Use the compiled code under path (as bearing_fmu.compiled_code writes it: target.json and
        <kernel source hash>/...) if it was built for this platform and these sources."""
        path = Path(path)
        try:
            magic = tuple(json.loads((path / TARGET_FILE).read_text())["magic"])
        except (OSError, ValueError, KeyError):
            return False
        entries = path / self.key
        if not entries.is_dir():
            entries = same_sources_entries(path, self.root)
        if entries is None or any(entries == d for d, _ in self.read):
            return False
        self.read.append((entries, magic))
        return True


def same_sources_entries(path, root=_ROOT):
    """The entries of a compiled-code directory built from another set of the kernel sources, if every kernel
    source it was built from is, byte for byte, the file of the same name under root; else None.

    The case: a host that imported the product itself (the co-simulation master) loads an FMU; the FMU's
    entry script then runs on the host's modules, whose key covers every kernel source of the product, while
    the FMU's code was compiled under the key of the sources it bundles (path.parent: the FMU's resources).
    Equal bundled sources mean equal kernels and callees, so the FMU's entries are valid for the host."""
    bundle = path.parent
    try:
        entries = path / kernel_source_hash(bundle)
    except OSError:  # the bundle went away: another FMU's extraction, removed by its host while this one set up
        return None
    if not entries.is_dir():
        return None
    for pattern in KERNEL_SOURCES:
        for source in bundle.glob(pattern):
            own = root / source.relative_to(bundle)
            try:
                if own.read_bytes() != source.read_bytes():
                    return None
            except OSError:
                return None
    return entries


TIERS = CacheTiers()  # the tiers of this module's own source tree
_TIERS = {_ROOT: TIERS}  # source root -> its tiers
_COMPILED = []  # every compiled-code directory registered, offered to the tiers of trees met later


def source_root(py_file):
    """The root of a kernel's source tree: the directory holding its top-level package (the first parent
    without __init__.py)."""
    directory = Path(py_file).resolve().parent
    while (directory / "__init__.py").is_file():
        directory = directory.parent
    return directory


def tiers_for(py_file):
    """The tiers of the source tree of py_file, made (with every compiled-code directory registered so far)
    when a kernel of that tree is first met."""
    root = source_root(py_file)
    tiers = _TIERS.get(root)
    if tiers is None:
        tiers = _TIERS[root] = CacheTiers(kernel_source_hash(root), root)
        for path in _COMPILED:
            tiers.add_compiled_dir(path)
    return tiers


def add_compiled_dir(path):
    """Register a directory of compiled code shipped with an FMU (looked up after the user cache) with the
    tiers of every source tree; True if one of them can use it."""
    _COMPILED.append(Path(path))
    return any([tiers.add_compiled_dir(path) for tiers in _TIERS.values()])


def codegen_description(codegen=None):
    """numba's description of the code a codegen emits (target triple, CPU name, CPU features), the part
    of a cache key that says for which machines an entry is valid."""
    if codegen is None:
        from numba.core.registry import cpu_target

        codegen = cpu_target.target_context.codegen()
    return tuple(codegen.magic_tuple())


def kernel_subpath(py_file):
    """Directory of a kernel's entries relative to a cache directory: its source's package path (the same
    for every copy of the sources), or numba's hashed name for a file outside any package."""
    path = Path(py_file).resolve()
    if not (path.parent / "__init__.py").is_file():
        return caching._CacheLocator.get_suitable_cache_subpath(str(path))
    return path.parent.relative_to(source_root(path)).as_posix()


class _Locator(caching._CacheLocator):
    """A kernel's entries in one cache directory, stamped with the hash of its source file's contents."""

    def __init__(self, py_func, py_file, directory):
        self._py_file = py_file
        self._lineno = py_func.__code__.co_firstlineno
        self._cache_path = str(Path(directory) / kernel_subpath(py_file))

    def get_cache_path(self):
        return self._cache_path

    def get_source_stamp(self):
        return hashlib.sha256(Path(self._py_file).read_bytes()).hexdigest()

    def get_disambiguator(self):
        return str(self._lineno)

    @classmethod
    def from_function(cls, py_func, py_file):
        return cls(py_func, py_file, tiers_for(py_file).write)


class _CacheImpl(caching.CompileResultCacheImpl):
    _locator_classes = [_Locator]


class KernelCache(caching.FunctionCache):
    """numba's function cache over the tiers of TIERS: looked up in each read directory in turn (entries
    of compiled-code directories under the codegen description they were built with), saved to the
    write directory."""

    _impl_class = _CacheImpl

    def _index_files(self):
        base, stamp = self._impl.filename_base, self._impl.locator.get_source_stamp()
        py_file = self._impl.locator._py_file
        for directory, magic in tiers_for(py_file).read:
            path = Path(directory) / kernel_subpath(py_file)
            yield caching.IndexDataCacheFile(cache_path=str(path), filename_base=base, source_stamp=stamp), magic

    def _load_overload(self, sig, target_context):
        if not self._enabled:
            return None
        sig_key, host_magic, code_key = self._index_key(sig, target_context.codegen())
        for cache_file, magic in self._index_files():
            if magic is not None and magic[0] != host_magic[0]:  # another platform's code
                continue
            try:
                data = cache_file.load((sig_key, magic or host_magic, code_key))
            except OSError:  # an unreadable directory: a miss
                continue
            if data is not None:
                return self._impl.rebuild(target_context, data)
        return None

    def _save_overload(self, sig, data):
        try:
            super()._save_overload(sig, data)
        except OSError as error:  # the directory went away or became read-only: compiled, not kept
            where = self._impl.locator.get_cache_path()
            logger.warning("bearing_fmu: cannot save a compiled kernel to %s (%s)", where, error)


def kernel(function=None, **overrides):
    """Decorate a kernel with the product's jit policy (``@kernel`` or ``@kernel(inline="always")``)."""
    options = {**JIT_OPTIONS, **overrides}
    cache = options.pop("cache")

    def decorate(f):
        dispatcher = njit(**options)(f)
        # with NUMBA_DISABLE_JIT=1 (debugging) njit returns the plain function: nothing to cache
        if cache and hasattr(dispatcher, "py_func"):
            dispatcher._cache = KernelCache(dispatcher.py_func)
        return dispatcher

    return decorate if function is None else decorate(function)
