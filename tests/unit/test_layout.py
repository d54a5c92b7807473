"""The kernels' array layouts (bearing_fmu_common.layout): slots counted from their declarations."""

import importlib
import pkgutil
import re
from pathlib import Path

import pytest

import bearing_fmu.kernels
from bearing_fmu_common.layout import Layout

ROOT = Path(__file__).resolve().parents[2]


def test_slots_follow_each_other_by_their_widths():
    layout = Layout()
    assert (layout.slot(3), layout.slot(), layout.slot(2), layout.size) == (0, 3, 4, 6)


@pytest.mark.parametrize("width", [0, -1, 1.5])
def test_a_slot_has_a_positive_whole_width(width):
    with pytest.raises(ValueError, match="positive whole number"):
        Layout().slot(width)


def _kernel_modules():
    names = [m.name for m in pkgutil.walk_packages(bearing_fmu.kernels.__path__, "bearing_fmu.kernels.")]
    return [importlib.import_module(name) for name in names]


@pytest.mark.parametrize("module", _kernel_modules(), ids=lambda m: m.__name__)
def test_every_array_of_a_kernel_module_is_a_layout(module):
    """No slot number is written by hand: an array's `<PREFIX>SIZE` is the size of a Layout, and its slots are the
    layout's, each inside the array."""
    source = Path(module.__file__).read_text()
    assert not re.search(r"^[A-Z][A-Z0-9_]*_SIZE = \d", source, re.M), "a size written as a number"
    layouts = {name: value for name, value in vars(module).items() if isinstance(value, Layout)}
    sizes = {name: value for name, value in vars(module).items() if name.endswith("_SIZE") and isinstance(value, int)}
    own = re.findall(r"^([A-Z][A-Z0-9_]*_SIZE) = (_\w+)\.size", source, re.M)
    assert len(own) == len(re.findall(r"^([A-Z][A-Z0-9_]*_SIZE) = ", source, re.M))
    for size_name, layout_name in own:
        assert sizes[size_name] == layouts[layout_name].size
