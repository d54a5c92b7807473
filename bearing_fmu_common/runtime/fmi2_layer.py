"""The Python side of the FMUs' FMI layer (fmi2_python.c, docs/fmu_runtime.md).

The build puts this file into every FMU as resources/fmi2_layer.py (bearing_fmu_common.runtime.binaries); the
layer loads it from there at its first fmi2Instantiate, by file location, as a module of its own that is not
registered in sys.modules: each FMU's copy of the layer has its own copy of this module, and loading it adds
nothing to sys.path. Standard library only: it runs before the FMU's packages can be imported (the FMU state's
serialisation imports numpy when it is called, once the slave runs and numpy is loaded).
"""

import hashlib
import importlib
import inspect
import json
import os
import struct
import sys
import threading
import traceback
import types
import weakref

# One set-up lock for every FMU of the product in the process. Each FMU brings its own copy of the layer and
# so its own copy of this module: the lock lives in a module registered once in sys.modules. Two FMUs set up
# by two threads at once (imports, numba loading kernels and filling its registries) are not safe: one of
# them can fail to instantiate.
_SHARED = "_bearing_fmu_runtime_shared"
_shared = sys.modules.setdefault(_SHARED, types.ModuleType(_SHARED))
_setup_lock = _shared.__dict__.setdefault("setup_lock", threading.RLock())


class Refused(ImportError):
    """An FMU that cannot run as it is in this process; the message says why (logged without a traceback)."""


def begin_setup():
    _setup_lock.acquire()


def end_setup():
    _setup_lock.release()


def slave_class(resources):
    """The Fmi2Slave subclass of the module named in resources/slavemodule.txt (the one with the longest class
    hierarchy). resources/ is put on sys.path only if that module is not imported yet: later instances, from
    any extraction of the FMU, reuse it. Refused if the process has already imported that module or a package
    the FMU carries with other contents (foreign_code)."""
    with open(os.path.join(resources, "slavemodule.txt"), encoding="utf-8") as fh:
        name = fh.readline().strip()
    why = foreign_code(resources, name)
    if why is not None:
        raise Refused(why)
    if name not in sys.modules and resources not in sys.path:
        sys.path.insert(0, resources)
    module = importlib.import_module(name)
    remember_code(resources, name)
    found = [
        c
        for c in vars(module).values()
        if inspect.isclass(c) and not inspect.isabstract(c) and any(k.__name__ == "Fmi2Slave" for k in c.__mro__)
    ]
    if not found:
        raise ImportError(f"no Fmi2Slave subclass in module {name} ({module.__file__})")
    return max(found, key=lambda c: len(c.__mro__))


def describe(kind, value, tb):
    """An exception and its traceback as one text, the exception first: a host that shows only the start of
    a long message still shows the cause. An exception raised by the layer's own C code has no traceback, and a
    refusal (Refused) says all there is to say: their text alone."""
    head = "".join(traceback.format_exception_only(kind, value)).rstrip()
    if tb is None or isinstance(value, Refused):
        return head
    return head + "\n" + "".join(traceback.format_exception(kind, value, tb)).rstrip()


def variable_name(slave, vr):
    """The name of the slave's variable of value reference vr, with the reference, for a message."""
    var = slave.vars.get(vr)
    return f"value reference {vr}" if var is None else f"{var.name} (value reference {vr})"


# -- an FMU runs its own code --------------------------------------------------------------------------------
# Python has one module per name in a process: an FMU whose packages (bearing_fmu, bearing_fmu_common, spindle)
# the process has already imported from elsewhere — the host's own checkout or installation, another release's
# FMU — would run that code, not the code it carries. It is refused unless that code is the same as the FMU's.
OWN_PACKAGES = "own_packages.txt"  # resources/ file the build writes (runtime/binaries.py: OWN_PACKAGES)
_SKIPPED = ("__pycache__",)
_CACHE_SUFFIXES = (".pyc", ".nbi", ".nbc")  # written by Python and numba beside the sources, never carried
# What the process imported, by content, for every copy of the layer: package name -> (directory, {relative path:
# SHA-256}) and entry module name -> SHA-256 of its file. Recorded when imported: an extraction an FMU ran from
# may be removed by its host afterwards (fmpy's simulate_fmu does), and another copy compares against this.
_imported = _shared.__dict__.setdefault("imported_packages", {})
_entries = _shared.__dict__.setdefault("imported_entries", {})


