"""Free-free modes of the rod against the closed forms and an independent finite-element
eigen-solution; the FlexibleRod body."""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable

import numpy as np
import pytest
from paper_drops import SEC

from impactlab.bodies import beam_modes as bm
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.bodies.modal import modal_basis, rigid_modes
from impactlab.bodies.residual import axial_residual_modes
from impactlab.bodies.rod_section import EULER_BERNOULLI, TIMOSHENKO, RodSection
from impactlab.bodies.timoshenko import (
    timoshenko_cutoff,
    timoshenko_frequencies,
    timoshenko_shape_fn,
)
from impactlab.bodies.timoshenko_solutions import determinant as _determinant
from impactlab.bodies.timoshenko_solutions import determinants as _determinants
from impactlab.dynamics.flex_fe import CorotationalRod
from impactlab.materials import AISI_201

GL_X, GL_W = np.polynomial.legendre.leggauss(40)


def quad(f: Callable[[np.ndarray], np.ndarray], L: float, panels: int = 40) -> float:
    """Composite Gauss-Legendre on s in [-L/2, L/2]."""
    edges = np.linspace(-0.5 * L, 0.5 * L, panels + 1)
    tot = 0.0
    for a, b in itertools.pairwise(edges):
        s = 0.5 * (a + b) + 0.5 * (b - a) * GL_X
        tot += 0.5 * (b - a) * float(np.sum(GL_W * f(s)))
    return tot


def test_section_from_mass() -> None:
    assert SEC.d == pytest.approx(math.sqrt(4 * 0.4607 / (7800 * 0.3048) / math.pi), rel=1e-14)
    assert SEC.slenderness == pytest.approx(19.40, abs=0.01)
    assert SEC.kappa == pytest.approx(6 * 1.3 / (7 + 1.8), rel=1e-14)


def test_eb_roots_against_table() -> None:
    """beta_n L = 4.7300, 7.8532, 10.9956, ... (tabulated to 10 digits) to 1e-9."""
    bl = bm.eb_beta_l(5)
    np.testing.assert_allclose(bl, bm.BETA_L_TABLE, rtol=1e-9)
    np.testing.assert_allclose(np.cos(bl) * np.cosh(bl), 1.0, atol=1e-8)
    assert bm.eb_beta_l(20)[-1] == pytest.approx(41 * math.pi / 2, rel=1e-12)


def test_eb_and_axial_frequencies_closed_form() -> None:
    """Bending (beta_n L)^2 sqrt(EI / rho A) / L^2 and axial n pi c / L to 1e-6."""
    L, E, I, rA = SEC.length, SEC.E, SEC.second_moment, SEC.rho_a
    om = bm.eb_frequencies(SEC, 5)
    ref = np.array(bm.BETA_L_TABLE) ** 2 / L**2 * math.sqrt(E * I / rA)
    np.testing.assert_allclose(om, ref, rtol=1e-6)
    c = math.sqrt(E / SEC.rho_eff)
    np.testing.assert_allclose(
        bm.axial_frequencies(SEC, 6), np.arange(1, 7) * math.pi * c / L, rtol=1e-12
    )
    assert om[0] / (2 * math.pi) == pytest.approx(762.1, abs=0.1)


@pytest.mark.parametrize("k", [1, 2, 3, 6, 12])
def test_eb_shapes(k: int) -> None:
    """Mass-normalised, orthogonal to the rigid modes and to mode 1, stiffness = omega^2, free
    ends (W'' = W''' = 0), end values 2/sqrt(m), slope = dW/ds."""
    L, m, EI, rA = SEC.length, SEC.mass, SEC.E * SEC.second_moment, SEC.rho_a

    def W(s: np.ndarray) -> np.ndarray:
        return bm.eb_shape(SEC, k, s)

    assert quad(lambda s: rA * W(s) ** 2, L) == pytest.approx(1.0, rel=1e-10)
    assert abs(quad(lambda s: rA * W(s), L)) < 1e-10
    assert abs(quad(lambda s: rA * s * W(s), L)) < 1e-10
    if k > 1:
        assert abs(quad(lambda s: rA * W(s) * bm.eb_shape(SEC, 1, s), L)) < 1e-10
    om = bm.eb_frequencies(SEC, k)[-1]
    assert quad(lambda s: EI * bm.eb_shape(SEC, k, s, 2) ** 2, L) == pytest.approx(om**2, rel=1e-6)
    ends = np.array([-L / 2, L / 2])
    beta = bm.eb_beta_l(k)[-1] / L
    scale2 = beta**2 * 2 / math.sqrt(m)
    assert np.max(np.abs(bm.eb_shape(SEC, k, ends, 2))) < 1e-6 * scale2
    assert np.max(np.abs(bm.eb_shape(SEC, k, ends, 3))) < 1e-6 * scale2 * beta
    np.testing.assert_allclose(np.abs(bm.eb_shape(SEC, k, ends)), 2 / math.sqrt(m), rtol=1e-10)
    h = 1e-6
    fd = (W(ends + h) - W(ends - h)) / (2 * h)
    np.testing.assert_allclose(bm.eb_shape(SEC, k, ends, 1), fd, rtol=1e-6)


