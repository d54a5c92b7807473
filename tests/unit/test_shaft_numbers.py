"""The shaft file's numbers (spindle/shaft/params.py shaft_numbers, shaft_with_numbers): what the shaft FMUs take as
numeric parameters. A shaft rebuilt from a file's own numbers is the file's, bit for bit; a changed number gives the
shaft of the file with that number, the disks, seats and tool tip on the same nodes; a refused number is named as the
caller names it (an FMU parameter), with its value and what is allowed; numbers of another structure are refused."""

import numpy as np
import pytest

from bearing_fmu_common.paramfile import ParameterError
from spindle.shaft.params import DEFAULT_SHAFT, read_shaft, shaft_numbers, shaft_with_numbers
from tests.cases import shaft_beams as sb

FIELDS = ("z", "elements", "poisson", "disks", "seat_nodes", "seat_axes", "tip_node")


def numbers(name_or_path):
    return {(table, i, key): value for table, i, _, key, value in shaft_numbers(name_or_path)}


def assert_same_shaft(a, b):
    for field in FIELDS:
        assert np.array_equal(getattr(a, field), getattr(b, field)), field


def fmi_name(table, index, key):
    return f"shaft_data.{table}_{index + 1}.{key}"


def test_the_numbers_are_the_files_in_its_order():
    rows = shaft_numbers(DEFAULT_SHAFT)
    assert rows[:4] == [
        ("material", 0, "steel", "youngs_modulus", 210e9),
        ("material", 0, "steel", "poisson_ratio", 0.3),
        ("material", 0, "steel", "density", 7850.0),
        ("section", 0, "nose", "length", 0.03),
    ]
    assert len(rows) == 3 + 5 * 3 + 2 * 3
    assert rows[-1] == ("disk", 1, "drive_coupling", "diametral_inertia", 6.08e-4)


def test_the_files_own_numbers_give_the_file_bit_for_bit():
    assert_same_shaft(shaft_with_numbers(DEFAULT_SHAFT, numbers(DEFAULT_SHAFT)), read_shaft(DEFAULT_SHAFT))


def test_a_changed_length_keeps_the_disks_seats_and_tip_on_their_nodes(tmp_path):
    """Section 2 from 0.3 m to 0.4 m: the file written with 0.4 m and its disk and seat moved with their nodes."""
    before = sb.shaft_file(
        tmp_path / "a.toml", [(0.2, 0.05, 0.0, 4), (0.3, 0.06, 0.01, 6)], [(0.5, 2.0, 1e-3, 2e-3)], (0.1, 0.35)
    )
    after = sb.shaft_file(
        tmp_path / "b.toml", [(0.2, 0.05, 0.0, 4), (0.4, 0.06, 0.01, 6)], [(0.6, 2.0, 1e-3, 2e-3)], (0.1, 0.4)
    )
    changed = numbers(before) | {("section", 1, "length"): 0.4}
    assert_same_shaft(shaft_with_numbers(before, changed), read_shaft(after))


def test_a_changed_disk_and_material_are_the_files_with_them(tmp_path):
    path = sb.default_shaft_with(tmp_path / "heavy.toml", "value = 1.5, unit", "value = 4.0, unit")
    assert_same_shaft(shaft_with_numbers(DEFAULT_SHAFT, numbers(DEFAULT_SHAFT) | {("disk", 0, "mass"): 4.0}),
                      read_shaft(path))  # fmt: skip
    path = sb.default_shaft_with(tmp_path / "soft.toml", "value = 210.0e9", "value = 70.0e9")
    changed = numbers(DEFAULT_SHAFT) | {("material", 0, "youngs_modulus"): 70e9}
    assert_same_shaft(shaft_with_numbers(DEFAULT_SHAFT, changed), read_shaft(path))


def test_a_material_given_by_its_shear_modulus_takes_a_poisson_ratio(tmp_path):
    """The file's shear modulus is replaced by the Poisson's ratio it implies (E / (2 G) - 1), to rounding."""
    path = sb.default_shaft_with(
        tmp_path / "g.toml",
        'poisson_ratio  = { value = 0.3, unit = "-"',
        'shear_modulus  = { value = 80.0e9, unit = "Pa"',
    )
    values = numbers(path)
    assert values["material", 0, "poisson_ratio"] == 210e9 / (2.0 * 80e9) - 1.0
    rebuilt, read = shaft_with_numbers(path, values), read_shaft(path)
    assert np.allclose(rebuilt.elements, read.elements, rtol=1e-15, atol=0.0)


@pytest.mark.parametrize(
    "key,value,message",
    [
        (
            ("section", 2, "inner_diameter"),
            0.075,
            "shaft_data.section_3.inner_diameter = 0.075 m must be below shaft_data.section_3.outer_diameter = 0.075 "
            "m (section 'between_bearings'); allowed: an inner diameter in [0, 0.075[ m",
        ),
        (
            ("section", 0, "length"),
            0.0,
            "shaft_data.section_1.length = 0.0 m is outside the allowed range ]0.0, 10.0]",
        ),
        (
            ("material", 0, "poisson_ratio"),
            0.6,
            "shaft_data.material_1.poisson_ratio = 0.6 - is outside the allowed range ]0.0, 0.5]",
        ),
        (("disk", 1, "mass"), -1.0, "shaft_data.disk_2.mass = -1.0 kg is outside the allowed range [0.0, 10000.0]"),
    ],
)
def test_a_refused_number_is_named_as_the_caller_names_it(key, value, message):
    with pytest.raises(ParameterError) as refused:
        shaft_with_numbers(DEFAULT_SHAFT, numbers(DEFAULT_SHAFT) | {key: value}, fmi_name)
    assert message in str(refused.value)


def test_a_file_refusal_names_the_table_entry(tmp_path):
    path = sb.default_shaft_with(tmp_path / "bad.toml", "value = 0.126, unit", "value = 12.0, unit")
    with pytest.raises(ParameterError, match=r"section\[2\]\.length = 12.0 m is outside the allowed range"):
        read_shaft(path)


def test_numbers_of_another_structure_are_refused(tmp_path):
    other = sb.shaft_file(tmp_path / "other.toml", [(0.3, 0.05, 0.0, 6)], seats=(0.1, 0.2))
    with pytest.raises(ParameterError, match="entries material 1, section 5, disk 2; the file has material 1, "
                       "section 1, disk 0: allowed, a file with as many"):  # fmt: skip
        shaft_with_numbers(other, numbers(DEFAULT_SHAFT))
