"""The FMU runtime's C sources (bearing_fmu_common/runtime, docs/fmu_runtime.md) and the headers of their own
folder they include: every such header is installed with the package (an installed product compiles the
runtime when it builds an FMU) and is part of the key of a compiled copy in the cache (a changed header
recompiles both libraries)."""

import fnmatch
import re
import tomllib

from bearing_fmu_common.runtime import binaries
from tests.conftest import ROOT

INCLUDE = re.compile(r'^#include "([^"]+)"', re.MULTILINE)


def own_headers():
    """The headers of the runtime's folder that its sources include, directly or through another header."""
    found, todo = set(), [binaries.SOURCE, binaries.LOADER_SOURCE]
    while todo:
        for name in INCLUDE.findall(todo.pop().read_text()):
            path = binaries.RUNTIME_DIR / name
            if path.is_file() and path not in found:  # fmi2Functions.h comes from fmpy (-I)
                found.add(path)
                todo.append(path)
    return found


def test_the_sources_include_headers_of_their_folder():
    assert {p.name for p in own_headers()} >= {"fmi2_shared.h", "fmi2_function_list.h"}


def test_every_included_header_is_package_data():
    patterns = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]
    package = binaries.RUNTIME_DIR.parent
    for path in own_headers() | {binaries.SOURCE, binaries.LOADER_SOURCE}:
        relative = path.relative_to(package).as_posix()
        assert any(fnmatch.fnmatch(relative, p) for p in patterns[package.name]), relative


def test_every_included_header_is_in_the_cache_key():
    assert own_headers() <= set(binaries.HEADERS)
