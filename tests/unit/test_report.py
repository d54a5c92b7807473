"""The report assembler (benchmarks/report.py): targets beside medians with the missed ones named, the
stability table from the cases' docstrings, and the run-to-run comparison."""

import json

import pytest

from benchmarks import common, report


@pytest.fixture
def reports(tmp_path, monkeypatch):
    folder = tmp_path / "docs" / "reports"
    folder.mkdir(parents=True)
    monkeypatch.setattr(common, "REPORTS", folder)
    monkeypatch.setattr(common, "METRICS", folder / "metrics.json")
    monkeypatch.setattr(report, "METRICS", folder / "metrics.json")
    monkeypatch.setattr(report, "REPORTS", folder)
    monkeypatch.setattr(report, "REPORT", tmp_path / "docs" / "report.md")
    return tmp_path


def test_targets_missed_are_named_and_met_ones_are_not(reports):
    common.record("closed_loop", "step / floor", 1.6, "1", kind="timing", target=1.5)
    common.record("dem_timing", "us per step", 1.0e-6, "s", kind="timing", target=1.2e-6)
    common.record("dem_error", "cage speed error", 0.001, "1", kind="error")
    report.assemble({}, {}, {}, 1.0)
    text = (reports / "docs" / "report.md").read_text()
    assert "| closed_loop | step / floor | 1.5 | 1.6 | 1.07 | **no** |" in text
    assert "| dem_timing | us per step | 1.2 us | 1 us | 0.83 | yes |" in text
    assert "- closed_loop, step / floor:" in text and "- dem_timing" not in text


def test_a_benchmark_run_again_forgets_its_old_entries(reports):
    common.record("solver_tolerance", "old key", 1.0, "1", kind="error")
    common.forget("solver_tolerance")
    common.record("solver_tolerance", "new key", 2.0, "1", kind="error")
    assert json.loads(common.METRICS.read_text()) == {
        "solver_tolerance": {"new key": dict(value=2.0, unit="1", kind="error", target=None, note="")}
    }


def test_reproduction_counts_exact_errors_and_timing_deviations():
    now = {"b": {"e": dict(value=0.5, kind="error"), "t": dict(value=1.2, kind="timing")}}
    before = {"b": {"e": dict(value=0.5, kind="error"), "t": dict(value=1.0, kind="timing")}}
    lines = report.reproduction_section(now, before, {"b"})
    assert lines[0] == "Errors and counts: 1 repeated exactly, 0 differ."
    assert "median deviation 20.0 %" in lines[2] and "All within." in lines[4]
    before["b"]["e"]["value"] = 0.4
    assert "1 differ" in report.reproduction_section(now, before, {"b"})[0]
    assert "nothing to compare" in report.reproduction_section(now, before, set())[0]


def test_timing_noise_band_widens_to_the_machines_measured_speed_spread():
    """A timing 1.6x slower is outside the same-state band of 1.3, but inside it when the reference workload
    itself ran 1.7x slower at some point of the two runs (the machine changed, not the code)."""
    now = {"b": {"t": dict(value=1.6, kind="timing")}}
    before = {"b": {"t": dict(value=1.0, kind="timing")}}
    assert "1 outside: b: t (x1.60)" in report.reproduction_section(now, before, {"b"})[4]
    now[report.MACHINE] = {"before b": dict(value=1.7e-3, kind="machine")}
    before[report.MACHINE] = {"before b": dict(value=1.0e-3, kind="machine")}
    line = report.reproduction_section(now, before, {"b"})[4]
    assert "within a factor 1.70" in line and "All within." in line


def test_stability_table_quotes_each_cases_outcome():
    from tests.stability.cases import CASES

    case, fidelities, path, function = CASES[0]
    lines = report.stability_section({(path, function): ("passed", 0.5)})
    row = next(line for line in lines if function in line)
    assert row.startswith(f"| {case} | {fidelities} | ") and "passed (0.5 s)" in row
    assert report.outcome_of(path, function) in row
