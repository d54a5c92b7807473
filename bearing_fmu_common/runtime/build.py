"""Compile the FMI 2.0 export layer (fmi2_python.c) for the running Python and put it into an FMU.

The layer replaces pythonfmu's prebuilt binary (docs/fmu_runtime.md): it links the running
interpreter's libpython, so the FMU binary serves that Python only (same version, built with
--enable-shared). It is compiled once per source/interpreter/compiler into a cache directory and
reused by every FMU of a build.
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

SOURCE = Path(__file__).with_name("fmi2_python.c")
PLATFORM = "linux64"  # the only platform the layer is built for
PYTHON_HINT = "python.txt"  # resources/ file read by the layer: the interpreter for native hosts
GUID_FILE = "guid.txt"  # resources/ file read by the layer: the GUID fmi2Instantiate must be given


class RuntimeBuildError(RuntimeError):
    """The export layer cannot be compiled here (no shared libpython, no compiler, compile error)."""


def fmi_headers():
    """Directory of the FMI 2.0 headers (fmi2Functions.h ...) shipped with fmpy."""
    import fmpy

    path = Path(fmpy.__file__).parent / "c-code"
    if not (path / "fmi2Functions.h").is_file():
        raise RuntimeBuildError(f"fmi2Functions.h not found in {path} (fmpy's package data)")
    return path


def compile_command(output):
    """gcc command line compiling SOURCE into the shared library `output` against this Python."""
    if sys.platform != "linux" or sys.maxsize < 2**32:
        raise RuntimeBuildError(f"the FMU runtime is built for {PLATFORM} only, not {sys.platform}")
    if not sysconfig.get_config_var("Py_ENABLE_SHARED"):
        raise RuntimeBuildError(
            f"{sys.executable} has no shared libpython (configure --enable-shared): the FMU runtime links it"
        )
    libdir = sysconfig.get_config_var("LIBDIR")
    library = f"python{sysconfig.get_config_var('LDVERSION')}"
    return [
        os.environ.get("CC", "gcc"),
        "-shared",
        "-fPIC",
        "-O2",
        "-std=gnu11",
        "-Wall",
        "-Wextra",
        "-fvisibility=hidden",  # only the fmi2* functions are exported
        f"-I{sysconfig.get_paths()['include']}",
        f"-I{fmi_headers()}",
        str(SOURCE),
        "-o",
        str(output),
        f"-L{libdir}",
        f"-l{library}",
        f"-Wl,-rpath,{libdir}",  # a native host finds libpython without LD_LIBRARY_PATH
        "-ldl",
        "-lpthread",
    ]


def cache_dir():
    base = os.environ.get("BEARING_FMU_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"), "bearing_fmu"
    )
    return Path(base) / "runtime"


def compiled_runtime(directory=None):
    """Path of the compiled layer for this interpreter, compiling it if the cache has no copy."""
    probe = compile_command("OUT")
    digest = hashlib.sha256(SOURCE.read_bytes())
    digest.update("\0".join(probe).encode())
    digest.update(sys.version.encode())
    path = Path(directory or cache_dir()) / f"fmi2_python-{digest.hexdigest()[:16]}.so"
    if path.is_file():
        return path
    path.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(dir=path.parent) as tmp:
        staged = Path(tmp) / path.name
        proc = subprocess.run(compile_command(staged), capture_output=True, text=True)
        if proc.returncode != 0:
            raise RuntimeBuildError(f"compiling {SOURCE.name} failed:\n{proc.stderr}")
        os.replace(staged, path)  # atomic: concurrent builds do not collide
    return path


def install_runtime(fmu_path, python=sys.executable):
    """Replace the binaries of a pythonfmu-built FMU by the layer (binaries/linux64/<modelIdentifier>.so),
    record `python` in resources/python.txt for native hosts and the modelDescription's GUID in
    resources/guid.txt (fmi2Instantiate refuses another GUID: one library serves every FMU, so the GUID
    cannot be compiled in)."""
    fmu_path = Path(fmu_path)
    library = compiled_runtime()
    staged = fmu_path.with_suffix(".fmu.tmp")
    with zipfile.ZipFile(fmu_path) as source, zipfile.ZipFile(staged, "w", zipfile.ZIP_DEFLATED) as target:
        md = ElementTree.fromstring(source.read("modelDescription.xml"))
        identifier = md.find("CoSimulation").get("modelIdentifier")
        written = (f"resources/{PYTHON_HINT}", f"resources/{GUID_FILE}")
        for item in source.infolist():
            if not item.filename.startswith("binaries/") and item.filename not in written:
                target.writestr(item, source.read(item))
        target.write(library, f"binaries/{PLATFORM}/{identifier}.so")
        target.writestr(f"resources/{PYTHON_HINT}", f"{python}\n")
        target.writestr(f"resources/{GUID_FILE}", f"{md.get('guid')}\n")
    shutil.move(staged, fmu_path)
    return fmu_path
