"""A column's unit that is no unit of it (a CSV header's, a TOML key's or a ``[units]``
entry's) is refused once, where it is written: the header's line, naming the column and the
unit text, with a unit the column takes (formerly it was glued to each row's number and the
error quoted text such as '60 10 um' on the first data line)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from impactlab.calibrate import Measurements, read_measurements

ROW = "a,20,-1.41,60,1"


def _csv(tmp_path: Path, column: str, comment: str = "") -> Path:
    path = tmp_path / "m.csv"
    path.write_text(f"{comment}label,angle [deg],vy [m/s],{column},delta_p_sigma [um]\n{ROW}\n")
    return path


@pytest.mark.parametrize(
    ("column", "match"),
    [
        ("delta_p [10 um]",
         r"m.csv: line 1: column 'delta_p \[10 um\]': '10 um' is not a unit: it holds a number "
         r"\(.*\); delta_p takes a unit convertible to m, e.g. 'delta_p \[um\]'$"),
        ("delta_p [blarg]",
         r"line 1: column 'delta_p \[blarg\]': 'blarg' is not a unit \('blarg' is not defined.*\); "
         r"delta_p takes a unit convertible to m"),
        ("delta_p [um] [mm]",
         r"line 1: column 'delta_p \[um\] \[mm\]': 'um\] \[mm' is not a unit: it holds a bracket"),
        ("delta_p [m/s]",
         r"line 1: column 'delta_p \[m/s\]': 'm/s' has the wrong dimension; delta_p takes a unit "
         r"convertible to m, e.g. 'delta_p \[um\]'"),
        ("delta_p [%]",
         r"line 1: column 'delta_p \[%\]': '%' is percent, and only a fraction \(e, .*\) may be"),
        ("delta_p [-]",
         r"line 1: column 'delta_p \[-\]': '-' marks a plain number, without a unit; delta_p "
         r"takes a unit convertible to m, e.g. 'delta_p \[um\]'$"),
        ("delta_p [1]", r"column 'delta_p \[1\]': '1' marks a plain number, without a unit; "),
        ("e [deg]",
         r"line 1: column 'e \[deg\]': 'deg' is a unit, where a plain number is expected; e takes "
         r"no unit \(a fraction of 1: the header 'e'\) or percent, e.g. 'e \[%\]'"),
        ("flat_nu [MPa]", r"column 'flat_nu \[MPa\]': .*flat_nu takes no unit \(a plain number"),
        ("flat_yield_strength [HB]",
         r"column 'flat_yield_strength \[HB\]': 'HB' is a Brinell hardness's unit, not one of Pa"),
        ("body [m]", r"line 1: column 'body \[m\]': body is not a quantity, so it takes no unit"),
        ("correlation_e_delta_p [%]",
         r"line 1: column 'correlation_e_delta_p \[%\]': a correlation coefficient .* takes no "
         r"unit"),
    ],
)  # fmt: skip
def test_a_bad_header_unit_is_refused_on_the_header_line(tmp_path: Path, column: str, match: str):
    with pytest.raises(ValueError, match=match) as info:
        read_measurements(_csv(tmp_path, column))
    assert "line 2" not in str(info.value) and "\n" not in str(info.value)


def test_the_header_line_is_the_file_line(tmp_path: Path) -> None:
    """Comment lines before the header are counted."""
    path = _csv(tmp_path, "delta_p [10 um]", comment="# made by hand\n# second note\n")
    with pytest.raises(ValueError, match=r"m.csv: line 3: column 'delta_p \[10 um\]'"):
        read_measurements(path)


@pytest.mark.parametrize(
    ("column", "value", "si"),
    [("delta_p [um]", "60", 60e-6), ("delta_p [ mm ]", "0.06", 60e-6), ("delta_p []", "6e-5", 6e-5),
     ("e [%]", "45", 0.45), ("e [1]", "0.45", 0.45), ("e [-]", "0.45", 0.45),
     ("spin_out [rpm]", "-60", -2 * math.pi),
     ("duration [ms]", "0.2", 2e-4)],
)  # fmt: skip
def test_good_header_units_read_as_before(tmp_path: Path, column: str, value: str, si: float):
    name = column.split("[")[0].strip()
    path = tmp_path / "m.csv"
    path.write_text(
        f"label,angle [deg],vy [m/s],{column},{name}_sigma\n"
        f"a,20,-1.41,{value},{abs(float(value)) / 10}\n"
    )
    m = read_measurements(path)
    assert m.observed[name][0] == pytest.approx(si)
    assert m.sigma[name][0] == pytest.approx(abs(si) / 10)
    path.write_text(
        "label,angle [deg],vy [m/s],e,e_sigma,flat_brinell_hardness [HB]\n"
        "a,20,-1.41,0.45,0.02,105\n"
    )
    assert read_measurements(path).inputs["flat_brinell_hardness"][0] == 105.0


def test_a_toml_key_and_a_units_entry_are_checked_too(tmp_path: Path) -> None:
    drop = '[[drop]]\nlabel = "a"\nangle = "20 deg"\nvy = -1.41\n'
    path = tmp_path / "m.toml"
    path.write_text(drop + '"delta_p [10 um]" = 60\ndelta_p_sigma = "1 um"\n')
    with pytest.raises(ValueError, match=r"m.toml: drop 1: column 'delta_p \[10 um\]': '10 um' "
                       "is not a unit: it holds a number"):  # fmt: skip
        read_measurements(path)
    path.write_text(drop + 'delta_p = 60\ndelta_p_sigma = 1\n[units]\ndelta_p = "10 um"\n')
    with pytest.raises(ValueError, match=r"m.toml: \[units\] delta_p = '10 um': '10 um' is not a "
                       r"unit: .*e.g. 'delta_p = \"um\"'"):  # fmt: skip
        read_measurements(path)
    with pytest.raises(ValueError, match=r"drop 1: column 'e \[deg\]': 'deg' is a unit"):
        Measurements.from_records([{"label": "a", "angle": "20 deg", "vy": -1.41,
                                    "e [deg]": 0.4, "e_sigma": 0.02}])  # fmt: skip


def test_a_plain_number_mark_in_the_units_table_reads_as_no_unit(tmp_path: Path) -> None:
    """``[units] e = "-"`` is the header ``e [-]``: a plain number (engineering's mark)."""
    path = tmp_path / "m.toml"
    drop = '[[drop]]\nlabel = "a"\nangle = "20 deg"\nvy = -1.41\ne = 0.45\ne_sigma = 0.02\n'
    path.write_text(drop + '[units]\ne = "-"\ne_sigma = "1"\n')
    m = read_measurements(path)
    assert (m.observed["e"][0], m.sigma["e"][0]) == (0.45, 0.02)
    csv = tmp_path / "m.csv"
    csv.write_text("label,angle [deg],vy [m/s],flat_nu [-],e,e_sigma\na,20,-1.41,0.3,0.45,0.02\n")
    assert read_measurements(csv).inputs["flat_nu"][0] == 0.3
    path.write_text(drop.replace("e = 0.45", "delta_p = 60") + '[units]\ndelta_p = "-"\n')
    with pytest.raises(ValueError, match=r"\[units\] delta_p = '-': '-' marks a plain number"):
        read_measurements(path)
