"""The serialised FMU state (bearing_fmu_common/runtime/fmi2_layer.py, docs/fmu_runtime.md "FMU state"): named
values written with their type, dtype and shape, never pickle.

- the state of every FMU kind (the slaves of the five bearing scenes and of both thermal FMUs, run in this
  process) goes through the format with every value's type and bits kept, and an instance restored from the
  bytes continues bit for bit as the one that saved them;
- bytes saved by another version or another FMU are refused naming both; truncated or altered bytes, an empty
  string and a pickle are refused, and the pickle's code is not run;
- a value the format cannot hold exactly is refused when the state is serialised, naming its entry.
"""

import hashlib
import json
import pickle
import struct
import tomllib

import numpy as np
import pytest

from bearing_fmu import fmu as bearing_slaves
from bearing_fmu.build import SCENES_DIR
from bearing_fmu.scene import Scene
from bearing_fmu_common.runtime import fmi2_layer as layer
from spindle.thermal.fmu import SpindleThermal
from tests.fmu.harness import PickleMarker

VERSION = "0.1.0"


def slave_kinds():
    """(FMU name, slave class as the build makes it, communication step in s) of every FMU kind."""
    kinds = []
    for path in sorted(SCENES_DIR.glob("*.toml")):
        doc = tomllib.loads(path.read_text())
        base = getattr(bearing_slaves, doc["fmu"]["slave"])
        attributes = {"scene": Scene.from_dict(doc["scene"]), "version": VERSION}
        step = 0.5e-3 if doc["scene"]["fidelity"] == "dem" else 1.0
        kinds.append((doc["fmu"]["name"], type(doc["fmu"]["name"], (base,), attributes), step))
    for name, axial in (("SpindleThermal", False), ("SpindleThermalFixed", True)):
        kinds.append((name, type(name, (SpindleThermal,), {"axial_float": axial, "version": VERSION}), 60.0))
    return kinds


KINDS = slave_kinds()


def started(cls, step, steps=2):
    slave = cls(instance_name="state")
    assert slave.exit_initialization_mode() is True
    for n in range(steps):
        assert slave.do_step(n * step, step)
    return slave


