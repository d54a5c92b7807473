"""The numba cache cannot be served stale: its directory is keyed on the kernel sources (bearing_fmu_common/jit.py).

numba's cache=True checks only the cached function's own source file, so an edit to a callee would leave
a stale caller in a fixed cache directory; these tests pin the key, its independence of the location
(the FMU bundles run a copy of the sources from a stable per-version directory), and the fallbacks.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numba
import pytest

from bearing_fmu.kernels import hertz
from bearing_fmu_common import jit

ROOT = Path(jit.__file__).resolve().parent.parent


def copy_sources(dest):
    for pattern in jit.KERNEL_SOURCES:
        for path in ROOT.glob(pattern):
            target = dest / path.relative_to(ROOT)
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(path, target)


def test_kernels_cache_in_the_directory_keyed_on_their_sources():
    if os.environ.get("NUMBA_CACHE_DIR"):
        pytest.skip("NUMBA_CACHE_DIR set by the user: numba uses it as given")
    key = jit.kernel_source_hash()
    assert Path(numba.config.CACHE_DIR).name == key
    assert Path(hertz.hertz_contact._cache._cache_path).is_relative_to(numba.config.CACHE_DIR)


def test_key_depends_on_every_kernel_source_and_not_on_the_location(tmp_path):
    copy_sources(tmp_path)
    assert jit.kernel_source_hash(tmp_path) == jit.kernel_source_hash()  # a bundle's copy shares the key
    callee = tmp_path / "bearing_fmu" / "kernels" / "lubricant.py"  # called by other kernels' modules
    callee.write_text(callee.read_text() + "\n# edited\n")
    assert jit.kernel_source_hash(tmp_path) != jit.kernel_source_hash()
    network = tmp_path / "spindle" / "thermal" / "network.py"
    assert network.is_file()
    callee.unlink()
    before = jit.kernel_source_hash(tmp_path)
    network.write_text(network.read_text() + "\n# edited\n")
    assert jit.kernel_source_hash(tmp_path) != before


def _cache_dir_in_child(env):
    code = (
        "import numba, bearing_fmu_common.jit\n"
        "from bearing_fmu.kernels import hertz\n"
        "assert hertz.hertz_stiffness(0.005, 0.1, 2.3e11, 8.0, 1.02, 3.2) > 0.0\n"
        "print(numba.config.CACHE_DIR)"
    )
    env = {k: v for k, v in {**os.environ, **env}.items() if k != "NUMBA_CACHE_DIR"}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    return out.stdout.strip().splitlines()[-1] if out.stdout.strip() else ""


def test_unwritable_cache_falls_back_to_the_temporary_directory(tmp_path):
    blocker = tmp_path / "a_file"
    blocker.write_text("not a directory")
    tmp = tmp_path / "tmp"
    tmp.mkdir()
    used = _cache_dir_in_child({"BEARING_FMU_CACHE": str(blocker / "cache"), "TMPDIR": str(tmp)})
    assert Path(used).is_relative_to(tmp) and Path(used).name == jit.kernel_source_hash()


def test_nothing_writable_leaves_numba_its_own_locations(tmp_path, monkeypatch):
    blocker = tmp_path / "a_file"
    blocker.write_text("not a directory")
    monkeypatch.setattr(numba.config, "CACHE_DIR", "")
    monkeypatch.setenv("BEARING_FMU_CACHE", str(blocker / "cache"))
    monkeypatch.setattr(jit.tempfile, "gettempdir", lambda: str(blocker / "tmp"))
    jit._set_cache_dir()
    assert numba.config.CACHE_DIR == ""


def test_bearing_fmu_cache_is_the_base_as_for_the_fmu_bundles(tmp_path):
    used = _cache_dir_in_child({"BEARING_FMU_CACHE": str(tmp_path)})
    assert Path(used) == tmp_path / "numba" / jit.kernel_source_hash()
