"""Compile the FMUs' FMI 2.0 binaries and put them into an FMU (docs/fmu_runtime.md).

Two libraries, both linked with no libpython:
- the FMU's binary, binaries/linux64/<modelIdentifier>.so (fmi2_loader.c): finds the interpreter (the
  host's, or for a native host one found by a documented search and started) and loads the layer;
- the layer, binaries/linux64/fmi2_python.abi3.so (fmi2_python.c), built for CPython's stable ABI
  (Py_LIMITED_API 3.10): one binary serves every Python from 3.10 on.
Each is compiled once per source and compiler command into a cache directory and reused by every FMU
of a build. The layer's Python side (fmi2_layer.py) goes into the FMU as resources/fmi2_layer.py.
"""

import hashlib
import os
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import zipfile
from pathlib import Path
from xml.etree import ElementTree

RUNTIME_DIR = Path(__file__).resolve().parent
SOURCE = RUNTIME_DIR / "fmi2_python.c"  # the layer
LOADER_SOURCE = RUNTIME_DIR / "fmi2_loader.c"  # the FMU's binary
HEADERS = sorted(RUNTIME_DIR.glob("*.h"))  # included by both sources: part of every compiled copy's cache key
HELPER_SOURCE = RUNTIME_DIR / "fmi2_layer.py"  # the layer's Python side
HELPER_FILE = "fmi2_layer.py"  # resources/ file the layer loads at its first fmi2Instantiate
LAYER_FILE = "fmi2_python.abi3.so"  # beside the FMU's binary; the name fmi2_loader.c loads
PLATFORM = "linux64"  # the only platform the layer is built for
PYTHON_HINT = "python.txt"  # resources/ file read by the loader: the interpreter that built the FMU
GUID_FILE = "guid.txt"  # resources/ file read by the layer: the GUID fmi2Instantiate must be given
OWN_PACKAGES = "own_packages.txt"  # resources/ file read by the layer: the product's packages the FMU carries
LIMITED_API = "0x030A0000"  # the stable ABI of Python 3.10, the oldest supported host


class RuntimeBuildError(RuntimeError):
    """The FMI binaries cannot be compiled here (no compiler, no Python headers, compile error)."""


def fmi_headers():
    """Directory of the FMI 2.0 headers (fmi2Functions.h ...) shipped with fmpy."""
    import fmpy

    path = Path(fmpy.__file__).parent / "c-code"
    if not (path / "fmi2Functions.h").is_file():
        raise RuntimeBuildError(f"fmi2Functions.h not found in {path} (fmpy's package data)")
    return path


def compile_command(source, output):
    """gcc command line compiling `source` (SOURCE or LOADER_SOURCE) into the shared library `output`.
    Neither links a libpython: the layer takes the interpreter's symbols from the process, the loader
    needs none."""
    if sys.platform != "linux" or sys.maxsize < 2**32:
        raise RuntimeBuildError(f"the FMU runtime is built for {PLATFORM} only, not {sys.platform}")
    command = [
        os.environ.get("CC", "gcc"),
        "-shared",
        "-fPIC",
        "-O2",
        "-std=gnu11",
        "-Wall",
        "-Wextra",
        "-fvisibility=hidden",  # only the fmi2* functions are exported
        f"-I{fmi_headers()}",
        f"-I{RUNTIME_DIR}",
    ]
    if Path(source) == SOURCE:
        include = sysconfig.get_paths()["include"]
        if not (Path(include) / "Python.h").is_file():
            raise RuntimeBuildError(f"Python.h not found in {include} (the Python headers are needed)")
        command.append(f"-I{include}")  # any Python >= 3.10: Py_LIMITED_API selects the 3.10 stable ABI
    return command + [str(source), "-o", str(output), "-ldl", "-lpthread"]


def cache_dir():
    base = os.environ.get("BEARING_FMU_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"), "bearing_fmu"
    )
    return Path(base) / "runtime"


def compiled_runtime(source=SOURCE, directory=None):
    """Path of `source` compiled (SOURCE: the layer; LOADER_SOURCE: the FMU's binary), compiling it if the
    cache has no copy."""
    probe = compile_command(source, "OUT")
    digest = hashlib.sha256(Path(source).read_bytes())
    for header in HEADERS:
        digest.update(header.read_bytes())
    digest.update("\0".join(probe).encode())
    path = Path(directory or cache_dir()) / f"{Path(source).stem}-{digest.hexdigest()[:16]}.so"
    if path.is_file():
        return path
    path.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(dir=path.parent) as tmp:
        staged = Path(tmp) / path.name
        proc = subprocess.run(compile_command(source, staged), capture_output=True, text=True)
        if proc.returncode != 0:
            raise RuntimeBuildError(f"compiling {Path(source).name} failed:\n{proc.stderr}")
        os.replace(staged, path)  # atomic: concurrent builds do not collide
    return path


def install_runtime(fmu_path, python=sys.executable):
    """Replace the binaries of a pythonfmu-built FMU by the project's (binaries/linux64/<modelIdentifier>.so,
    the loader, and the layer beside it), record `python` in resources/python.txt (a native host's last
    candidate interpreter: the build machine's) and the modelDescription's GUID in resources/guid.txt
    (fmi2Instantiate refuses another GUID: one layer serves every FMU, so the GUID cannot be compiled in), and
    the layer's Python side in resources/fmi2_layer.py."""
    fmu_path = Path(fmu_path)
    loader, layer = compiled_runtime(LOADER_SOURCE), compiled_runtime(SOURCE)
    staged = fmu_path.with_suffix(".fmu.tmp")
    with zipfile.ZipFile(fmu_path) as source, zipfile.ZipFile(staged, "w", zipfile.ZIP_DEFLATED) as target:
        md = ElementTree.fromstring(source.read("modelDescription.xml"))
        identifier = md.find("CoSimulation").get("modelIdentifier")
        written = (f"resources/{PYTHON_HINT}", f"resources/{GUID_FILE}", f"resources/{HELPER_FILE}")
        for item in source.infolist():
            if not item.filename.startswith("binaries/") and item.filename not in written:
                target.writestr(item, source.read(item))
        target.write(loader, f"binaries/{PLATFORM}/{identifier}.so")
        target.write(layer, f"binaries/{PLATFORM}/{LAYER_FILE}")
        target.writestr(f"resources/{PYTHON_HINT}", f"{python}\n")
        target.writestr(f"resources/{GUID_FILE}", f"{md.get('guid')}\n")
        target.write(HELPER_SOURCE, f"resources/{HELPER_FILE}")
    shutil.move(staged, fmu_path)
    return fmu_path
