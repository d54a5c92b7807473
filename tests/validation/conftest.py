"""Fixtures the validation tests share."""

import pytest

from tests.cases.cwru import bearing_file, rows


@pytest.fixture(scope="module")
def cwru_6205(tmp_path_factory):
    """The CWRU rig's drive-end 6205 (tests/validation/data/cwru_bearing_frequencies.csv) as a bearing file, its
    cage elements estimated from its pockets (bearing_file leaves out the template's cage-element radius, the
    6208's)."""
    row = next(r for r in rows() if r["bearing"].startswith("6205"))
    return bearing_file(row, tmp_path_factory.mktemp("cwru"))