@pytest.mark.parametrize("k", [1, 2, 5])
def test_axial_shapes(k: int) -> None:
    L, rA, EA = SEC.length, SEC.rho_a, SEC.E * SEC.area
    U = lambda s: bm.axial_shape(SEC, k, s)  # noqa: E731
    assert quad(lambda s: rA * U(s) ** 2, L) == pytest.approx(1.0, rel=1e-12)
    assert abs(quad(lambda s: rA * U(s), L)) < 1e-12
    om = bm.axial_frequencies(SEC, k)[-1]
    dU = lambda s: bm.axial_slope(SEC, k, s)  # noqa: E731
    assert quad(lambda s: EA * dU(s) ** 2, L) == pytest.approx(om**2, rel=1e-6)
    h = 1e-7
    s = np.array([-0.1, 0.03, 0.12])
    np.testing.assert_allclose(dU(s), (U(s + h) - U(s - h)) / (2 * h), rtol=1e-6)


@pytest.mark.parametrize("k", [1, 3, 8])
def test_timoshenko_shapes(k: int) -> None:
    """Mass-normalised with rotary inertia, orthogonal to the rigid modes, energy = omega^2,
    free-end conditions psi' = gamma = 0."""
    L, rA = SEC.length, SEC.rho_a
    rI = rA * SEC.second_moment / SEC.area
    EI = SEC.E * SEC.second_moment
    kGA = SEC.kappa * SEC.G * SEC.area
    om = timoshenko_frequencies(SEC, k)[-1]
    f = timoshenko_shape_fn(SEC, om)
    assert quad(lambda s: rA * f(s)[0] ** 2 + rI * f(s)[1] ** 2, L) == pytest.approx(1.0, rel=1e-10)
    assert abs(quad(lambda s: rA * f(s)[0], L)) < 1e-9
    assert abs(quad(lambda s: rA * s * f(s)[0] + rI * f(s)[1], L)) < 1e-9
    energy = quad(lambda s: EI * f(s)[2] ** 2 + kGA * f(s)[3] ** 2, L)
    assert energy == pytest.approx(om**2, rel=1e-6)
    _W, _P, dP, gam = f(np.array([-L / 2, L / 2]))
    scale = math.sqrt(om**2 / EI)
    assert np.max(np.abs(dP)) < 1e-6 * scale
    assert np.max(np.abs(gam)) < 1e-6 * scale * L


@pytest.mark.parametrize("diameter", [None, 0.05, 0.3048 / 20000])
def test_frequency_scan_equals_one_frequency_at_a_time(diameter: float | None) -> None:
    """The root scan's determinants, computed for all frequencies at once, are those of one
    frequency at a time to the bit, below and above the cut-off (the roots are refined from
    the scan's sign changes, so the frequencies depend on it)."""
    sec = SEC if diameter is None else RodSection.paper(diameter=diameter)
    cut = timoshenko_cutoff(sec)
    eb = bm.eb_frequencies(sec, 8)
    om = np.concatenate(
        [np.geomspace(0.3 * eb[0], 1.05 * eb[-1], 300), np.geomspace(0.5 * cut, 3.0 * cut, 300)]
    )
    om = om[np.abs(om / cut - 1.0) > 1e-6]
    one_at_a_time = np.array([_determinant(w, sec) for w in om])
    assert np.all(np.isfinite(one_at_a_time))
    assert np.array_equal(_determinants(sec, om).view(np.int64), one_at_a_time.view(np.int64))


def test_timoshenko_limits_and_fe() -> None:
    """A thin rod gives Euler-Bernoulli to 1e-6; the paper's rod agrees with an independent
    finite-element eigen-solution (corotational Timoshenko elements, Ne = 40 and 80,
    Richardson-extrapolated) to 2e-5."""
    thin = RodSection.paper(diameter=SEC.length / 20000)
    np.testing.assert_allclose(
        timoshenko_frequencies(thin, 5), bm.eb_frequencies(thin, 5), rtol=1e-6
    )
    om_t = timoshenko_frequencies(SEC, 6)
    assert np.all(om_t < bm.eb_frequencies(SEC, 6))
    body = FlexibleRod.paper()
    fes = []
    for ne in (40, 80):
        w = CorotationalRod.from_body(body, ne, math.radians(20), 9.80665).eigenfrequencies(12)
        fes.append(w[np.argsort(np.abs(w[:, None] - om_t[None, :]), axis=0)[0]])
    np.testing.assert_allclose(fes[1] + (fes[1] - fes[0]) / 3.0, om_t, rtol=2e-5)