def assert_identical(a, b, path="state"):
    """a and b the same nested values: same types, same keys in the same order, same bits."""
    assert type(a) is type(b), (path, type(a), type(b))
    if isinstance(a, dict):
        assert list(a) == list(b), path
        for key in a:
            assert_identical(a[key], b[key], f"{path}/{key}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for k, (x, y) in enumerate(zip(a, b)):
            assert_identical(x, y, f"{path}[{k}]")
    elif isinstance(a, (np.ndarray, np.generic)):
        assert (a.dtype, a.shape, a.tobytes()) == (b.dtype, b.shape, b.tobytes()), path
    elif isinstance(a, float):
        assert struct.pack("<d", a) == struct.pack("<d", b), (path, a, b)
    else:
        assert a == b, path


def bits(values):
    return [struct.pack("<d", float(v)) for v in values]


@pytest.mark.parametrize("name, cls, step", KINDS, ids=[k[0] for k in KINDS])
def test_every_fmu_kind_round_trips_and_continues_bit_for_bit(name, cls, step):
    slave = started(cls, step)
    state = (4, 2 * step, slave._get_fmu_state())
    data = layer.dumps(state, slave)
    assert data.startswith(layer.STATE_MAGIC)
    restored = layer.loads(data, slave)
    assert not isinstance(restored, str), restored
    assert restored[:2] == (4, 2 * step)
    assert_identical(state[2], restored[2])
    assert slave.do_step(2 * step, step)
    expected = bits(slave._y)
    fresh = cls(instance_name="restored")
    assert fresh.exit_initialization_mode() is True
    fresh._set_fmu_state(restored[2])
    assert fresh.do_step(2 * step, step)
    assert bits(fresh._y) == expected


@pytest.fixture(scope="module")
def analytic():
    """A started BearingAnalytic slave and the bytes of its state."""
    name, cls, step = KINDS[0]
    assert name == "BearingAnalytic"
    slave = started(cls, step)
    return slave, layer.dumps((4, 2.0, slave._get_fmu_state()), slave)


def resaved(data, **identity):
    """`data` saved again with the header fields `identity` changed (another version, another FMU)."""
    header, _ = layer._header(data)
    saved = {key: header[key] for key in ("model", "version", "variables")}
    return layer.pack(layer.unpack(data), {**saved, **identity})


def test_a_state_of_another_version_is_refused_naming_both(analytic):
    slave, data = analytic
    why = layer.loads(resaved(data, version="0.0.9"), slave)
    assert isinstance(why, str)
    assert "saved by BearingAnalytic version 0.0.9" in why and "this FMU is BearingAnalytic version 0.1.0" in why


def test_a_state_of_another_fmu_is_refused_naming_both(analytic):
    slave, data = analytic
    assert "saved by Bearing version 0.1.0" in layer.loads(resaved(data, model="Bearing"), slave)
    other_variables = layer.loads(resaved(data, variables="0123456789abcdef"), slave)
    assert "(variables 0123456789abcdef)" in other_variables and "this FMU is BearingAnalytic" in other_variables


@pytest.mark.parametrize(
    "damage, message",
    [
        (lambda d: d[:-1], "do not match their SHA-256 checksum"),
        (lambda d: d[: len(d) // 2], "do not match their SHA-256 checksum"),
        (lambda d: d[:30], "truncated: 30 bytes"),
        (lambda d: b"", "not a serialised FMU state of this product"),
        (lambda d: d[:-100] + bytes([d[-100] ^ 1]) + d[-99:], "do not match their SHA-256 checksum"),
        (lambda d: d[:22] + struct.pack("<I", 2) + d[26:], "format version 2, this FMU reads format version 1"),
    ],
    ids=["last byte cut", "half", "30 bytes", "empty", "one bit flipped", "another format"],
)
def test_truncated_or_altered_bytes_are_refused(analytic, damage, message):
    slave, data = analytic
    why = layer.loads(damage(data), slave)
    assert isinstance(why, str) and message in why


def test_a_pickle_is_refused_and_not_run(analytic, tmp_path):
    slave, _ = analytic
    marker = tmp_path / "ran"
    payload = pickle.dumps((4, 0.0, {"x": PickleMarker(marker)}))
    why = layer.loads(payload, slave)
    assert isinstance(why, str) and "not a serialised FMU state of this product" in why
    assert not marker.exists()


def test_a_consistent_header_that_lies_about_its_data_is_refused(analytic):
    """Bytes with a valid checksum whose header does not describe their data (written by something else than
    this layer) are refused, not read past their end."""
    slave, data = analytic
    header, start = layer._header(data)
    header["floats"] += 1
    head = json.dumps(header).encode()
    body = layer.STATE_MAGIC + struct.pack("<II", 1, len(head)) + head + data[start:-32]
    why = layer.loads(body + hashlib.sha256(body).digest(), slave)
    assert isinstance(why, str) and "corrupted" in why


@pytest.mark.parametrize(
    "value, what",
    [([1, 2.5], "list of dtype float64"), ([[1.0], [2.0, 3.0]], "list of dtype object"), (object(), "object")],
    ids=["mixed list", "ragged list", "object"],
)
def test_a_value_without_exact_representation_is_refused_naming_it(value, what):
    with pytest.raises(TypeError, match=f"entry /slave/_solver_state/bad: .*{what}"):
        layer.pack({"slave": {"_solver_state": {"bad": value}}}, {"model": "M", "version": "1", "variables": "0"})


def test_values_keep_their_types_and_bits():
    values = {
        "nan": struct.unpack("<d", struct.pack("<Q", 0x7FF8000000000123))[0],  # a NaN with a payload
        "negative zero": -0.0,
        "big int": 2**70,
        "flags": [True, False],
        "numpy scalar": np.float64(1.5),
        "ints": np.arange(6, dtype=np.int32).reshape(2, 3),
        "empty": [],
        "nothing": None,
        "text": "6208 / 'ISO VG 68'",
        "nested": {"empty": {}, "matrix": [[1.0, 2.0], [3.0, 4.0]]},
    }
    identity = {"model": "M", "version": "1", "variables": "0"}
    assert_identical(values, layer.unpack(layer.pack(values, identity), identity))
