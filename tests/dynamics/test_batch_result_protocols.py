"""A batch result reads like a mapping of its columns (``"e" in batch``, ``list(batch)``), a
sphere's batch has no axis angle, every column a batch of drops publishes has a schema unit,
and ``run_arrays`` refuses ids that are no integers and a brittle limit that is no pressure."""

from __future__ import annotations

import re

import numpy as np
import pytest

import impactlab as il
from impactlab import schema
from impactlab.dynamics import contact_model, run_arrays
from impactlab.dynamics.models import body_params

ROD = il.Rod.paper()


@pytest.mark.parametrize("batch", [il.simulate_batch, il.simulate_drops])
def test_a_batch_answers_in_and_iterates_its_field_names(batch) -> None:
    """``"e" in batch`` raised KeyError: unknown field 0 (the old sequence protocol)."""
    b = batch(ROD, angle=0.3, vy=[-1.0, -2.0], mu=0.2)
    assert "e" in b and "status" in b and "vy" in b
    assert "nonsense" not in b and 0 not in b
    names = list(b)
    assert names and len(names) == len(set(names))
    assert all(name in b for name in names)
    np.testing.assert_array_equal({n: b[n] for n in names}["e"], b.e)
    # every column of to_dataframe() is a key: {k: b[k] for k in b} dropped status
    assert set(b.to_dataframe().columns) <= set(names)


def test_an_old_drop_field_name_is_not_in_a_batch_of_drops() -> None:
    d = il.simulate_drops(ROD, angle=0.3, vy=-1.0, mu=0.2)
    assert "dent_depth" in d and "delta_p" not in d  # the old name reads, with a warning


def test_a_spheres_batch_has_no_angle() -> None:
    """It held the engine's pi/2, labelled as a rod's axis angle; ImpactResult.angle is NaN."""
    s = il.Sphere(radius=0.01, material=il.AISI_201)
    b = il.simulate_batch(s, vy=[-1.0, -2.0])
    assert np.isnan(b.angle).all() and np.isnan(il.simulate(s, velocity=(0, -1.0)).angle)
    assert (b.status == 0).all()
    assert b.e[0] == il.simulate(s, velocity=(0, -1.0), history=False).e


def test_every_column_of_a_batch_of_drops_has_a_schema_unit() -> None:
    units = il.simulate_drops(ROD, angle=0.3, vy=-1.0).to_dataframe().attrs["units"]
    for name in ("n_dents", "n_jumps", "t_final"):  # schema.unit raised KeyError
        assert schema.unit(name) == units[name]
    assert [k for k in units if k != "status" and k not in schema.FIELDS] == []


@pytest.mark.parametrize(
    ("law", "friction", "kw", "said"),
    [
        (1.9, 1, {}, "law_id must be an integer, got 1.9"),
        (True, 1, {}, "law_id must be an integer, got True"),
        (None, 1.5, {}, "friction_id must be an integer, got 1.5"),
        (None, 1, {"brittle_limit": -1.0}, "brittle_limit must be > 0 [Pa]"),
        (None, 1, {"brittle_limit": np.nan}, "brittle_limit must be > 0 [Pa]"),
    ],
)
def test_run_arrays_refuses_what_it_would_misread(law, friction, kw, said) -> None:
    """1.9 ran law 1; a negative brittle limit flagged every case BRITTLE."""
    m = contact_model(ROD, il.AISI_1010, "ghaednia")
    args = (m.params, body_params(ROD, il.AISI_1010), np.array([[0.3, 0.0, -1.0, 0.0]]), 0.2)
    with pytest.raises(ValueError, match=re.escape(said)):
        run_arrays(m.law_id if law is None else law, friction, *args, **kw)
    _, status = run_arrays(np.int64(m.law_id), 1.0, *args)  # whole numbers are ids
    assert status.tolist() == [0]


def test_a_two_dimensional_batch_input_says_how_to_make_a_grid() -> None:
    """The tutorial said batch inputs broadcast; a column of mu was refused without a hint."""
    with pytest.raises(ValueError, match=r"mu must be a scalar or a 1-D array, got shape "
                       r"\(5, 1\): .*np.meshgrid\(...\) then .ravel\(\)"):  # fmt: skip
        il.simulate_batch(ROD, angle=0.3, vy=-1.0, mu=np.linspace(0, 0.8, 5)[:, None])


def test_an_impact_names_its_body_and_flat_as_printed() -> None:
    """``print(r)`` showed body and flat rows; ``r.body`` raised AttributeError."""
    r = il.simulate(ROD, angle=0.3, velocity=(0.0, -1.0), mu=0.2, history=False)
    assert r.body == r.summary()["body"] and r.body.startswith("Rod: length = 304.8 mm")
    assert r.flat == r.summary()["flat"] == il.AISI_1010.name


def test_a_spheres_approach_rule_is_its_own() -> None:
    """A sphere that does not approach was told the rod's rule, vy - spin * (L/2) cos(angle)."""
    s = il.Sphere(radius=0.01, material=il.AISI_201)
    with pytest.raises(ValueError, match=r"its normal velocity vy = 1\.0 m/s must be < 0\)"):
        il.simulate(s, velocity=(0.0, 1.0))
