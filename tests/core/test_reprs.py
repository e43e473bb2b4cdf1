"""Notebook reprs: bodies, materials, contact laws and studies show readable summaries,
not ``<... object at 0x...>`` or every axis value."""

from __future__ import annotations

import re

import numpy as np
import pytest

from impactlab.bodies import FlexibleRod, Rod, Sphere
from impactlab.contact import get_law, law_names
from impactlab.materials import AISI_201, AISI_1010, ContactPair
from impactlab.sweep import Normal, Sample, Study


def _cells(html: str) -> list[str]:
    return re.findall(r"<td[^>]*>(.*?)</td>", html)


def test_material_html_in_display_units() -> None:
    cells = _cells(AISI_1010._repr_html_())
    row = cells.index("yield_strength")
    assert cells[row : row + 3] == ["yield_strength", "305", "MPa"]
    row = cells.index("E")
    assert cells[row : row + 3] == ["E", "200", "GPa"]


def test_pair_html_shows_derived_moduli() -> None:
    cells = _cells(ContactPair(AISI_201, AISI_1010)._repr_html_())
    assert "E_star" in cells and "G_star" in cells
    assert "AISI 1010 low-carbon steel (paper&#x27;s flat)" in cells


@pytest.mark.parametrize(
    ("body", "title", "field"),
    [
        (Rod.paper(), "Rod", "tip_radius"),
        (Sphere(0.01), "Sphere", "inertia"),
        (FlexibleRod.paper(), "FlexibleRod", "n_bending"),
    ],
)
def test_body_html(body: object, title: str, field: str) -> None:
    html = body._repr_html_()  # type: ignore[attr-defined]
    assert f"<th>{title}</th>" in html and field in _cells(html)
    assert "object at 0x" not in html and "material" in _cells(html)


@pytest.mark.parametrize("name", law_names())
def test_law_repr_and_html(name: str) -> None:
    law = get_law(name)
    text = repr(law)
    assert "object at 0x" not in text
    assert text.startswith(f"<contact law {name!r}:") and f"doi:{law.doi}" in text
    html = law._repr_html_()  # type: ignore[attr-defined]
    assert f"href='https://doi.org/{law.doi}'" in html
    assert "validity:" in html and "calibrated range:" in html


def test_study_repr_summarises_axes() -> None:
    angles = np.radians(np.linspace(5.0, 85.0, 81))
    st = Study(
        name="map",
        grid={"angle": angles, "mu": np.linspace(0.0, 0.5, 51), "law": ["ghaednia", "brake"]},
        fixed={"vy": -1.41},
    )
    text = repr(st)
    assert "angle[81] 5 .. 85 deg" in text and "mu[51] 0 .. 0.5" in text
    assert "law[2] ghaednia, brake" in text and "vy = -1.41 m/s" in text
    assert "8262 cases" in text
    assert len(text) < 300 and "0.0872" not in text  # no value-by-value dump
    cells = _cells(st._repr_html_())
    assert cells[:4] == ["angle", "81", "5 .. 85", "deg"]


def test_study_repr_of_a_sample() -> None:
    st = Study(
        name="mc",
        fixed={"angle": 0.35, "vy": -1.41},
        sample=Sample(size=500, seed=3, inputs={"mu": Normal(0.2, 0.02)}),
    )
    assert "sample: mu[500] dist normal, mean 0.2, std 0.02" in repr(st)


def test_synthetic_truth_repr_is_one_line_without_arrays() -> None:
    from impactlab.testing.impacts import ImpactTruth

    path = np.zeros((500, 4))
    truth = ImpactTruth(0.3, (0.0, -1.0), 0.0, (0.1, 0.5), 2.0, (0.0, -1.0), (0.1, 0.5), 0.5,
                        0.2, "slip", 1e-4, "engine", 6e-5, -2e-5, path)  # fmt: skip
    text = repr(truth)
    assert "\n" not in text and "<500 rows>" in text and "0." * 20 not in text
    assert "regime='slip'" in text and "e=0.5" in text
