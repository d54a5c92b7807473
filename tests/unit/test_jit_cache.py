"""The numba cache of the kernels (bearing_fmu_common/jit.py, docs/fmu_runtime.md "Compiled code").

numba's cache=True checks only the cached function's own source file, so an edit to a callee would leave
a stale caller in a fixed cache directory; these tests pin the key, its independence of the location
and file times of the sources (the FMUs run copies of them), the fallbacks for an unusable directory,
the use of a read-only filled one, the modes of shared directories, and the compiled-code directories
an FMU ships. Each case runs in a fresh process (the cache is chosen when jit is imported).
"""

import json
import os
import shutil
import stat
import sys
from pathlib import Path

import pytest

from bearing_fmu.kernels import hertz
from bearing_fmu_common import jit
from tests._processes import run_checked

ROOT = Path(jit.__file__).resolve().parent.parent
HERTZ_CALL = "hertz.hertz_stiffness(0.005, 0.1, 2.3e11, 8.0, 1.02, 3.2)"
# prints, as JSON: the tiers, and the hits and misses of the call
CHILD = f"""
import json, os, sys
{{prelude}}
from bearing_fmu_common import jit
{{register}}
from bearing_fmu.kernels import hertz
assert {HERTZ_CALL} > 0.0
stats = hertz.hertz_stiffness.stats
print(json.dumps({{{{"write": str(jit.TIERS.write), "read": [str(d) for d, _ in jit.TIERS.read],
    "hits": sum(stats.cache_hits.values()), "misses": sum(stats.cache_misses.values()),
    "codegen": jit.codegen_description()}}}}))
"""
UNSET = ("NUMBA_CACHE_DIR", "BEARING_FMU_CACHE", "XDG_CACHE_HOME", "NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES")


def run_child(env=None, prelude="", cwd=None, umask=None):
    """(result dict, stderr) of CHILD in a fresh interpreter with env added to a clean environment; prelude runs
    before jit is imported; the compiled-code directory $COMPILED, if set, is registered before the call."""
    full = {k: v for k, v in os.environ.items() if k not in UNSET}
    full.update(env or {})
    register = "jit.add_compiled_dir(os.environ['COMPILED'])" if "COMPILED" in full else ""
    code = CHILD.format(prelude=prelude, register=register)
    proc = run_checked([sys.executable, "-c", code], full, cwd=cwd, umask=umask)
    return json.loads(proc.stdout.strip().splitlines()[-1]), proc.stderr


def copy_sources(dest):
    for pattern in jit.KERNEL_SOURCES:
        for path in ROOT.glob(pattern):
            target = dest / path.relative_to(ROOT)
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(path, target)


def copy_packages(dest):
    """A copy of the packages (as an FMU bundle unpacks them), with new file times."""
    for package in ("bearing_fmu", "bearing_fmu_common", "spindle"):
        shutil.copytree(ROOT / package, dest / package, ignore=shutil.ignore_patterns("__pycache__"))
    return dest


def test_kernels_cache_in_the_user_directory_keyed_on_their_sources():
    if not os.access(jit.user_cache_dir(), os.W_OK):
        pytest.skip("the user cache is not writable here")
    assert jit.TIERS.write == jit.user_cache_dir()
    assert jit.TIERS.write.name == jit.kernel_source_hash()
    assert Path(hertz.hertz_contact.stats.cache_path) == jit.TIERS.write / "bearing_fmu" / "kernels"


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


def test_key_covers_the_kernels_in_subpackages(tmp_path):
    copy_sources(tmp_path)
    integrator = tmp_path / "bearing_fmu" / "kernels" / "ball_dynamics" / "integrator.py"
    assert integrator.is_file()
    integrator.write_text(integrator.read_text() + "\n# edited\n")
    assert jit.kernel_source_hash(tmp_path) != jit.kernel_source_hash()


def test_cache_serves_a_copy_of_the_sources_elsewhere_with_other_file_times(tmp_path):
    cache = tmp_path / "cache"
    first, _ = run_child({"BEARING_FMU_CACHE": str(cache)})
    copy = copy_packages(tmp_path / "elsewhere")
    for path in copy.rglob("*.py"):
        os.utime(path, (1e9, 1e9))  # file times of another unpacking
    second, _ = run_child({"BEARING_FMU_CACHE": str(cache), "PYTHONPATH": str(copy)}, cwd=copy)
    assert first["misses"] == 1 and first["write"] == str(cache / "numba" / jit.kernel_source_hash())
    assert second["write"] == first["write"] and (second["hits"], second["misses"]) == (1, 0)


def _falls_back(tmp_path, variable, leaf):
    """With `variable` set to a path through a file, the child compiles into a private temporary directory (under
    its TMPDIR, mode 0700, ours) and says which path it could not write."""
    blocker = tmp_path / "a_file"
    blocker.write_text("not a directory")
    tmp = tmp_path / "tmp"
    tmp.mkdir()
    unusable = blocker / leaf
    result, stderr = run_child({variable: str(unusable), "TMPDIR": str(tmp)})
    write = Path(result["write"])
    assert write.is_relative_to(tmp), write
    assert write.stat().st_mode & 0o777 == 0o700 and write.stat().st_uid == os.getuid()
    assert "cannot be written" in stderr and str(unusable) in stderr
    assert result["misses"] == 1


