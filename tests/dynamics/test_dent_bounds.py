"""The dent map keeps every cap's depth: a cap whose law unloads with R_r <= R (no concave
solution of 1/R_r = 1/R - 1/R_d) or whose relation puts its rim beyond the contact is drawn with
the widest contact radius as rim (the relation's limit R_r -> R+, continuous across R_r = R),
and the DentMap says so; the depth of the dent is the law's (``delta_p`` of one loading, a
drop's ``dent_depth``)."""

from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")
import numpy as np
import pytest

import impactlab as il
from impactlab.bodies import PAPER_ROD
from impactlab.contact.kernel_arrays import loading_contact_radius_array
from impactlab.contact.kernels import P_R
from impactlab.dynamics import plotting
from impactlab.dynamics.core.batch import residual_caps
from impactlab.dynamics.dent import (
    AT_CONTACT_RADIUS,
    AT_TIP_RADIUS,
    BY_RELATION,
    residual_cap_geometry,
)

JG_COPPER = {"law": "jackson-green", "angle": 0.6, "velocity": (0.0, -5.0)}
SPHERE_PMMA = {"law": "ghaednia", "velocity": (0.0, -1.0)}


@pytest.fixture(scope="module")
def jg_copper() -> il.ImpactResult:
    return il.simulate(il.Rod.paper(), "copper-ofhc", **JG_COPPER)


@pytest.fixture(scope="module")
def sphere_pmma() -> il.ImpactResult:
    return il.simulate(il.Sphere(radius=0.005, material="aisi-52100"), "pmma", **SPHERE_PMMA)


