"""The table of stability cases (tests/stability/cases.py) names only tests that exist, each with a
docstring stating its case and outcome."""

import ast

import pytest

from tests.conftest import ROOT
from tests.stability.cases import CASES


def functions(path):
    tree = ast.parse((ROOT / path).read_text())
    return {node.name: ast.get_docstring(node) for node in tree.body if isinstance(node, ast.FunctionDef)}


@pytest.mark.parametrize("case,fidelities,path,name", CASES, ids=[f"{c[0]}-{c[3]}" for c in CASES])
def test_every_listed_case_has_its_test(case, fidelities, path, name):
    """Each listed test exists and has a docstring (the case and its expected outcome)."""
    found = functions(path)
    assert name in found, f"{path} has no {name} (case: {case})"
    assert found[name] and len(found[name]) > 40, f"{path}::{name} states no outcome"


def test_every_stability_file_is_in_the_table():
    """No stability test file is left out of the table the report prints."""
    listed = {path for _, _, path, _ in CASES}
    files = {p.relative_to(ROOT).as_posix() for p in (ROOT / "tests" / "stability").glob("test_*.py")}
    assert files - {"tests/stability/test_cases.py"} <= listed
