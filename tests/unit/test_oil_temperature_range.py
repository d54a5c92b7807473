"""The oil temperature against the range the lubricant file's data support ([temperature_range]): a warning once
per entry into the extrapolated range, in every fidelity (models.limits.OilTemperatureWatch).

iso_vg68_mineral: Walther's law through 40 and 100 C, read 40 K below and 20 K above (0-120 C, estimated); the
thesis turbine oil: characterised between 30 and 150 C (Wheeler 2016, section 3.2). The B7214C with 250 K oil
(inside the input range, -40..200 C, far below the file's data) gave 45 N.m and 45 kW without a word.
"""

import pytest

from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.params import ParameterError, load_lubricant

TEMPERATURES = (313.15, 250.0, 249.0, 313.15, 250.0, 400.0)  # K
WARNED = [False, True, False, False, True, False]  # an entry warns; staying out, or crossing to the other side, not


def _warned(warnings):
    return any("outside the temperature range of the data of lubricant 'iso_vg68_mineral'" in w for w in warnings)


def test_quasi_static_warns_once_per_entry():
    """B7214C with iso_vg68_mineral, the same temperature sequence: a warning at each entry, naming the
    temperature, the file's range [273.15, 393.15] K and that the laws are extrapolated."""
    model = QuasiStaticModel("B7214C", "iso_vg68_mineral")
    warned = []
    for T in TEMPERATURES:
        model.evaluate(omega=100.0, F_z=800.0, T_oil=T)
        warned.append(_warned(model.warnings))
    assert warned == WARNED
    model.evaluate(omega=100.0, F_z=800.0, T_oil=313.15)
    model.evaluate(omega=100.0, F_z=800.0, T_oil=260.0)
    assert any("T_oil = 260 K" in w and "[273.15, 393.15] K" in w and "extrapolated" in w for w in model.warnings)


def test_analytic_and_dem_warn_once_per_entry():
    """6208 with iso_vg68_mineral: 313 K, 250 K, 249 K, 313 K, 250 K, 400 K oil: the analytic and DEM fidelities warn
    at each entry into the range outside the file's data (250 K twice), not while staying out or back in."""
    analytic = AnalyticModel("6208", "iso_vg68_mineral")
    dem = DemModel("6208", "iso_vg68_mineral")
    warned_a, warned_d = [], []
    for k, T in enumerate(TEMPERATURES):
        analytic.evaluate(100.0, 1000.0, T)
        warned_a.append(_warned(analytic.warnings))
        dem.advance(1e-4 * (k + 1), omega=10.0, F_y=1000.0, T_oil=T)
        warned_d.append(_warned(dem.warnings))
    assert warned_a == WARNED
    assert warned_d == WARNED


def test_ranges_come_from_the_files():
    """The thesis oil's range is the characterisation's (30-150 C); a constant-property oil (the papers', given for
    its operating state) gives none, so it never warns; a file with half a range is refused."""
    thesis = load_lubricant("thesis_turbine_oil")
    assert (thesis.T_low, thesis.T_high) == (303.15, 423.15)
    papers = load_lubricant("guessasma_oil")
    assert papers.T_low is None and papers.T_high is None
    model = QuasiStaticModel("6208", "guessasma_oil")
    model.evaluate(omega=100.0, F_y=1000.0, T_oil=250.0)
    assert not any("temperature range" in w for w in model.warnings)


def test_half_a_range_is_refused(tmp_path):
    text = load_lubricant("iso_vg68_mineral").path
    broken = tmp_path / "oil.toml"
    content = open(text).read()
    broken.write_text(content[: content.index("T_high")])
    with pytest.raises(ParameterError, match=r"'temperature_range.T_high' = not given are not allowed: both given"):
        load_lubricant(str(broken))