def test_basis_end_values() -> None:
    b = modal_basis(SEC, 3, 4, EULER_BERNOULLI)
    assert b.n_modes == 7
    np.testing.assert_allclose(np.abs(b.U[:, :3]), math.sqrt(2 / SEC.mass), rtol=1e-12)
    np.testing.assert_allclose(b.U[1, :3], b.U[0, :3] * np.array([-1, 1, -1]), rtol=1e-12)
    np.testing.assert_allclose(np.abs(b.W[:, 3:]), 2 / math.sqrt(SEC.mass), rtol=1e-10)
    assert b.inertia == pytest.approx(SEC.mass * SEC.length**2 / 12, rel=1e-14)
    bt = modal_basis(SEC, 0, 3, TIMOSHENKO)
    assert bt.inertia == pytest.approx(SEC.mass * (SEC.length**2 / 12 + SEC.d**2 / 16))


def test_rigid_modes_orthonormal() -> None:
    L, rA = SEC.length, SEC.rho_a
    rI = rA * SEC.second_moment / SEC.area

    def mode(i: int, s: np.ndarray) -> list[np.ndarray]:
        return [np.broadcast_to(x, s.shape) for x in rigid_modes(SEC, s, TIMOSHENKO)[i]]

    for i in range(3):
        for j in range(3):
            val = quad(
                lambda s, i=i, j=j: (
                    rA * (mode(i, s)[0] * mode(j, s)[0] + mode(i, s)[1] * mode(j, s)[1])
                    + rI * mode(i, s)[2] * mode(j, s)[2]
                ),
                L,
            )
            assert val == pytest.approx(1.0 if i == j else 0.0, abs=1e-12)


@pytest.mark.parametrize("n", [1, 4, 8, 12])
def test_axial_residual_modes(n: int) -> None:
    """The two pseudo-modes reproduce the static end compliance of every truncated axial mode
    (direct sum to k = 2e5 plus its 1/k tail), lie above the retained band and are symmetric /
    antisymmetric."""
    om, U = axial_residual_modes(SEC, n)
    s = math.pi * SEC.bar_speed / SEC.length
    k = np.arange(n + 1, 200001, dtype=float)
    u2 = 2 / SEC.mass
    G00 = u2 / s**2 * (np.sum(1 / k**2) + 1 / 200000.5)
    G01 = u2 / s**2 * np.sum((-1) ** k / k**2)
    assert np.sum(U[0] ** 2 / om**2) == pytest.approx(G00, rel=1e-9)
    assert np.sum(U[1] ** 2 / om**2) == pytest.approx(G00, rel=1e-9)
    assert np.sum(U[0] * U[1] / om**2) == pytest.approx(G01, rel=1e-6, abs=1e-9 * G00)
    assert np.all(om > n * s)
    np.testing.assert_allclose(np.abs(U[0]), np.abs(U[1]), rtol=1e-10)


def test_flexible_rod_body() -> None:
    """Diameter from mass (or mass from diameter), the defaults, the rigid equivalent, and one
    clear ValueError per invalid parameter."""
    rod = FlexibleRod.paper()
    assert rod.section.d == pytest.approx(SEC.d, rel=1e-14)
    assert (rod.n_axial, rod.n_bending, rod.axial_residual, rod.theory) == (
        8,
        12,
        True,
        TIMOSHENKO,
    )
    assert rod.basis().n_modes == 22
    assert rod.rigid().inertia == pytest.approx(rod.inertia, rel=1e-15)
    by_d = FlexibleRod(length=0.3048, tip_radius=0.0088, diameter=SEC.d, material=AISI_201)
    assert by_d.mass == pytest.approx(0.4607, rel=1e-12)
    assert by_d.basis().omega == pytest.approx(rod.basis().omega, rel=1e-9)
    bad = [
        ({"mass": None, "diameter": None}, "mass"),
        ({"mass": -1.0}, "mass"),
        ({"n_bending": 2.5}, "n_bending"),
        ({"n_axial": 0, "axial_residual": True}, "axial_residual"),
        ({"damping": 1.0}, "damping"),
        ({"theory": "rayleigh"}, "theory"),
        ({"tip_radius": 0.2}, "tip_radius"),
        ({"geometric": 1}, "geometric"),
    ]
    for kw, word in bad:
        with pytest.raises(ValueError, match=word):
            FlexibleRod.paper(**kw)


@pytest.mark.parametrize(("section", "counts"), [
    ("paper", (64, 96)),  # the paper's rod: a pair at 193.63 / 193.66 kHz
    ("thick", (24, 96)),  # L/d = 8, cut-off 25 kHz: a pair at 31.44 / 31.45 kHz
])  # fmt: skip
def test_near_equal_roots_above_the_cut_off_are_both_found(
    section: str, counts: tuple[int, int]
) -> None:
    """Above the cut-off two roots can fall within one grid step (whose spacing follows the
    count asked for): the first n frequencies are the same whatever the count, none missed."""
    if section == "paper":
        rod = FlexibleRod.paper()
    else:
        rod = FlexibleRod(length=0.594, tip_radius=0.594 / 16, diameter=0.594 / 8,
                          material=AISI_201, n_axial=1, n_bending=1)  # fmt: skip
    few, many = (timoshenko_frequencies(rod.section, n) for n in counts)
    np.testing.assert_allclose(many[: counts[0]], few, rtol=1e-12)
    assert np.all(np.diff(many) > 0)
