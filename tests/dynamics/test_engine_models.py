"""The one contact-model builder (cached by value, used by simulate and the sweep), the kernel and
body vectors, the output schema of the compiled core and the references results record."""

from __future__ import annotations

import dataclasses
import gc
import math
import weakref

import numpy as np
import pytest

from impactlab import ImplausibleInputWarning, schema
from impactlab.bodies import PAPER_ROD, Rod, Sphere
from impactlab.contact import get_law
from impactlab.dynamics import HISTORY_FIELDS, OUTPUT_FIELDS, simulate, simulate_batch
from impactlab.dynamics.kernels import layout
from impactlab.dynamics.models import (
    INTEGRATOR_REFERENCES,
    body_params,
    build_contact_model,
    contact_model,
    kernel_params,
)
from impactlab.materials import AISI_201, AISI_1010, ContactPair
from impactlab.references import REFERENCES
from impactlab.sweep.engine import Statics, build_models
from impactlab.sweep.inputs import INPUTS


def test_contact_models_are_cached_by_value() -> None:
    a = contact_model(PAPER_ROD, AISI_1010, "ghaednia")
    twin = Rod(
        length=PAPER_ROD.length,
        tip_radius=PAPER_ROD.tip_radius,
        mass=PAPER_ROD.mass,
        material=dataclasses.replace(AISI_201),
    )
    b = contact_model(twin, dataclasses.replace(AISI_1010), "ghaednia")
    assert a is b
    other = contact_model(
        PAPER_ROD, dataclasses.replace(AISI_1010, yield_strength=250e6), "ghaednia"
    )
    assert other is not a
    assert float(other.params[2]) != float(a.params[2])
    ref = get_law("ghaednia").build(ContactPair(AISI_201, AISI_1010), PAPER_ROD.tip_radius)
    np.testing.assert_array_equal(a.params, ref.params)


def test_build_contact_model_rejects_bad_parameters() -> None:
    with pytest.raises(ValueError, match="law_params values must be numbers"):
        build_contact_model("hertz", AISI_201, AISI_1010, 0.01, {"x": [1.0]})  # type: ignore[dict-item]
    with pytest.raises(ValueError, match="unknown parameter"):
        build_contact_model("hertz", AISI_201, AISI_1010, 0.01, {"bogus": 1.0})


def test_the_sweep_builds_the_same_models_as_simulate() -> None:
    cases = {
        name: np.full(2, math.nan if s.default is None else float(s.default))
        for name, s in INPUTS.items()
        if s.kind == "float"
    }
    cases.update(
        {
            "angle": np.full(2, 0.35),
            "vy": np.full(2, -1.41),
            "mu": np.full(2, 0.2),
            "radius": np.array([0.01, 0.02]),
        }
    )
    cat = {
        "law": "brake",
        "friction": "coulomb",
        "body": "sphere",
        "body_material": "aisi-201",
        "flat_material": "aisi-1010",
    }
    lp, bp, status = build_models(cases, Statics(cat))
    assert (status == 0).all()
    for i, radius in enumerate((0.01, 0.02)):
        sphere = Sphere(radius=radius, material=AISI_201)
        np.testing.assert_array_equal(lp[i], contact_model(sphere, AISI_1010, "brake").params)
        np.testing.assert_array_equal(bp[i], body_params(sphere, AISI_1010))


def test_kernel_params_live_as_long_as_their_model() -> None:
    model = get_law("hertz").build(ContactPair(AISI_201, AISI_1010), 0.01)
    p = kernel_params(model)
    assert kernel_params(model) is p
    assert p.flags.c_contiguous and p.flags.writeable
    np.testing.assert_array_equal(p, model.params)
    ref = weakref.ref(model)
    del model
    gc.collect()
    assert ref() is None  # the cache does not keep the model alive (no id() reuse)


def test_body_params_by_value() -> None:
    """Equal bodies give equal vectors, each the caller's own (not cached: it costs 1.6 us,
    docs/architecture.md, "Caches")."""
    a = body_params(Sphere(0.01), AISI_1010)
    b = body_params(Sphere(0.01), AISI_1010)
    assert b is not a
    np.testing.assert_array_equal(b, a)
    np.testing.assert_array_equal(a, Sphere(0.01).to_params(AISI_1010))
    assert a.flags.c_contiguous and a.flags.writeable


def test_core_layout_follows_the_schema() -> None:
    assert OUTPUT_FIELDS == tuple(f.name for f in schema.OUTPUT_FIELDS)
    assert HISTORY_FIELDS == tuple(f.name for f in schema.HISTORY_FIELDS)
    assert layout.N_OUT == len(OUTPUT_FIELDS)
    assert OUTPUT_FIELDS[layout.O_SPIN] == "spin_out"
    assert OUTPUT_FIELDS[layout.O_FEX] == "friction_excess"
    assert HISTORY_FIELDS[layout.H_SPIN] == "spin" and layout.NH == len(HISTORY_FIELDS)
    assert layout.S_SPIN != layout.S_WORK
    for name in (
        *OUTPUT_FIELDS,
        *HISTORY_FIELDS,
        "velocity_out",
        "velocity_in",
        "spin_in",
        "angle",
        "mu",
    ):
        assert schema.unit(name) and schema.description(name)
    assert schema.unit("e") == "1" and schema.unit("normal_impulse") == "N s"
    with pytest.raises(KeyError, match="unknown result field"):
        schema.unit("L_s")


def test_results_record_their_references() -> None:
    r = simulate(
        PAPER_ROD,
        law="ghaednia",
        friction="coulomb",
        mu=0.2,
        angle=math.radians(20),
        velocity=(0.0, -1.41),
    )
    law = get_law("ghaednia")
    assert r.references[: len(law.references)] == law.references
    assert set(INTEGRATOR_REFERENCES) <= set(r.references)
    assert REFERENCES["stronge-2000"] in r.references  # Coulomb friction
    assert "10.1016/0771-050X(80)90013-3" in r.dois()  # Dormand & Prince
    assert len(set(r.dois())) == len(r.dois())
    assert "references" not in r.to_dict()
    with pytest.warns(ImplausibleInputWarning, match="with mu = 0 is frictionless"):
        frictionless = simulate(
            Sphere(0.01), law="hertz", friction="mindlin", mu=0.0, velocity=(0.0, -1.0)
        )
    assert REFERENCES["mindlin-deresiewicz-1953"] not in frictionless.references
    b = simulate_batch(
        Sphere(0.01), law="hertz", friction="mindlin", mu=[0.0, 0.2], vy=[-1.0, -1.0]
    )
    assert REFERENCES["mindlin-deresiewicz-1953"] in b.references
    assert b.dois()[-2:] == tuple(x.doi for x in INTEGRATOR_REFERENCES)
