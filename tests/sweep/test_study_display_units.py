"""A study's repr and notebook table label each distribution parameter with its own unit: a
lognormal's sigma is the dimensionless spread of the log, the others are in the display unit of
their input, as grid and fixed inputs are."""

from __future__ import annotations

import re

import numpy as np

from impactlab.sweep import LogNormal, Normal, Sample, Study


def _study() -> Study:
    return Study(
        name="mc",
        grid={"angle": np.radians([10.0, 20.0])},
        fixed={"vy": -1.41, "flat_E": 200e9, "flat_nu": 0.3, "flat_brinell_hardness": 105},
        sample=Sample(
            size=50,
            seed=1,
            inputs={
                "flat_yield_strength": LogNormal(305e6, 0.08),
                "mu": Normal(0.2, 0.02),
                "vx": Normal(0.0, 0.02),
            },
        ),
    )


def _row(html: str, name: str) -> list[str]:
    rows = re.findall(r"<tr>(.*?)</tr>", html, flags=re.S)
    row = next(r for r in rows if name in r)
    return re.findall(r"<td[^>]*>(.*?)</td>", row)


def test_lognormal_sigma_has_no_unit_in_repr() -> None:
    text = repr(_study())
    assert "sample: flat_yield_strength[50] dist lognormal, median 305 MPa, sigma 0.08 (log)" in (
        text
    )
    assert "0.08 Pa" not in text and "0.08 MPa" not in text and "3.05e8" not in text
    assert "angle[2] 10 .. 20 deg" in text and "vy = -1.41 m/s" in text
    assert "sample: mu[50] dist normal, mean 0.2, std 0.02;" in text
    assert "sample: vx[50] dist normal, mean 0 m/s, std 0.02 m/s" in text


def test_lognormal_sigma_has_no_unit_in_html() -> None:
    cells = _row(_study()._repr_html_(), "flat_yield_strength")
    assert cells[-2:] == ["dist lognormal, median 305 MPa, sigma 0.08 (log)", "MPa"]


def test_sampled_angle_in_degrees_like_the_grid() -> None:
    st = Study(
        name="a",
        fixed={"vy": -1.41, "mu": 0.2},
        sample=Sample(size=10, seed=2, inputs={"angle": Normal(np.radians(20.0), np.radians(0.5))}),
    )
    assert "sample: angle[10] dist normal, mean 20 deg, std 0.5 deg" in repr(st)
    assert _row(st._repr_html_(), "angle")[-2:] == ["dist normal, mean 20 deg, std 0.5 deg", "deg"]