def _contact_radius(law: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """a_c [m]: the widest of the loading, unloading and undeformed-flat crossing radii."""
    dr, rr = residual_caps(law, p, delta)
    with np.errstate(invalid="ignore"):
        a_unl = np.sqrt(rr * (delta - dr))
    a_unl = np.where(np.isfinite(a_unl), a_unl, 0.0)
    R = float(p[P_R])
    return np.maximum.reduce(
        [loading_contact_radius_array(law, p, delta), a_unl, np.sqrt(2 * R * delta)]
    )


@pytest.mark.parametrize("name", ["jg_copper", "sphere_pmma"])
def test_deepest_cap_with_no_concave_solution_keeps_its_depth(name, request) -> None:
    r = request.getfixturevalue(name)
    d = r.dent()
    assert r.ok and r.delta_p > 0
    assert d.max_depth == pytest.approx(r.delta_p, rel=1e-12)
    assert -d.height.min() == pytest.approx(r.delta_p, rel=1e-2)
    # drawn at the contact radius of its peak: the relation's limit R_r -> R+
    p = np.asarray(r._law_params, dtype=np.float64)
    law, R = int(r._law_id), float(p[P_R])
    peak = np.array([float(np.max(r.history.penetration))])
    _, rr = residual_caps(law, p, peak)
    assert rr[0] <= R
    assert d.width == pytest.approx(2.0 * _contact_radius(law, p, peak)[0], rel=1e-9)
    assert d.width > 2.0 * math.sqrt(2.0 * R * r.delta_p)
    assert d.caps_at_contact_radius >= 1 and "deepest among them" in d.note
    assert "contact radius" in d.note and "caps_at_contact_radius" in repr(d)


@pytest.mark.parametrize(
    ("flat", "law", "v", "deepest_bounded"),
    [
        ("copper-ofhc", "jackson-green", 5.0, True),
        ("pmma", "ghaednia", 1.0, False),
        ("aisi-1010", "ghaednia", 1.0, False),
    ],
)
def test_drop_dent_depth_is_its_dent_map_depth(flat, law, v, deepest_bounded) -> None:
    d = il.simulate_drop(il.FlexibleRod.paper(), flat, law=law, angle=0.6, velocity=(0.0, -v))
    dm = d.dent()
    assert d.ok and d.dent_depth > 0
    assert dm.max_depth == pytest.approx(d.dent_depth, rel=1e-12)
    assert ("deepest among them" in dm.note) == deepest_bounded
    assert bool(dm.note) == bool(dm.caps_at_contact_radius)


def test_cap_geometry_bounds(jg_copper: il.ImpactResult) -> None:
    p = np.asarray(jg_copper._law_params, dtype=np.float64)
    law, R = int(jg_copper._law_id), float(p[P_R])
    # R_r crosses R near delta = 0.1 mm: sample it finely there
    delta = np.sort(np.r_[np.geomspace(1e-7, 1e-3, 400), np.linspace(9e-5, 1.1e-4, 2001)])
    dr, rr = residual_caps(law, p, delta)
    caps = residual_cap_geometry(law, p, delta)
    assert np.array_equal(caps.delta_r, dr)
    dent = dr > 0
    assert np.all(caps.R_d[dent] >= R) and np.all(caps.a_d[dent] > 0)
    a_c = _contact_radius(law, p, delta)
    # the rim never passes the widest circle the tip touched
    assert np.all(caps.a_d[dent] <= a_c[dent] * (1 + 1e-6))
    # R_r <= R (no concave solution) and R_r just above R (the relation's R_d -> inf): a_c
    with np.errstate(divide="ignore", invalid="ignore"):
        a_rel = np.sqrt(2 * R * rr / (rr - R) * dr)
    near = dent & (rr > R) & (rr < 1.01 * R)
    assert near.any() and np.all(a_rel[near] > 5 * a_c[near])  # the relation's rim: far out
    below = dent & (rr <= R)
    for sel in (near, below):
        assert sel.any() and np.all(caps.bound[sel] == AT_CONTACT_RADIUS)
        assert np.all(caps.a_d[sel] == a_c[sel])
        np.testing.assert_allclose(caps.R_d[sel], a_c[sel] ** 2 / (2 * dr[sel]), rtol=1e-15)
    # elsewhere the relation itself, unchanged
    kept = dent & (rr > R) & (a_rel <= a_c)
    assert kept.any() and np.all(caps.bound[kept] == BY_RELATION)
    assert np.array_equal(caps.R_d[kept], R * rr[kept] / (rr[kept] - R))


def test_rim_is_continuous_where_r_r_crosses_r(jg_copper: il.ImpactResult) -> None:
    p = np.asarray(jg_copper._law_params, dtype=np.float64)
    law, R = int(jg_copper._law_id), float(p[P_R])
    delta = np.linspace(100.40e-6, 100.48e-6, 8001)  # steps of 1e-11 m
    _, rr = residual_caps(law, p, delta)
    assert rr[0] > R and rr[-1] < R  # R_r crosses R inside
    caps = residual_cap_geometry(law, p, delta)
    assert np.max(np.abs(np.diff(caps.a_d)) / caps.a_d[1:]) < 1e-6
    assert np.max(np.abs(np.diff(caps.R_d)) / caps.R_d[1:]) < 1e-6
    # over the whole range the rim grows with the interference (no jump at R_r = R)
    wide = np.linspace(2e-5, 4e-4, 20001)
    a_d = residual_cap_geometry(law, p, wide).a_d
    assert np.all(np.diff(a_d) >= -1e-6 * a_d[1:])


def test_width_grows_with_impact_speed() -> None:
    speeds = (0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.3, 1.4, 1.6)
    widths = []
    for v in speeds:
        r = il.simulate(
            il.Rod.paper(), "copper-ofhc", law="jackson-green", angle=0.6, velocity=(0.0, -v)
        )
        widths.append(r.dent().width)
    assert np.all(np.diff(widths) > 0), dict(zip(speeds, widths, strict=True))


def test_cap_without_loading_is_empty() -> None:
    r = il.simulate(il.Rod.paper(), "copper-ofhc", **JG_COPPER)
    p = np.asarray(r._law_params, dtype=np.float64)
    caps = residual_cap_geometry(int(r._law_id), p, np.array([0.0, 2e-4]))
    assert caps.a_d[0] == 0.0 and caps.R_d[0] == math.inf and caps.bound[0] == BY_RELATION
    assert np.isfinite(caps.R_d[1]) and caps.a_d[1] > 0


def _cases():
    bodies = [
        ("rod", il.Rod.paper()),
        ("sphere 5 mm", il.Sphere(radius=0.005, material="aisi-52100")),
        ("sphere 25 mm", il.Sphere(radius=0.025, material="brass-c360")),
    ]
    for law in il.law_names():
        for label, body in bodies:
            for flat in ("copper-ofhc", "pmma", "aisi-201", "ti-6al-4v", "alumina-99.5"):
                for v in (0.1, 1.0, 5.0):
                    yield law, label, body, flat, v


def test_max_depth_is_delta_p_for_every_law() -> None:
    plastic: set[str] = set()
    for law, label, body, flat, v in _cases():
        kw = {"law": law, "velocity": (0.0, -v)}
        if isinstance(body, il.Rod):
            kw["angle"] = 0.6
        try:
            r = il.simulate(body, flat, **kw)
        except ValueError:
            continue  # a law that does not take this pair
        if r.delta_p <= 0.0:
            continue
        if r.body_yields_first:  # delta_p is the body's flattening: no dent in the flat
            with pytest.raises(ValueError, match="no dent in the flat"):
                r.dent()
            continue
        plastic.add(law)
        d = r.dent()
        where = f"{law}, {label} on {flat} at {v} m/s"
        # the history's recorded peak may pass delta_max by a few 1e-8 of it
        assert d.max_depth == pytest.approx(r.delta_p, rel=1e-5), where
        R = float(r._law_params[P_R])
        assert d.width >= 2 * math.sqrt(2 * R * d.max_depth) * (1 - 1e-9)
        # no cap narrower than the tip: R_d >= R, at the contact radius too (a_c^2 >= 2 R delta)
        caps = residual_cap_geometry(r._law_id, r._law_params, r.history.penetration)
        assert np.all(caps.R_d[(caps.delta_r > 0) & (caps.bound != AT_TIP_RADIUS)] >= R), where
        assert np.all(d.height <= 0.0) and d.height.min() < 0.0, where
        assert bool(d.note) == bool(d.caps_at_contact_radius), where
    assert {"ghaednia", "jackson-green", "thornton", "brake", "kogut-komvopoulos"} <= plastic


def _hertzian_envelope(r: il.ImpactResult, nx: int, ny: int) -> np.ndarray:
    """The dent of the relation alone (no bound), on the same grid: the map before the bounds."""
    p = np.asarray(r._law_params, dtype=np.float64)
    R = float(p[P_R])
    pen = np.ascontiguousarray(r.history.penetration)
    dr, rr = residual_caps(int(r._law_id), p, pen)
    keep = (dr > 0) & (rr > R * (1 + 1e-12))
    dr, rr, xc = dr[keep], rr[keep], r.history.contact_x[keep]
    rd = R * rr / (rr - R)
    ad = np.sqrt(2 * rd * dr)
    x_lo, x_hi, a_max = np.min(xc - ad), np.max(xc + ad), ad.max()
    pad = 0.15 * max(x_hi - x_lo, 2 * a_max)
    x = np.linspace(x_lo - pad, x_hi + pad, nx)
    y = np.linspace(-(a_max + pad), a_max + pad, ny)
    h = np.zeros((ny, nx))
    for i in range(dr.shape[0]):
        cap = -dr[i] + ((x[None, :] - xc[i]) ** 2 + (y * y)[:, None]) / (2 * rd[i])
        inside = np.abs(x - xc[i]) <= ad[i]
        h[:, inside] = np.minimum(h[:, inside], cap[:, inside])
    return h


def test_paper_dent_is_unchanged() -> None:
    r = il.simulate(
        PAPER_ROD,
        law="ghaednia",
        friction="coulomb",
        mu=0.2,
        angle=math.radians(20),
        velocity=(0.0, -1.41),
    )
    d = r.dent(nx=121, ny=61)
    assert d.max_depth == pytest.approx(62e-6, abs=0.5e-6)
    assert d.width == pytest.approx(2.14e-3, abs=0.005e-3)
    assert d.caps_at_contact_radius == 0 and d.note == ""
    caps = residual_cap_geometry(r._law_id, r._law_params, r.history.penetration)
    assert np.all(caps.bound == BY_RELATION)
    assert caps.R_d[np.argmax(caps.delta_r)] == pytest.approx(9.3e-3, abs=0.05e-3)
    np.testing.assert_allclose(d.height, _hertzian_envelope(r, 121, 61), rtol=0, atol=1e-15)
    assert "caps_at" not in repr(d)


def test_plot_dent_names_the_bounded_caps(jg_copper: il.ImpactResult) -> None:
    fig = plotting.plot_dent(jg_copper)
    title = fig.axes[0].get_title()
    assert "dent: depth 559 um" in title and "at the contact radius" in title


def test_a_normal_impact_leaves_the_cap_of_its_deepest_instant() -> None:
    """The imprints of the shallower instants at the same place were drawn as a ring around it
    (12 % wider at 2 m/s), and the width fell as the speed rose."""
    sphere = il.Sphere(0.005, material="aisi-52100")
    widths = []
    for v in (2.0, 2.29, 2.44, 2.58, 2.73, 3.02):
        r = il.simulate(sphere, "pmma", law="ghaednia", velocity=(0.0, -v), gravity=False)
        d = r.dent(nx=401, ny=201)
        caps = residual_cap_geometry(r._law_id, r._law_params, r.history.penetration)
        deepest = int(np.argmax(caps.delta_r))
        assert d.width == pytest.approx(2 * caps.a_d[deepest], rel=1e-12)
        x, z = d.profile()
        assert np.all(z[np.abs(x - r.history.contact_x[deepest]) > caps.a_d[deepest]] == 0.0)
        widths.append(d.width)
    assert np.all(np.diff(widths) > 0), widths


def test_no_sphere_leaves_a_dent_wider_than_itself() -> None:
    """Past delta = R/2 the crossing of the paraboloid tip, sqrt(2 R delta), passes R: a 1 mm
    sphere at 200 m/s left a dent 2.76 mm across, with no note."""
    sphere = il.Sphere(0.001)
    with pytest.warns(il.ImplausibleInputWarning, match="exceeds 100 m/s"):
        r = il.simulate(sphere, "al-6061-t6", law="thornton", velocity=(0.0, -200.0))
    assert r.delta_p > 0.5 * sphere.radius
    d = r.dent()
    assert d.width <= 2 * sphere.radius * (1 + 1e-12)
    assert "at the tip's radius R" in d.note and d.caps_at_contact_radius >= 1


@pytest.mark.parametrize("law", ["ghaednia", "thornton"])
def test_a_sliding_dent_keeps_its_imprints_and_its_length(law: str) -> None:
    """No later instant erases an earlier imprint it did not load further: a rule that gave
    each point to the instant that pressed it deepest, elastic ones included, cut a sliding
    dent on PMMA to 0.44 of its 0.75 mm and drew steps and stripes."""
    sphere = il.Sphere(0.0025, material="aisi-52100")
    r = il.simulate(sphere, "pmma", law=law, mu=0.3, velocity=(5.0, -1.0))
    d = r.dent(nx=801, ny=41)
    x, z = d.profile()
    dented = x[z < 0.0]
    step = x[1] - x[0]
    assert np.ptp(dented) == pytest.approx(d.length, abs=2 * step)
    inside = (x > dented.min()) & (x < dented.max())
    assert np.all(z[inside] < 0.0)  # no hole inside the dent


def _superseded_pairwise(delta, xc, caps, R):  # the rule over every pair, as written
    out = np.zeros(delta.size, dtype=bool)
    for i in range(delta.size):
        if not caps.delta_r[i] > 0.0:
            continue
        for j in range(delta.size):
            d = abs(xc[j] - xc[i])
            lead = delta[j] - delta[i] - (d * d + 2.0 * d * caps.a_c[i]) / (2.0 * R)
            if caps.delta_r[j] > 0.0 and caps.a_c[j] >= d + caps.a_c[i] and lead > 0.0:
                out[i] = True
                break
    return out


@pytest.mark.parametrize("seed", range(6))
def test_the_standing_caps_give_the_pairwise_rule(seed: int) -> None:
    """``superseded`` asks only the caps still standing (deepest first): the same answer as
    the rule over every pair, at a cost that does not grow with the square of a drop's rows."""
    from impactlab.dynamics.dent import ResidualCaps, superseded

    rng = np.random.default_rng(seed)
    n, R = 300, 0.005
    delta = rng.uniform(-5e-6, 60e-6, n)
    xc = np.cumsum(rng.normal(0.0, 20e-6, n))
    dr = np.where(rng.random(n) < 0.8, np.maximum(delta - 8e-6, 0.0), 0.0)
    ac = np.sqrt(2.0 * R * np.maximum(delta, 0.0)) * rng.uniform(0.8, 1.3, n)
    caps = ResidualCaps(dr, np.full(n, 0.01), np.sqrt(0.02 * dr), np.zeros(n, np.int8), ac)
    expected = _superseded_pairwise(delta, xc, caps, R)
    assert expected.any() and not expected.all()
    assert np.array_equal(superseded(delta, xc, caps, R), expected)
