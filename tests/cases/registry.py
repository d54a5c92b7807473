"""Every reference case, in the order of the report's table: what every fidelity shares, then the fidelities
from the cheapest, then the numerical EHL solver (the films' reference), then the spindle shaft."""

from . import (
    cwru,
    dem_6208,
    ehl_annexe_d,
    guessasma_6208,
    hertz_thesis,
    lubricant_and_rating,
    shaft_closed_form,
    shaft_ross,
    thrust_218,
)

ORDERED = (
    hertz_thesis.CASE,
    *lubricant_and_rating.CASES,
    *guessasma_6208.CASES[:3],
    cwru.CASES[0],
    *guessasma_6208.CASES[3:],
    cwru.CASES[1],
    thrust_218.CASE,
    *dem_6208.CASES,
    ehl_annexe_d.CASE,
    shaft_closed_form.CASE,
    *shaft_ross.CASES,
)
CASES = {case.name: case for case in ORDERED}
