"""The lubricant laws and the ISO 281 rating, which every fidelity shares.

- Thesis turbine oil (lubricant 2): the modified WLF law and the Murnaghan density with the thesis' constants
  (Wheeler 2016, Tables 2.1-3) against the values the thesis quotes at 313 K (Table 2.2-1): mu0 = 0.00795 Pa.s,
  alpha* = 20.2 GPa^-1, rho0 = 863 kg/m^3.
- The 6208's dynamic rating C_r by ISO 281:2007 from its published internal geometry (Guessasma & Machado 2018
  Table 1: Z = 9, D = 12.6 mm, d_m = 60.6 mm) against the makers' published ratings (30.7 and 32.5 kN,
  tests/validation/data/rating_life_cases.csv and its README): compared with the middle of that band, its
  half-width the reference's uncertainty and the tolerance. ISO 281 gives the rating of a bearing of the
  standard's reference quality; makers publish ratings with their own factors (SKF: its Explorer class
  'require[s] adjusted factors to calculate the dynamic load ratings in accordance with ISO 281:2007', skf.com,
  Load ratings), so the published values of one size differ by 6 % and the geometric value can only be expected
  inside that spread.
"""

import csv
import tomllib

from bearing_fmu.kernels import rating_life as rl
from bearing_fmu.kernels.lubricant import murnaghan_density, wlf_alpha_star, wlf_viscosity
from bearing_fmu.params import CATALOGUE, load_bearing

from .comparison import DATA, Comparison, ReferenceCase, printed_comparison

T_THESIS = 313.0  # K


def lubricant_2():
    """(WLF constants, density constants) of the thesis' lubricant 2 from the product's lubricant file."""
    with open(CATALOGUE / "lubricants" / "thesis_turbine_oil.toml", "rb") as fh:
        doc = tomllib.load(fh)
    wlf = {k: v["value"] for k, v in doc["lubricant_2_wlf"].items()}
    return wlf, {k: v["value"] for k, v in doc["density"].items() if isinstance(v, dict)}


WLF_ARGS = ("mu_G", "T_g0", "A_1", "A_2", "b_1", "b_2", "C_1", "C_2")
DENSITY_ARGS = ("rho_R", "T_R", "a_v", "beta_K", "K_MM", "K_M_prime")


def viscosity(w):
    return wlf_viscosity(0.0, T_THESIS, *(w[k] for k in WLF_ARGS))


def lubricant_comparisons():
    """mu0 within 0.5 % (the constants are printed with 4-5 digits; C1 and C2 act exponentially); rho0 within
    0.2 %; alpha* within 1.5 %: 1 % above the printed value, more than rounding explains, likely the thesis' own
    fit or integration range, which it does not state (a known discrepancy, stated, not hidden)."""
    w, d = lubricant_2()
    return [
        printed_comparison("mu0 at 313 K (Pa.s)", viscosity(w), "0.00795", 0.005),
        printed_comparison(
            "alpha* at 313 K (1/Pa)", wlf_alpha_star(T_THESIS, *(w[k] for k in WLF_ARGS)), "20.2e-9", 0.015
        ),
        printed_comparison(
            "rho0 at 313 K (kg/m^3)", murnaghan_density(0.0, T_THESIS, *(d[k] for k in DENSITY_ARGS)), "863", 0.002
        ),
    ]


def lubricant_evaluation():
    w, d = lubricant_2()
    return lambda: viscosity(w)


def published_ratings():
    with open(DATA / "rating_life_cases.csv") as fh:
        rows = csv.reader(line for line in fh if not line.startswith("#"))
        return [float(r[2]) for r in rows if r[0] == "6208" and r[1] == "C_r"]


def dynamic_rating(bearing=None):
    b = bearing or load_bearing("6208")
    return rl.iso281_dynamic_rating(b.Z, b.D, b.dm, 0.0)


def rating_evaluation():
    bearing = load_bearing("6208")
    return lambda: dynamic_rating(bearing)


def rating_comparisons():
    ratings = published_ratings()
    middle, half = 0.5 * (max(ratings) + min(ratings)), 0.5 * (max(ratings) - min(ratings))
    return [Comparison("6208 C_r (N)", dynamic_rating(), middle, half / middle, half / middle)]


CASES = (
    ReferenceCase(
        "lubricant_2",
        "every fidelity (lubricant laws)",
        "viscosity, pressure-viscosity coefficient, density at 313 K",
        "Wheeler (2016) thesis, Tables 2.1-3 and 2.2-1",
        lubricant_comparisons,
        lubricant_evaluation,
    ),
    ReferenceCase(
        "rating_6208",
        "every fidelity (ISO 281 rating)",
        "6208 dynamic rating C_r from its geometry",
        "ISO 281:2007; NTN and SKF catalogue ratings of the 6208",
        rating_comparisons,
        rating_evaluation,
    ),
)