def test_a_path_through_a_file_falls_back_to_a_private_temporary_directory(tmp_path):
    _falls_back(tmp_path, "BEARING_FMU_CACHE", "cache")


def test_no_usable_home_falls_back_to_a_private_temporary_directory(tmp_path):
    _falls_back(tmp_path, "HOME", "home")


# refuses writes under READ_ONLY as a read-only directory would, also for root (who may write anywhere)
READ_ONLY_PRELUDE = """
import tempfile
_ro = os.path.realpath(os.environ["READ_ONLY"])
_temporary_file = tempfile.TemporaryFile
def _refuse(*args, dir=None, **kwargs):
    if dir is not None and os.path.realpath(dir).startswith(_ro):
        raise PermissionError(13, "Read-only file system", dir)
    return _temporary_file(*args, dir=dir, **kwargs)
tempfile.TemporaryFile = _refuse
"""


def make_read_only(path):
    for p in [path, *path.rglob("*")]:
        p.chmod(p.stat().st_mode & ~(stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH))


def test_a_filled_read_only_cache_is_used_and_new_code_goes_to_a_private_directory(tmp_path):
    shared = tmp_path / "shared"
    filled, _ = run_child({"BEARING_FMU_CACHE": str(shared)})
    make_read_only(shared)
    tmp = tmp_path / "tmp"
    tmp.mkdir()
    try:
        result, stderr = run_child(
            {"BEARING_FMU_CACHE": str(shared), "TMPDIR": str(tmp), "READ_ONLY": str(shared)},
            prelude=READ_ONLY_PRELUDE,
        )
    finally:
        shared.chmod(0o755)
    assert filled["misses"] == 1
    assert (result["hits"], result["misses"]) == (1, 0)  # served by the read-only cache
    assert result["read"][0] == filled["write"] and Path(result["write"]).is_relative_to(tmp)
    assert "cannot be written" in stderr and "existing entries are still used" in stderr


def test_another_users_temporary_directory_is_not_used(tmp_path, monkeypatch):
    monkeypatch.setattr(jit.tempfile, "tempdir", str(tmp_path))
    key = "k" * 64
    ours = jit.private_temp_dir(key)
    assert ours == tmp_path / f"bearing_fmu-{os.getuid()}" / "numba" / key
    assert ours.stat().st_mode & 0o777 == 0o700
    monkeypatch.setattr(jit.os, "getuid", lambda: os.geteuid() + 1)  # the same path now belongs to another user
    planted = tmp_path / f"bearing_fmu-{os.geteuid() + 1}" / "numba" / key
    shutil.copytree(ours.parent.parent, planted.parent.parent)
    other = jit.private_temp_dir(key)
    assert other != planted and other.parent == tmp_path and other.stat().st_mode & 0o777 == 0o700


def test_a_group_writable_temporary_directory_is_not_used(tmp_path, monkeypatch):
    monkeypatch.setattr(jit.tempfile, "tempdir", str(tmp_path))
    key = "g" * 64
    ours = jit.private_temp_dir(key)
    ours.chmod(0o770)
    assert jit.private_temp_dir(key) != ours


def test_a_shared_cache_is_created_with_the_users_umask_not_0700(tmp_path):
    shared = tmp_path / "shared"
    result, _ = run_child({"BEARING_FMU_CACHE": str(shared)}, umask=0o002)
    write = Path(result["write"])
    for path in (shared, shared / "numba", write, write / "bearing_fmu", write / "bearing_fmu" / "kernels"):
        assert path.stat().st_mode & 0o777 == 0o775, path
    for entry in (write / "bearing_fmu" / "kernels").iterdir():
        assert entry.stat().st_mode & 0o666 == 0o664, entry


def test_numba_cache_dir_set_by_the_user_holds_the_cache(tmp_path):
    result, _ = run_child({"NUMBA_CACHE_DIR": str(tmp_path)})
    assert result["write"] == str(tmp_path / f"bearing_fmu-{jit.kernel_source_hash()}")


def _portable_dir(tmp_path, triple=None):
    """A compiled-code directory as an FMU ships it: hertz kernels compiled for the generic CPU."""
    build, _ = run_child({"BEARING_FMU_CACHE": str(tmp_path / "build"), "NUMBA_CPU_NAME": jit.PORTABLE_CPU})
    assert build["codegen"][1:] == [jit.PORTABLE_CPU, ""]  # generic CPU, no optional features
    compiled = tmp_path / "compiled"
    shutil.copytree(Path(build["write"]), compiled / jit.kernel_source_hash())
    magic = [triple or build["codegen"][0], *build["codegen"][1:]]
    (compiled / jit.TARGET_FILE).write_text(json.dumps({"magic": magic}))
    return compiled