def _file_digest(path):
    with open(path, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


def _digests(directory):
    """{relative path: SHA-256} of the files under `directory`, without Python's and numba's caches."""
    out = {}
    for root, dirs, files in os.walk(directory):
        dirs[:] = sorted(d for d in dirs if d not in _SKIPPED)
        for name in sorted(files):
            if not name.endswith(_CACHE_SUFFIXES):
                path = os.path.join(root, name)
                out[os.path.relpath(path, directory)] = _file_digest(path)
    return out


def _loaded(name):
    """(directory, {relative path: SHA-256}) of the package `name` as the process imported it; None: not
    imported; (None, None): not from one directory (a namespace package)."""
    module = sys.modules.get(name)
    if module is None:
        return None
    path = getattr(module, "__file__", None)
    directory = os.path.dirname(os.path.realpath(path)) if path else None
    record = _imported.get(name)
    if directory is not None and (record is None or record[0] != directory):
        record = _imported[name] = (directory, _digests(directory))
    return record if directory is not None else (None, None)


def _own_packages(resources):
    """The packages of the product the FMU carries (resources/own_packages.txt, one name a line, written by the
    build; none for an FMU without it). Not pythonfmu, which it carries for hosts that lack it: a host that
    imported its own runs the FMU on it, as it runs any pythonfmu FMU."""
    try:
        with open(os.path.join(resources, OWN_PACKAGES), encoding="utf-8") as fh:
            return [line.strip() for line in fh if line.strip()]
    except FileNotFoundError:
        return []


def _package_problem(name, carried, loaded):
    """Why the package `name` imported as `loaded` (_loaded) is not the one the FMU carries in `carried`: a file
    of another content, or a Python source it lacks. A data file it lacks is not counted: a package run from a
    checkout can read it from elsewhere (the thermal model reads the bearing catalogue from bearing_fmu/params,
    which the thermal FMU carries as spindle/thermal/bearings)."""
    directory, theirs = loaded
    if directory is None:
        return f"package {name} not from one directory (this FMU's is {carried})"
    if directory == carried:
        return None
    differ = [
        rel
        for rel, digest in _digests(carried).items()
        if theirs.get(rel) != digest and (rel in theirs or rel.endswith(".py"))
    ]
    if not differ:
        return None
    return (
        f"package {name} from {directory} ({len(differ)} of its files differ from this FMU's {carried}, "
        f"e.g. {differ[0]})"
    )


def foreign_code(resources, entry):
    """Why this FMU (its resources/ directory and entry module name) would not run its own code in this process:
    its entry module or a package it carries already imported with another content; None if it runs its own."""
    problems = []
    own = os.path.join(resources, entry + ".py")
    module = sys.modules.get(entry)
    if module is not None:
        path = getattr(module, "__file__", None)
        theirs = _entries.get(entry) or (_file_digest(path) if path and os.path.isfile(path) else None)
        if theirs != _file_digest(own):
            problems.append(f"its module {entry} from {path} (this FMU's is {own})")
    for name in _own_packages(resources):
        loaded = _loaded(name)
        problem = loaded and _package_problem(name, os.path.realpath(os.path.join(resources, name)), loaded)
        if problem:
            problems.append(problem)
    if not problems:
        return None
    return (
        "this FMU runs only the code it carries, but this process has already imported other code under the same "
        "names: " + "; ".join(problems) + ". Python keeps one module per name in a process, so the FMU would run "
        "that code instead. Instantiate it in a process that has not imported another version of these packages "
        "(a checkout or installation of the product, or an FMU of another release)"
    )


def remember_code(resources, entry):
    """Record what the FMU's set-up imported (its entry module, its packages), by content, for the checks of
    later instances (foreign_code)."""
    if entry not in _entries:  # this FMU's file: the module was imported from it, or checked equal to it
        _entries[entry] = _file_digest(os.path.join(resources, entry + ".py"))
    for name in _own_packages(resources):
        _loaded(name)


# -- serialised FMU states ----------------------------------------------------------------------------------
# fmi2SerializeFMUstate writes the state as named values, never as pickle: bytes handed to
# fmi2DeSerializeFMUstate are read as data only (a pickle runs whatever code it names), and a state of another
# FMU, another version or with damaged bytes is refused with what differs. Layout:
#
#   STATE_MAGIC | format (uint32, little-endian) | header length (uint32) | header | data | SHA-256 of all before
#
# The header (JSON, UTF-8) names the FMU that saved the state (model identifier, version, a hash of its declared
# variables) and lists the state's entries in order, each [parent, key, kind] or [parent, key, kind, value]:
# parent is the index of the entry of the dict holding it (-1: the top dict), key its name there; kind "dict"
# (a dict), "float" (the next value of the floats block), "int", "bool", "str" (the value inline), "none", or
# "array", "list", "numpy" (value: [dtype, shape], the next bytes of data: a NumPy array, a list of numbers of
# one type, a NumPy scalar). data: the floats block (every Python float as float64, so each keeps its exact
# bits, NaN payloads included), then each array's bytes in entry order (C order, the dtype as written).

STATE_MAGIC = b"bearing_fmu FMU state\n"
STATE_FORMAT = 1
_HEAD = struct.Struct("<II")  # format, header length
_DIGEST = 32  # bytes of SHA-256
_DTYPES = {f"{order}{kind}{size}" for order in "<>|" for kind in "biufc" for size in (1, 2, 4, 8, 16)}
_SCALARS = {"int": int, "bool": bool, "str": str}
_FMI_TYPES = ("Real", "Integer", "Boolean", "String")  # pythonfmu's variable classes
_identities = weakref.WeakKeyDictionary()  # slave -> (number of its variables, state_identity): made once
# slave -> (the state last serialised, its bytes): a host asks fmi2SerializedFMUstateSize, then
# fmi2SerializeFMUstate, of the same state (FMU states are never changed once taken)
_serialised = weakref.WeakKeyDictionary()


class StateError(ValueError):
    """Bytes that are not a state this FMU can restore; the message says what differs."""


def state_identity(slave):
    """What a serialised state must match: the FMU's model identifier and version (modelDescription.xml) and
    a hash of its declared variables (value reference, name, type, causality, variability), which differs
    between FMUs built from other scenes or networks."""
    known = _identities.get(slave)
    if known is not None and known[0] == len(slave.vars):
        return known[1]
    digest = hashlib.sha256()
    for vr, var in slave.vars.items():
        kind = next((k.__name__ for k in type(var).__mro__ if k.__name__ in _FMI_TYPES), "")
        causality, variability = getattr(var.causality, "name", ""), getattr(var.variability, "name", "")
        digest.update(f"{vr}\t{var.name}\t{kind}\t{causality}\t{variability}\n".encode())
    version = getattr(type(slave), "version", None) or getattr(slave, "version", None) or ""
    identity = {"model": slave.modelName, "version": str(version), "variables": digest.hexdigest()[:16]}
    _identities[slave] = (len(slave.vars), identity)
    return identity


def _same(a, b):
    """a and b the same nested lists of the same Python types and bits (floats compared by their bytes)."""
    if type(a) is not type(b):
        return False
    if type(a) is list:
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if type(a) is float:
        return struct.pack("<d", a) == struct.pack("<d", b)
    return a == b


def _array_entry(value, path, np):
    """[dtype, shape] and bytes of a NumPy array or scalar or a list of numbers; TypeError naming the entry if
    it has no exact representation."""
    try:
        array = np.asarray(value)
    except ValueError:  # a ragged list
        array = np.asarray(None)
    if array.dtype.str not in _DTYPES or (type(value) is list and not _same(array.tolist(), value)):
        raise TypeError(
            f"FMU state entry {path}: {type(value).__name__} of dtype {array.dtype} has no exact representation "
            "(numbers of one type in a rectangular array have)"
        )
    return [array.dtype.str, list(array.shape)], np.ascontiguousarray(array).tobytes()


def _flatten(values, parent, path, out, np):
    """Append the entries of dict `values` (the entry `parent`, at `path`) to out = (entries, floats, blocks)."""
    entries, floats, blocks = out
    for key, value in values.items():
        where = f"{path}/{key}"
        if type(key) is not str:
            raise TypeError(f"FMU state entry {path}: key {key!r} is not a string")
        kind = type(value)
        if kind is dict:
            entries.append([parent, key, "dict"])
            _flatten(value, len(entries) - 1, where, out, np)
        elif kind is float:
            entries.append([parent, key, "float"])
            floats.append(value)
        elif kind in (bool, int, str):
            entries.append([parent, key, kind.__name__, value])
        elif value is None:
            entries.append([parent, key, "none"])
        elif kind is list or isinstance(value, (np.ndarray, np.generic)):
            meta, data = _array_entry(value, where, np)
            entries.append([parent, key, "list" if kind is list else "array" if kind is np.ndarray else "numpy", meta])
            blocks.append(data)
        else:
            raise TypeError(f"FMU state entry {where}: a {kind.__name__} has no representation in a state")


def pack(values, identity):
    """The bytes of dict `values` (of nested dicts, numbers, strings, None, lists of numbers, NumPy arrays and
    scalars) saved by the FMU `identity` (state_identity)."""
    import numpy as np

    entries, floats, blocks = [], [], []
    _flatten(values, -1, "", (entries, floats, blocks), np)
    head = json.dumps({**identity, "floats": len(floats), "entries": entries}, separators=(",", ":")).encode()
    floats = np.array(floats, dtype="<f8").tobytes()
    body = b"".join([STATE_MAGIC, _HEAD.pack(STATE_FORMAT, len(head)), head, floats, *blocks])
    return body + hashlib.sha256(body).digest()


def _header(data):
    """The header (dict) and where data starts; StateError for bytes that are not an intact state."""
    if not data.startswith(STATE_MAGIC):
        raise StateError(
            f"not a serialised FMU state of this product (its {len(data)} bytes do not start with "
            f"{STATE_MAGIC!r}: e.g. a pickle, or a state of another kind of FMU)"
        )
    start = len(STATE_MAGIC) + _HEAD.size
    if len(data) < start + _DIGEST:
        raise StateError(f"truncated: {len(data)} bytes, a serialised state has at least {start + _DIGEST}")
    version, length = _HEAD.unpack_from(data, len(STATE_MAGIC))
    if version != STATE_FORMAT:
        raise StateError(f"format version {version}, this FMU reads format version {STATE_FORMAT}")
    if hashlib.sha256(data[:-_DIGEST]).digest() != data[-_DIGEST:]:
        raise StateError(f"corrupted or truncated: its {len(data)} bytes do not match their SHA-256 checksum")
    try:
        header = json.loads(data[start : start + length].decode("utf-8"))
    except (ValueError, RecursionError) as exc:  # RecursionError: JSON nested deeper than Python parses
        raise StateError(f"corrupted header: {exc}") from None
    if not isinstance(header, dict) or not isinstance(header.get("entries"), list):
        raise StateError("corrupted header: no list of entries")
    return header, start + length


def _check_identity(header, identity):
    fields = ("model", "version", "variables")
    if any(header.get(k) != identity[k] for k in fields):
        saved = "{} version {} (variables {})".format(*(header.get(k) for k in fields))
        own = "{} version {} (variables {})".format(*(identity[k] for k in fields))
        raise StateError(
            f"the state was saved by {saved}, this FMU is {own}: a state is restored only into the FMU and "
            "version that saved it"
        )


def _array(meta, data, at, np):
    """(array, next offset) of an entry's [dtype, shape] at data[at:]; StateError if it does not fit."""
    if not (isinstance(meta, list) and len(meta) == 2 and meta[0] in _DTYPES and isinstance(meta[1], list)):
        raise StateError(f"corrupted entry: {meta!r} is no [dtype, shape]")
    dtype, shape = np.dtype(meta[0]), meta[1]
    if not all(type(n) is int and n >= 0 for n in shape):
        raise StateError(f"corrupted entry: shape {shape!r}")
    count = 1
    for n in shape:
        count *= n
    end = at + count * dtype.itemsize
    if end > len(data) - _DIGEST:
        raise StateError(f"corrupted entry: an array of {count} {dtype} beyond the data")
    return np.frombuffer(data, dtype=dtype, count=count, offset=at).reshape(shape).copy(), end


def _value(entry, floats, data, at, np):
    """(value, next offset in data) of one header entry [parent, key, kind(, value)]."""
    kind, value = entry[2], entry[3] if len(entry) == 4 else None
    if kind == "dict":
        return {}, at
    if kind == "float":
        return next(floats), at
    if kind == "none":
        return None, at
    if kind in _SCALARS and type(value) is _SCALARS[kind]:
        return value, at
    if kind in ("array", "list", "numpy"):
        array, at = _array(value, data, at, np)
        return (array.tolist() if kind == "list" else array[()] if kind == "numpy" else array), at
    raise StateError(f"corrupted entry {entry!r}")


def unpack(data, identity=None):
    """The dict of a serialised state (pack); StateError if the bytes are not an intact state or, with
    `identity`, were saved by another FMU or version."""
    import numpy as np

    data = bytes(data)
    header, at = _header(data)
    if identity is not None:
        _check_identity(header, identity)
    n = header.get("floats")
    if type(n) is not int or n < 0 or at + 8 * n > len(data) - _DIGEST:
        raise StateError(f"corrupted header: floats {n!r}")
    floats = iter(np.frombuffer(data, dtype="<f8", count=n, offset=at).tolist())
    at += 8 * n
    root, dicts = {}, []  # dicts: the value of each entry (None for a non-dict)
    for entry in header["entries"]:
        if not (isinstance(entry, list) and len(entry) in (3, 4) and type(entry[0]) is int and -1 <= entry[0]):
            raise StateError(f"corrupted entry {entry!r}")
        parent = root if entry[0] == -1 else dicts[entry[0]] if entry[0] < len(dicts) else None
        if not isinstance(parent, dict) or type(entry[1]) is not str:
            raise StateError(f"corrupted entry {entry!r}: no dict holds it")
        try:
            value, at = _value(entry, floats, data, at, np)
        except StopIteration:
            raise StateError("corrupted header: fewer floats than entries of kind float") from None
        parent[entry[1]] = value
        dicts.append(value if entry[2] == "dict" else None)
    if next(floats, None) is not None or at != len(data) - _DIGEST:
        raise StateError("corrupted: more data than the entries hold")
    return root


def dumps(state, slave):
    """fmi2SerializeFMUstate: the bytes of the FMU state `state` of `slave`, the layer's tuple (call-sequence
    state, time, the slave's _get_fmu_state())."""
    known = _serialised.get(slave)
    if known is not None and known[0] is state:
        return known[1]
    where, time, values = state
    data = pack({"call_state": where, "time": time, "slave": values}, state_identity(slave))
    _serialised[slave] = (state, data)
    return data


def loads(data, slave):
    """fmi2DeSerializeFMUstate: the FMU state (call-sequence state, time, the slave's state) of bytes `data`
    saved by this FMU (dumps), or the reason (str) they are refused."""
    try:
        values = unpack(data, state_identity(slave))
        return (values["call_state"], values["time"], values["slave"])
    except StateError as exc:
        return str(exc)
    except (KeyError, TypeError) as exc:
        return f"corrupted: {type(exc).__name__}: {exc}"
