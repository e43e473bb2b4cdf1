"""Empty fields of a measurements CSV: a trailing comma on every line (a column without a name
or a value) is left out, a row of empty fields (a spreadsheet's ",,,,,") is skipped as a blank
line, a value under a column without a name is refused naming the line and the field, and a
drop's error names its line in the file. Before, the first read "drop 1: unknown column ''; a
drop takes label, body, ..." and the second "drop 2 (drop 2): the drop needs 'angle'"."""

from __future__ import annotations

import re

import pytest

from impactlab.calibrate import Measurements, read_measurements

HEADER = "label,angle [deg],vy,mu,e,e_sigma"
A = "a,20,-1.4,0.2,0.4,0.02"
B = "b,45,-1.4,0.2,0.3,0.02"


def _write(tmp_path, *lines):
    path = tmp_path / "m.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_a_trailing_comma_on_every_line_is_read(tmp_path):
    m = read_measurements(_write(tmp_path, HEADER + ",", A + ",", B + ","))
    assert m.labels == ("a", "b")
    assert m.observed["e"].tolist() == [0.4, 0.3]


def test_a_row_of_empty_fields_is_skipped_as_a_blank_line(tmp_path):
    m = read_measurements(_write(tmp_path, HEADER, A, ",,,,,", " , ,,,,", B))
    assert m.labels == ("a", "b")


def test_a_value_under_a_column_without_a_name_names_the_line_and_field(tmp_path):
    path = _write(tmp_path, HEADER + ",", A + ",", B + ",x")
    with pytest.raises(ValueError, match="without a name") as info:
        read_measurements(path)
    assert str(info.value) == (
        f"{path}: line 3: field 7 holds 'x' under a column without a name (field 7 of the "
        "header, line 1, is empty): name the column, or remove the value (a comma too many?)"
    )


def test_a_drops_error_names_its_line(tmp_path):
    path = _write(tmp_path, "# drops of 2024", HEADER, A, "", "b,,-1.4,0.2,0.3,0.02")
    where = re.escape(str(path))
    needs = r"drop 2 \(b\): the drop needs 'angle'"
    with pytest.raises(ValueError, match=rf"^{where}: line 5: {needs}"):
        read_measurements(path)
    path = _write(tmp_path, HEADER, A, "b,45,-1.4,0.2,,")
    with pytest.raises(ValueError, match=rf"^{where}: line 3: drop 2 \(b\) has no measured value"):
        read_measurements(path)


def test_a_record_with_a_key_without_a_name_says_so():
    rec = {"": "", "label": "a", "angle": "20 deg", "vy": -1.4, "e": 0.4, "e_sigma": 0.02}
    with pytest.raises(ValueError, match=r"^drop 1: a column has an empty name \(''\)"):
        Measurements.from_records([rec])
