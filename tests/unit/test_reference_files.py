"""A rebuild leaves a tracked reference result alone when it computes the same values to within
bearing_fmu.build.REFERENCE_RTOL (the last digits of the linear algebra differ between CPUs), and rewrites it
when a value moved beyond that or the columns changed."""

from bearing_fmu.build import REFERENCE_RTOL, csv_text, reference_cell, write_reference_if_changed


def _text(value, name="T"):
    return csv_text([{"time": 0.0, name: 1.0}, {"time": 60.0, name: value}], reference_cell)


def test_last_digit_differences_leave_the_file_alone(tmp_path):
    path = tmp_path / "X_ref.csv"
    path.write_bytes(_text(73.30972305490559).encode())
    before = path.read_bytes()
    kept = write_reference_if_changed(path, _text(73.3097230549032))  # 3.3e-14 relative apart
    assert path.read_bytes() == before and kept == before.decode()


def test_a_changed_value_or_column_is_written(tmp_path):
    path = tmp_path / "X_ref.csv"
    path.write_bytes(_text(100.0).encode())
    moved = _text(100.0 * (1 + 100 * REFERENCE_RTOL))
    assert write_reference_if_changed(path, moved) == moved and path.read_bytes() == moved.encode()
    renamed = _text(100.0, name="T_ir")
    write_reference_if_changed(path, renamed)
    assert path.read_bytes() == renamed.encode()
    longer = renamed + "120.0,1.0\r\n"
    write_reference_if_changed(path, longer)
    assert path.read_bytes() == longer.encode()


def test_a_missing_file_is_written(tmp_path):
    path = tmp_path / "X_ref.csv"
    assert write_reference_if_changed(path, _text(2.0)) == _text(2.0) and path.read_bytes() == _text(2.0).encode()
