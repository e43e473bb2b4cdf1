"""A batch whose impacting body yields first (``materials.body_yields_first``): the batch says
so once per call (``body_yields_first``, one advisory ``warnings`` sentence, the ``setup`` and
``to_xarray`` attribute), and its numbers are those of the single results."""

from __future__ import annotations

import math

import numpy as np
import pytest

import impactlab as il

COPPER = il.get_material("copper-ofhc")
STEEL = il.get_material("aisi-1010")
AL = il.get_material("al-6061-t6")
HARD = il.get_material("aisi-52100")
ANGLE = math.radians(30)


def _rod(material: il.Material) -> il.Rod:
    return il.Rod(length=0.3, tip_radius=0.005, mass=0.3, material=material)


def test_a_copper_rod_s_batch_names_its_flattening_once() -> None:
    vy = np.array([-0.5, -1.0, -2.0, np.nan])  # a refused case too
    b = il.simulate_batch(_rod(COPPER), STEEL, angle=ANGLE, vy=vy)
    assert b.body_yields_first is True
    assert len(b.warnings) == 1 and b.warnings[0].startswith("body yields first: ")
    largest = float(np.nanmax(b["delta_p"]))
    assert f"the batch's largest delta_p = {largest * 1e6:.4g} um" in b.warnings[0]
    assert "not a dent in the flat" in b.warnings[0] and "'OFHC copper, annealed'" in b.warnings[0]
    assert b.setup["body_yields_first"] == 1 and b.to_xarray().attrs["body_yields_first"] == 1
    one = il.simulate(_rod(COPPER), STEEL, angle=ANGLE, velocity=(0.0, -2.0))
    assert b["delta_p"][2] == one.delta_p and one.body_yields_first  # no number changes
    assert bool(np.all(b.ok[:3]))  # advisory


def test_the_paper_s_pair_says_nothing() -> None:
    b = il.simulate_batch(_rod(il.AISI_1010), STEEL, angle=ANGLE, vy=-1.0)
    assert b.body_yields_first is False and b.warnings == ()
    assert b.setup["body_yields_first"] == 0


def test_an_elastic_batch_keeps_the_field_without_the_sentence() -> None:
    sphere = il.Sphere(radius=0.003, material=COPPER)
    b = il.simulate_batch(sphere, STEEL, vy=-1e-2, law="hertz")  # elastic: delta_p = 0
    assert b.body_yields_first is True and float(b["delta_p"][0]) == 0.0
    assert b.warnings == ()


def test_a_drop_batch_names_the_rod_s_flattening_once() -> None:
    law = "jackson-green"
    d = il.simulate_drops(_rod(AL), HARD, law=law, angle=ANGLE, vy=np.array([-1.0, -0.5]))
    assert d.body_yields_first is True and len(d.warnings) == 1
    assert f"the batch's largest dent_depth = {d['dent_depth'][0] * 1e6:.4g} um" in d.warnings[0]
    assert d.setup["body_yields_first"] == 1 and d.to_xarray().attrs["body_yields_first"] == 1
    one = il.simulate_drop(_rod(AL), HARD, law=law, angle=ANGLE, velocity=(0.0, -1.0))
    assert d["dent_depth"][0] == pytest.approx(one.dent_depth, rel=0, abs=0)
    steel = il.simulate_drops(_rod(il.AISI_1010), STEEL, law=law, angle=ANGLE, vy=-1.0)
    assert steel.body_yields_first is False and steel.warnings == ()
