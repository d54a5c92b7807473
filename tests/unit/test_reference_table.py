"""The reference table (benchmarks/reference_table.py) and its cases (tests/cases): how a
comparison is judged and summarised, and that every case the report renders is one a validation test asserts on."""

import ast
import json
from pathlib import Path

import numpy as np
import pytest

from benchmarks import reference_table
from tests.cases import CASES, Comparison, ReferenceCase, worst
from tests.cases.comparison import half_unit, printed_comparison

VALIDATION = Path(__file__).resolve().parents[1] / "validation"


def test_deviation_is_relative_to_the_reference_and_judged_against_the_tolerance():
    c = Comparison("q", measured=101.0, reference=100.0, uncertainty=0.005, tolerance=0.01)
    assert c.deviation == pytest.approx(0.01) and c.within
    assert not Comparison("q", 101.5, 100.0, 0.005, 0.01).within
    assert Comparison("q", -1.01, -1.0, 0.0, 0.02).deviation == pytest.approx(-0.01)


def test_printed_values_carry_half_a_unit_of_their_last_digit():
    assert half_unit("0.40") == pytest.approx(0.005)
    assert half_unit("0.0910e-3") == pytest.approx(0.00005e-3)
    assert half_unit("1457") == 0.5
    assert printed_comparison("q", 1.0, "0.40", 0.1).uncertainty == pytest.approx(0.0125)


def test_the_worst_point_is_the_one_closest_to_its_tolerance():
    large_but_loose = Comparison("a", 1.05, 1.0, 0.0, 0.10)  # half its tolerance
    small_but_tight = Comparison("b", 1.0009, 1.0, 0.0, 0.001)  # 90 % of it
    assert worst([large_but_loose, small_but_tight]) is small_but_tight


def test_render_gives_one_row_per_case_with_its_measured_numbers(tmp_path):
    row = dict(
        name="x", fidelity="analytic", reference="Q_max", source="Paper (2018) Table 1", points=7, within=7,
        worst="Q at 3 kN", deviation=-2.07e-4, uncertainty=3.43e-4, tolerance=3.43e-4, largest_deviation=2.07e-4,
        cost=9.24e-6, repeats=40, load=2.0,
    )  # fmt: skip
    lines = reference_table.render([row])
    assert lines[2] == (
        "| analytic | Q_max | Paper (2018) Table 1 | 7 | Q at 3 kN | -2.07e-04 | 3.43e-04 | 3.43e-04 | 7 of 7 | "
        "9.24 us (median of 40, load 2.0) |"
    )
    json.dumps(row)  # a case's row, as the result keeps it for the report


def imported_case_modules():
    """Names of the tests.cases modules the validation tests import (either import form)."""
    names = set()
    for path in VALIDATION.glob("test_*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("tests.cases"):
                parts = node.module.split(".")
                names.update(parts[2:3] or [alias.name for alias in node.names])
    return names


def test_every_case_is_asserted_by_a_validation_test():
    """The report renders no case that no test checks: each case's module is imported by a validation test."""
    imported = imported_case_modules()
    for case in CASES.values():
        assert case.compare.__module__.rsplit(".", 1)[1] in imported, case.name


def test_a_measured_case_is_plain_json_even_from_numpy_values():
    """What reference_table.measure returns for the report (docs/reports/reference_table.json): numpy results (a
    solver's film, a model's output) are converted, the cost is a median over repeats, and the report renders the
    result as written or as the list of rows an earlier run wrote."""
    comparisons = [Comparison("q", np.float64(1.001), 1.0, 0.001, np.float64(0.01))]
    case = ReferenceCase("n", "analytic", "r", "Paper (2018)", lambda: comparisons, lambda: lambda: None)
    result = json.loads(json.dumps(reference_table.measure({"n": case})))
    row = result["cases"][0]
    assert row["within"] == 1 and row["deviation"] == pytest.approx(0.001) and row["repeats"] >= 5
    assert [m["key"] for m in result["metrics"]] == ["n: largest relative deviation", "n: cost per evaluation"]
    assert reference_table.render(result) == reference_table.render([row])
