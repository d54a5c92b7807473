"""The variable lists of the documentation are generated from the declarations and cannot drift.

- each committed fmus/<Name>.md equals what `spindle build` writes from the declarations today, and the
  README's FMU block equals `python -m spindle.all_fmus readme`'s: a declaration changed without rebuilding
  the documentation fails here, with the command that fixes it;
- a built FMU exposes exactly the variables its fmus/<Name>.md lists, in the same order (value
  references follow registration order), with the same causality and unit.
"""

import re

import pytest
from fmpy import read_model_description

from bearing_fmu.build import variables_markdown
from spindle.all_fmus import README, README_BEGIN, README_END, all_variables, readme_block
from tests.conftest import FMU_DIR

ROW = re.compile(r"^\| `([^`]+)` \| (\w+) \| (\w+) \| ([^|]*) \|")


def documented(name):
    """(name, causality, type, unit) of each variable row of fmus/<name>.md."""
    rows = []
    for line in (FMU_DIR / f"{name}.md").read_text().splitlines():
        match = ROW.match(line)
        if match:
            rows.append((match[1], match[2], match[3], match[4].strip()))
    return rows


@pytest.mark.parametrize("arguments", all_variables(), ids=lambda a: a[0])
def test_fmu_variable_list_is_up_to_date(arguments):
    path = FMU_DIR / f"{arguments[0]}.md"
    assert path.is_file(), f"{path} missing: run `python -m spindle.all_fmus docs`"
    assert path.read_text() == variables_markdown(*arguments), f"{path} is stale: run `python -m spindle.all_fmus docs`"


def test_readme_variable_block_is_up_to_date():
    text = README.read_text()
    assert text.count(README_BEGIN) == 1 and text.count(README_END) == 1
    block = text[text.index(README_BEGIN) : text.index(README_END) + len(README_END)]
    assert block == readme_block(), "README.md's FMU variable block is stale: run `python -m spindle.all_fmus readme`"


@pytest.mark.parametrize(
    "fixture, name",
    [
        ("analytic_fmu", "BearingAnalytic"),
        ("bearing_fmu", "Bearing"),
        ("bearing_disp_fmu", "BearingDisp"),
        ("bearing_fixed_fmu", "BearingFixed"),
        ("dem_disp_fmu", "BearingDEMDisp"),
        ("spindle_thermal_fmu", "SpindleThermal"),
        ("spindle_thermal_fixed_fmu", "SpindleThermalFixed"),
    ],
)
def test_built_fmu_exposes_the_documented_variables(fixture, name, request):
    md = read_model_description(str(request.getfixturevalue(fixture)))
    exposed = [(v.name, v.causality, v.type, v.unit or "") for v in md.modelVariables]
    assert exposed == documented(name)


def test_names_with_a_comma_come_with_the_csv_quoting_note():
    """K[i,j] names contain a comma: each variable list that has one, and the README's FMU section, say how
    a CSV must write them; a list without such names does not."""
    from bearing_fmu.build import COMMA_NAMES_NOTE

    for arguments in all_variables():
        name, *_, parameters, inputs, outputs = arguments[:6]
        has_comma = any("," in v.name for v in (*parameters, *inputs, *outputs))
        assert (COMMA_NAMES_NOTE in variables_markdown(*arguments)) == has_comma, name
    assert COMMA_NAMES_NOTE in readme_block()
    assert '`"K[1,2]"`' in COMMA_NAMES_NOTE
