"""What a reference case measures: compared values with their deviation, the reference's own uncertainty
and the tolerance the validation test accepts, all relative to the reference value."""

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

DATA = Path(__file__).resolve().parents[2] / "tests" / "validation" / "data"  # transcribed sources


@dataclass(frozen=True)
class Comparison:
    """One value of the product (`measured`) against its reference value. `uncertainty`: the reference's own
    relative uncertainty (rounding of the printed value, spread of the published values); `tolerance`: the
    relative deviation the validation test accepts (its grounds are the case's; it can be below the rounding of a
    value printed with few digits where the other values of the case show the model closer)."""

    quantity: str
    measured: float
    reference: float
    uncertainty: float
    tolerance: float

    @property
    def deviation(self):
        """(measured - reference) / |reference|."""
        return (self.measured - self.reference) / abs(self.reference)

    @property
    def within(self):
        return abs(self.deviation) <= self.tolerance


@dataclass(frozen=True)
class ReferenceCase:
    """A reference case: `compare()` returns its comparisons; `evaluation()` builds the model once and returns
    a call without arguments doing one evaluation at the case's point (what the report times)."""

    name: str
    fidelity: str
    reference: str
    source: str
    compare: Callable[[], list]
    evaluation: Callable[[], Callable[[], object]]


def worst(comparisons):
    """The comparison closest to (or furthest beyond) its tolerance."""
    return max(comparisons, key=lambda c: abs(c.deviation) / c.tolerance if c.tolerance else float("inf"))


def half_unit(printed):
    """Half a unit in the last printed digit of a number written as `printed` (e.g. '0.0910e-3')."""
    mantissa, _, exponent = printed.strip().lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 0.5 * 10.0 ** (-decimals) * 10.0 ** (int(exponent) if exponent else 0)


def printed_comparison(quantity, measured, printed, tolerance):
    """A comparison with a printed reference value: its uncertainty is the rounding of the print."""
    value = float(printed)
    return Comparison(quantity, measured, value, half_unit(printed) / abs(value), tolerance)


def outside(comparisons):
    """The comparisons beyond their tolerance (what a validation test reports when it fails)."""
    return [c for c in comparisons if not c.within]
