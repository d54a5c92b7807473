"""The shaft model against ROSS on the same shafts: the cases, their tolerances (0.5 % on the frequencies, 1 % on the
critical speeds) and their grounds are in tests/cases/shaft_ross.py (the report's first table shows the same
comparisons). Here also the whirl: at speed each mode whirls as ROSS's (where ROSS finds the nodes whirling both
ways, 'Mixed', the model's amplitude-weighted sense is not compared), and each critical speed's mode does not whirl
backward in ROSS ("Mixed" on the cross-coupled seats: nodes whirl both ways)."""

import pytest

from spindle.shaft.model import WHIRL_AXIAL, WHIRL_BACKWARD, WHIRL_FORWARD
from tests.cases import Comparison, outside
from tests.cases import shaft_ross as case

pytestmark = pytest.mark.validation
pytest.importorskip("ross")  # installed by the test extra; skipped only where it could not be installed

ROSS_WHIRL = {"Forward": WHIRL_FORWARD, "Backward": WHIRL_BACKWARD}


@pytest.mark.parametrize("name", sorted(case.SHAFTS))
def test_natural_frequencies_and_whirl_match_ross(name):
    rows = case.matched_modes(name)
    comparisons = [
        Comparison(f"{rpm:g} rpm", f, f_ross, 0.0, case.FREQUENCY_TOLERANCE) for rpm, f, _, f_ross, _ in rows
    ]
    assert not outside(comparisons), outside(comparisons)
    for rpm in case.SPEEDS_RPM:
        assert sum(r[0] == rpm for r in rows) == 6  # six different ROSS modes at each speed
    for rpm, f, whirl, _, whirl_ross in rows:
        if rpm > 0.0 and whirl != WHIRL_AXIAL and whirl_ross != "Mixed":
            assert ROSS_WHIRL[whirl_ross] == whirl, (name, rpm, f)


@pytest.mark.slow  # ROSS's iteration: about a minute per shaft
@pytest.mark.parametrize("name", sorted(case.SHAFTS))
def test_critical_speeds_match_ross(name):
    rows = case.matched_critical_speeds(name)
    assert len(rows) == 2
    comparisons = [Comparison(f"{k}", s, r, 0.0, case.CRITICAL_TOLERANCE) for k, (s, r, _) in enumerate(rows)]
    assert not outside(comparisons), (name, rows)
    assert all(whirl != "Backward" for _, _, whirl in rows)
