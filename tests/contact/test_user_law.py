"""A contact law of one's own, registered from outside the package (``register_law``): it runs
in ``simulate``, ``simulate_batch`` and a sweep, keeps the invariants, equals the same tables
given as the tabulated law, travels with a sweep's study, and bad input is refused."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterator

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import impactlab as il
from impactlab.contact import (
    IndentationCurves,
    get_law,
    law_names,
    register_law,
    registered_laws,
    tabulated_model,
    unregister_law,
)
from impactlab.contact._common import jg_critical
from impactlab.contact.energy import loading_work
from impactlab.contact.registered import RegisteredLaw, law_from_record, sample_law
from impactlab.contact.registry import ensure_laws
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = il.Rod.paper().tip_radius
DC, FC = jg_critical(PAIR.E_star, R, PAIR.yield_strength, PAIR.nu)
NAME = "toy-power"


def hertz(delta: float) -> float:
    return 4.0 / 3.0 * PAIR.E_star * math.sqrt(R) * delta**1.5


def toy_loading(delta: float) -> float:
    """Hertz up to delta_c, then a softer power law (F/F_Hertz falls: energy is dissipated)."""
    return hertz(delta) if delta <= DC else FC * (delta / DC) ** 1.25


def toy_unloading(delta_max: float) -> float:
    """delta_r: 0 up to delta_c, then a growing share of delta_max."""
    return 0.0 if delta_max <= DC else 0.7 * delta_max * (1.0 - math.sqrt(DC / delta_max))


@pytest.fixture(scope="module")
def toy() -> Iterator[RegisteredLaw]:
    law = register_law(
        NAME, loading=toy_loading, unloading=toy_unloading, pair=PAIR, radius=R, delta_max=400 * DC
    )
    yield law
    unregister_law(NAME)  # the other tests see the built-in laws only


def test_registration_states_its_sampling_error(toy: RegisteredLaw) -> None:
    assert NAME in law_names() and registered_laws()[NAME].fingerprint() == toy.fingerprint()
    force_error, residual_error = toy.sampling_error
    assert 0.0 < force_error <= 0.01 and 0.0 <= residual_error <= 0.01
    model = toy.build(PAIR, R)
    assert model.name == NAME and model.law_id == get_law("tabulated").law_id
    d = np.geomspace(DC, 400 * DC, 97)
    want = np.array([toy_loading(x) for x in d])
    assert np.max(np.abs(model.force(d) / want - 1.0)) <= force_error * (1 + 1e-9)
    assert model.fitted_range.status == "tabulated"
    assert toy.describe()["sampling_error"]["force"] == force_error


def _impact(law: object, **kw: object) -> il.ImpactResult:
    return il.simulate(
        il.Rod.paper(),
        AISI_1010,
        law=law,  # type: ignore[arg-type]
        mu=0.2,
        angle=math.radians(40.0),
        velocity=(0.0, -1.4),
        **kw,  # type: ignore[arg-type]
    )


def test_simulate_keeps_the_invariants_and_equals_the_tabulated_law(toy: RegisteredLaw) -> None:
    r = _impact(NAME, history=True)
    assert r.law == NAME and r.flags == 0
    assert 0.0 < r.e < 1.0 and r.energy_dissipated > 0.0
    h = r.history
    assert np.all(h["normal_force"] >= 0.0)
    # never increases, to the engine's accuracy contract for dense-output samples (1e-5 E_0,
    # as tests/dynamics/test_engine_invariants.py)
    energy = np.asarray(h["energy"])
    assert np.all(energy - np.minimum.accumulate(energy) <= 1e-5 * energy[0])
    assert r.delta_max > DC  # the tabulated (plastic) part was used
    same = _impact(tabulated_model(toy.own_curves, PAIR, R))
    for name in ("e", "delta_max", "delta_p", "duration", "max_force", "sliding_length"):
        assert getattr(r, name) == getattr(same, name)


def test_batch_equals_simulate(toy: RegisteredLaw) -> None:
    angles = np.radians([20.0, 40.0, 70.0])
    b = il.simulate_batch(il.Rod.paper(), AISI_1010, law=NAME, mu=0.2, angle=angles, vy=-1.4)
    assert b.law == NAME
    assert np.all(b.e < 1.0) and np.all(b.energy_dissipated > 0.0)
    one = _impact(NAME)
    assert b.e[1] == pytest.approx(one.e, rel=1e-9)


def test_sweep_runs_it_and_carries_its_data(toy: RegisteredLaw, tmp_path) -> None:
    from impactlab.sweep import Study, run_sweep
    from impactlab.sweep.chunks import compute_chunk
    from impactlab.sweep.engine import ENGINE

    study = Study(
        name="user-law",
        grid={"angle": np.radians([20.0, 40.0, 70.0])},
        fixed={"vy": -1.4, "mu": 0.2, "law": NAME},
        outputs=["e", "delta_max"],
    )
    assert study.laws == {NAME: toy.record()}
    assert study.to_dict()["laws"][NAME]["curves"] == toy.own_curves.record()
    ds = run_sweep(study, tmp_path / "user.zarr", quiet=True).dataset
    assert (ds["status"].values == 0).all()
    b = il.simulate_batch(
        il.Rod.paper(), AISI_1010, law=NAME, mu=0.2, angle=np.radians([20.0, 40.0, 70.0]), vy=-1.4
    )
    np.testing.assert_allclose(ds["e"].values, b.e, rtol=1e-9)
    # a worker process knows only what the study brings: without the registry's entry, the
    # chunk registers the law from the study's record and computes the same numbers
    unregister_law(NAME)
    try:
        res = compute_chunk(study, 0, ENGINE, ["e"])
        assert NAME in law_names()
    finally:
        ensure_laws({NAME: toy.record()})
    np.testing.assert_array_equal(res.outputs["e"], ds["e"].values[: res.n_cases])
    # the stored study reads back with its law
    again = Study.from_dict(study.to_dict())
    assert again.laws == study.laws and again.hash() == study.hash()


def test_a_result_reruns_with_the_law_it_carries(toy: RegisteredLaw) -> None:
    """A result's input record holds the user's law, so ``rerun`` works where the law is not
    registered (another process, or a Python started later)."""
    import json

    r = _impact(NAME)
    record = json.loads(json.dumps(r.to_dict()))
    assert record["input"]["law_data"] == toy.record()
    unregister_law(NAME)
    try:
        again = il.rerun(record)
        assert NAME in law_names()
    finally:
        ensure_laws({NAME: toy.record()})
    assert again.e == r.e and again.delta_p == r.delta_p


@settings(max_examples=15)
@given(
    n=st.floats(1.0, 1.5),
    share=st.floats(0.05, 0.9),
    q=st.floats(0.2, 1.0),
)
def test_sampled_power_laws_stay_within_their_bound_and_create_no_energy(
    n: float, share: float, q: float
) -> None:
    """Any F = F_c (delta/delta_c)^n (n <= 1.5: never stiffer than Hertz) with delta_r =
    share delta_max (1 - (delta_c/delta_max)^q) samples within the 1 % bound, and the law built
    from it returns at most the work spent at every turning point, with F >= 0 rising."""
    law = sample_law(
        "toy-property",
        lambda d: hertz(d) if d <= DC else FC * (d / DC) ** n,
        lambda dm: 0.0 if dm <= DC else share * dm * (1.0 - (DC / dm) ** q),
        PAIR,
        R,
        300 * DC,
    )
    assert max(law.sampling_error) <= 0.01
    model = law.build(PAIR, R)
    d = np.geomspace(1e-3 * DC, model.max_interference, 200)
    f = model.force(d)
    assert np.all(f >= 0.0) and np.all(np.diff(f) >= 0.0)
    for dm in d[::20]:
        assert model.unload(float(dm)).energy_returned() <= loading_work(model, float(dm)) * (
            1 + 1e-9
        )


def test_record_round_trip(toy: RegisteredLaw) -> None:
    back = law_from_record(toy.record())
    assert back.fingerprint() == toy.fingerprint()
    assert back.sampling_error == toy.sampling_error


def test_names_and_data_are_protected(toy: RegisteredLaw) -> None:
    with pytest.raises(ValueError, match="built-in law's and cannot be registered"):
        register_law("ghaednia", toy.own_curves)
    ensure_laws({NAME: toy.record()})  # the same data again: nothing changes
    assert get_law(NAME).fingerprint() == toy.fingerprint()  # type: ignore[attr-defined]
    other = IndentationCurves(
        "other", "test", toy.own_curves.e_star_over_sy, toy.own_curves.nu,
        toy.own_curves.delta, toy.own_curves.force * 0.99, toy.own_curves.delta_max,
        toy.own_curves.residual_ratio, elastic_limit=toy.own_curves.elastic_limit,
    )  # fmt: skip
    with pytest.raises(ValueError, match="already registered with other data"):
        register_law(NAME, other)
    with pytest.raises(ValueError, match="law name must be lower-case"):
        register_law("My Law", other)
    with pytest.raises(ValueError, match="unknown contact law 'no-such-law'"):
        get_law("no-such-law")
    harder = dataclasses.replace(AISI_1010, yield_strength=600e6)  # another E*/S_y
    with pytest.raises(ValueError, match=f"law '{NAME}': no indentation curves for E"):
        toy.build(ContactPair(AISI_201, harder), R)


def test_the_switch_interference_is_named_in_metres() -> None:
    """``switch_interference`` [m] is where the sampled law leaves Hertz; ``elastic_limit``,
    its name before, still works with a DeprecationWarning (the curves' ``elastic_limit`` is
    the same point in delta/delta_c)."""
    kw = {"pair": PAIR, "radius": R, "delta_max": 100 * DC}
    law = register_law("toy-switch", loading=toy_loading, unloading=toy_unloading,
                       switch_interference=DC, **kw)  # fmt: skip
    try:
        assert law.own_curves.elastic_limit == pytest.approx(1.0, rel=1e-12)
        with pytest.warns(DeprecationWarning, match="'elastic_limit' is renamed"):
            again = register_law("toy-switch", loading=toy_loading, unloading=toy_unloading,
                                 elastic_limit=DC, **kw)  # fmt: skip
        assert again.fingerprint() == law.fingerprint()
    finally:
        unregister_law("toy-switch")
    with pytest.raises(ValueError, match="differ: give switch_interference only"), \
            pytest.warns(DeprecationWarning, match="renamed"):  # fmt: skip
        register_law("toy-both", loading=toy_loading, unloading=toy_unloading,
                     switch_interference=DC, elastic_limit=2 * DC, **kw)  # fmt: skip
    with pytest.raises(ValueError, match="curves carry their own elastic limit"):
        register_law("toy-curves", law.own_curves, switch_interference=DC)
    with pytest.raises(ValueError, match=r"switch_interference must be > 0 m, got -1\.0"):
        register_law("toy-bad", loading=toy_loading, unloading=toy_unloading,
                     switch_interference=-1.0, **kw)  # fmt: skip


def test_bad_callables_and_tables_are_refused() -> None:
    kw = {"pair": PAIR, "radius": R, "delta_max": 100 * DC}
    with pytest.raises(ValueError, match=r"loading\(.*\) returned nan"):
        register_law("bad-nan", loading=lambda d: math.nan, unloading=toy_unloading, **kw)
    with pytest.raises(ValueError, match="from Hertz's"):
        register_law("bad-start", loading=lambda d: 2 * hertz(d), unloading=toy_unloading, **kw)
    stiff = lambda d: hertz(d) if d <= DC else hertz(DC) * (d / DC) ** 1.8  # noqa: E731
    with pytest.raises(ValueError, match="departs from the callable's force"):
        register_law("bad-stiff", loading=stiff, unloading=toy_unloading, **kw)
    with pytest.raises(ValueError, match=r"delta_max .* is required"):
        register_law("bad-range", loading=toy_loading, unloading=toy_unloading, pair=PAIR, radius=R)
    with pytest.raises(ValueError, match="force must not decrease"):
        IndentationCurves.from_arrays(PAIR, R, [DC, 2 * DC, 3 * DC, 4 * DC, 5 * DC],
                                      [FC, 2 * FC, 1.5 * FC, 3 * FC, 4 * FC], [DC, 5 * DC],
                                      [0.0, 0.2 * DC])  # fmt: skip
    assert not any(n.startswith("bad-") for n in law_names())


@pytest.mark.slow
def test_a_spawned_worker_gets_the_law_from_the_study(toy: RegisteredLaw, tmp_path) -> None:
    """The process pool starts its workers with "spawn": nothing of this process's registry
    reaches them, only the study (end to end: the worker loads the engine from its cache)."""
    from impactlab.sweep import Study, run_sweep

    study = Study(
        name="user-law-pool",
        grid={"angle": np.radians([20.0, 70.0])},
        fixed={"vy": -1.4, "mu": 0.2, "law": NAME},
        outputs=["e"],
    )
    pool = run_sweep(study, tmp_path / "pool.zarr", quiet=True, backend="processes", workers=1)
    here = run_sweep(study, tmp_path / "here.zarr", quiet=True)
    assert (pool.dataset["status"].values == 0).all()
    np.testing.assert_array_equal(pool.dataset["e"].values, here.dataset["e"].values)


def test_the_accuracy_command_measures_a_law_of_ones_own(toy: RegisteredLaw) -> None:
    """``impactlab laws NAME --accuracy`` measures a registered law against the shipped FE
    case of its pair, beside the built-in laws; a pair with no FE case is told so."""
    import json

    from typer.testing import CliRunner

    from impactlab.cli import app

    res = CliRunner().invoke(app, ["laws", NAME, "--accuracy", "--json"])
    assert res.exit_code == 0, res.output
    cases = json.loads(res.stdout)["cases"]
    assert [c["e_star_over_sy"]["value"] for c in cases] == pytest.approx([360.0], rel=0.01)
    assert list(cases[0]["laws"]) == [NAME]
    far = ContactPair(AISI_201, dataclasses.replace(AISI_1010, yield_strength=150e6))
    dc, fc = jg_critical(far.E_star, R, far.yield_strength, far.nu)  # E*/S_y 732: no FE case

    def loading(delta: float) -> float:
        return fc * (delta / dc) ** (1.5 if delta <= dc else 1.25)

    def unloading(delta_max: float) -> float:
        return 0.0 if delta_max <= dc else 0.7 * delta_max * (1.0 - math.sqrt(dc / delta_max))

    register_law("toy-lone", loading=loading, unloading=unloading, pair=far, radius=R,
                 delta_max=400 * dc)  # fmt: skip
    try:
        res = CliRunner().invoke(app, ["laws", "toy-lone", "--accuracy"])
    finally:
        unregister_law("toy-lone")
    assert res.exit_code == 2 and "none of the shipped FE cases has that pair" in res.output