def test_shipped_generic_code_is_used_with_an_empty_user_cache(tmp_path):
    compiled = _portable_dir(tmp_path)
    env = {"BEARING_FMU_CACHE": str(tmp_path / "fresh"), "COMPILED": str(compiled)}
    result, _ = run_child(env)
    assert result["codegen"][1] != jit.PORTABLE_CPU  # this host's codegen: the entry matched under its own
    assert (result["hits"], result["misses"]) == (1, 0)
    assert not list(Path(result["write"]).rglob("*.nbc"))  # nothing compiled, nothing saved


def test_shipped_code_of_another_platform_is_not_used(tmp_path):
    compiled = _portable_dir(tmp_path, triple="aarch64-unknown-linux-gnu")
    env = {"BEARING_FMU_CACHE": str(tmp_path / "fresh"), "COMPILED": str(compiled)}
    result, _ = run_child(env)
    assert (result["hits"], result["misses"]) == (0, 1)


def _bundle_with_compiled_code(tmp_path, edit=None):
    """An FMU's resources: a subset of the kernel sources (without spindle's) and, in numba_portable/, the
    hertz kernels compiled for the generic CPU under the key of that subset (not the whole tree's)."""
    bundle = tmp_path / "resources"
    for pattern in ("bearing_fmu_common/*.py", "bearing_fmu/kernels/**/*.py"):
        for path in ROOT.glob(pattern):
            target = bundle / path.relative_to(ROOT)
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(path, target)
    if edit:
        (bundle / edit).write_text((bundle / edit).read_text() + "\n# edited\n")
    key = jit.kernel_source_hash(bundle)
    assert key != jit.kernel_source_hash()
    compiled = _portable_dir(tmp_path)
    (compiled / jit.kernel_source_hash()).rename(compiled / key)
    shutil.move(str(compiled), str(bundle / "numba_portable"))
    return bundle / "numba_portable"


def test_a_host_with_its_own_copy_of_the_sources_uses_an_fmus_code_built_from_equal_ones(tmp_path):
    """The co-simulation master imports the product, so an FMU's entry script runs on the host's modules, keyed
    on the whole tree; the FMU's code is keyed on the sources it bundles. Equal sources: used, nothing compiled."""
    compiled = _bundle_with_compiled_code(tmp_path)
    result, _ = run_child({"BEARING_FMU_CACHE": str(tmp_path / "fresh"), "COMPILED": str(compiled)})
    assert (result["hits"], result["misses"]) == (1, 0)
    assert not list(Path(result["write"]).rglob("*.nbc"))


def test_an_fmus_code_built_from_other_sources_is_not_used(tmp_path):
    """One bundled kernel source differs from the host's (another release's FMU): its code is not trusted."""
    compiled = _bundle_with_compiled_code(tmp_path, edit="bearing_fmu/kernels/ehl.py")
    result, _ = run_child({"BEARING_FMU_CACHE": str(tmp_path / "fresh"), "COMPILED": str(compiled)})
    assert (result["hits"], result["misses"]) == (0, 1)


def test_a_directory_without_target_description_is_not_registered(tmp_path):
    (tmp_path / jit.kernel_source_hash()).mkdir()
    assert jit.add_compiled_dir(tmp_path) is False
    assert jit.add_compiled_dir(tmp_path / "missing") is False


def test_no_home_directory_at_all_falls_back_with_a_warning(tmp_path, monkeypatch, caplog):
    def no_home():
        raise RuntimeError("Could not determine home directory.")

    for name in ("BEARING_FMU_CACHE", "XDG_CACHE_HOME", "NUMBA_CACHE_DIR"):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setattr(jit.Path, "home", staticmethod(no_home))
    monkeypatch.setattr(jit.tempfile, "tempdir", str(tmp_path))
    tiers = jit.CacheTiers("h" * 64)
    assert tiers.write == tmp_path / f"bearing_fmu-{os.getuid()}" / "numba" / ("h" * 64)
    assert tiers.read == [(tiers.write, None)]
    assert "no home directory" in caplog.text and str(tiers.write) in caplog.text


def test_numba_disable_jit_runs_the_kernels_as_plain_python(tmp_path):
    """NUMBA_DISABLE_JIT=1 (numba's switch for debugging kernels in Python) runs the product: the policy
    attaches its cache only to compiled kernels, and the plain functions give the compiled results."""
    code = (
        "from bearing_fmu import AnalyticModel; import json; "
        "print(json.dumps(AnalyticModel('6208').evaluate(omega=500.0, F_y=3000.0, T_oil=313.15)['Q_max_inner']))"
    )
    env = {k: v for k, v in os.environ.items() if k not in UNSET}
    results = []
    for disable in ("1", "0"):
        child_env = {**env, "NUMBA_DISABLE_JIT": disable, "BEARING_FMU_CACHE": str(tmp_path)}
        proc = run_checked([sys.executable, "-c", code], child_env, cwd=ROOT)
        results.append(json.loads(proc.stdout.strip().splitlines()[-1]))
    assert results[0] == pytest.approx(results[1], rel=1e-12)
