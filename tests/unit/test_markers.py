"""The `slow`, `bare_host`, `python_hosts` and `ssp_masters` lists of tests/_markers.py name tests that exist (a
renamed test must not silently lose its marker)."""

import ast
from pathlib import Path

from tests._markers import BARE_HOST, PYTHON_HOSTS, SLOW, SSP_MASTERS

ROOT = Path(__file__).resolve().parents[2]


def test_every_slow_entry_names_an_existing_test_function():
    for relative, names in [*SLOW.items(), *BARE_HOST.items(), *PYTHON_HOSTS.items(), *SSP_MASTERS.items()]:
        tree = ast.parse((ROOT / relative).read_text())
        defined = {node.name for node in ast.walk(tree) if isinstance(node, ast.FunctionDef)}
        assert names <= defined, (relative, sorted(names - defined))
