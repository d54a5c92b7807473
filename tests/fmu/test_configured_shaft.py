"""Configured shaft FMUs (`spindle build --config`, docs/parameters.md, "Configured FMUs"): a configuration's `shaft`
builds SpindleShaft_<name>.fmu and SpindleShaftTransient_<name>.fmu whose start values are that shaft (the String
`shaft` and the numeric shaft_data.* parameters), each passing `spindle check` against its own reference result and
running, with no parameter set, as the generic FMU given that shaft; a shaft the catalogue lacks is refused naming
the catalogue's shafts."""

import numpy as np
import pytest
from fmpy import simulate_fmu

from spindle.configured import ConfigurationError, build_configured, read_configuration
from tests.conftest import ROOT

OMEGA = 1047.1975511965977  # rad/s, 10 000 rpm
SHAFT_FMUS = ("SpindleShaft", "SpindleShaftTransient")


@pytest.fixture(scope="module")
def configured(tmp_path_factory):
    """The rig's configuration with its shaft, only the two shaft FMUs: name -> path."""
    out = tmp_path_factory.mktemp("configured_shaft")
    config = out / "rabreau_rig.toml"
    config.write_text((ROOT / "configs" / "rabreau_rig.toml").read_text() + f"fmus = {list(SHAFT_FMUS)!r}\n")
    paths, notes = build_configured(config, out)
    assert notes == []
    return {p.stem: p for p in paths}


def test_a_configured_shaft_fmu_is_built_per_shaft_fmu_and_passes_its_check(configured):
    from spindle.check import check_fmu

    assert sorted(configured) == ["SpindleShaftTransient_B7214C", "SpindleShaft_B7214C"]
    for name, path in configured.items():
        assert path.with_name(f"{name}_shaft.toml").is_file() and path.with_name(f"{name}.md").is_file()
        result = check_fmu(path)
        assert result.differences == [], name
    assert check_fmu(configured["SpindleShaftTransient_B7214C"]).outputs == 25  # the time domain's own experiment


@pytest.mark.parametrize("switch", [{}, {"shaft_from_file": False}])
def test_a_configured_shaft_fmu_without_parameters_runs_its_shaft(configured, spindle_shaft_fmu, switch):
    generic = simulate_fmu(
        str(spindle_shaft_fmu),
        stop_time=0.5,
        output_interval=0.25,
        start_values={"shaft": "rabreau_b7214c", "omega": OMEGA},
    )
    path = configured["SpindleShaft_B7214C"]
    ours = simulate_fmu(str(path), stop_time=0.5, output_interval=0.25, start_values={**switch, "omega": OMEGA})
    assert generic.dtype.names == ours.dtype.names
    assert [n for n in generic.dtype.names if not np.array_equal(generic[n], ours[n])] == []


def test_a_shaft_the_catalogue_lacks_is_refused_naming_the_catalogue(tmp_path):
    config = tmp_path / "rig.toml"
    config.write_text('[configuration]\nname = "X"\nshaft = "no_such_shaft"\n')
    with pytest.raises(
        ConfigurationError, match=r"shaft = 'no_such_shaft' is not a shaft of the catalogue \(rabreau_b7214c"
    ):
        read_configuration(config)
