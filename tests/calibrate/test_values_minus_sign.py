"""A calibration's numbers written with a Unicode minus sign (U+2212, the hyphen U+2010, any
dash): a bare one is a number (in a column's unit, not SI), as quantity text reads it, and a
prior's bounds keep their sign."""

from __future__ import annotations

import pytest

from impactlab.calibrate import parse_parameter
from impactlab.calibrate import read_measurements as read
from impactlab.calibrate.values import bare, to_unit

MINUS, HYPHEN = "\u2212", "\u2010"


def test_a_bare_cell_with_a_minus_sign_is_in_its_columns_unit(tmp_path) -> None:
    path = tmp_path / "m.csv"
    path.write_text(
        "label,angle [deg],vx [cm/s],vy [cm/s],mu,e,e_sigma\n"
        f"a,20,{HYPHEN}30,{MINUS}141,0.2,0.45,0.02\n",
        encoding="utf-8",
    )
    m = read(path)
    assert m.inputs["vy"][0] == pytest.approx(-1.41, rel=1e-12)  # -141 cm/s, not -141 m/s
    assert m.inputs["vx"][0] == pytest.approx(-0.3, rel=1e-12)


def test_values_read_the_minus_sign() -> None:
    assert bare(f"{MINUS}141") and bare(f"{HYPHEN}0.5") and not bare(f"{MINUS}141 cm/s")
    assert to_unit(f"{MINUS}105", "kgf/mm^2", name="hb") == -105.0  # in the unit, not SI
    assert to_unit(f"{HYPHEN}2 um", "um", name="x") == pytest.approx(-2.0, rel=1e-12)
    p = parse_parameter("body_nu", f"uniform({HYPHEN}0.2, 0.4)")
    assert (p.low, p.high) == (-0.2, 0.4)  # +0.2 before: pint dropped the hyphen
