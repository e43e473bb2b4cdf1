"""The verification cases of docs/verification (impactlab.verification) with fewer cases, and
the same tolerances, asserted here: the published tables come from tested code."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from impactlab import verification as V
from impactlab.analytic import critical_friction
from impactlab.bodies import PAPER_ROD, rigid_impulse
from impactlab.verification.reference import case_inputs

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "verification" / "index.md"

pytestmark = pytest.mark.usefixtures("warm_engine")


def test_tolerances_are_the_published_ones() -> None:
    # changing a tolerance must be a visible decision: the page states these numbers
    assert V.TOLERANCES == {
        "hertz": 1e-6,
        "thornton": 2e-6,
        "rigid": 1e-6,
        "critical_friction": 1e-6,
        "reference": 1e-5,
        "paper_duration": 0.05,
        "invariants": 1e-6,
        "energy_history": 2e-5,
    }


def test_hertz_closed_forms() -> None:
    t = V.verify_hertz(V.HERTZ_CASES[:2])
    assert t.passed, t.to_markdown()
    assert t.worst <= 1e-6
    for r in t.records:
        assert r["err_T"] <= 1e-6 and r["err_F"] <= 1e-6 and r["err_delta"] <= 1e-6
        assert r["err_e"] <= 1e-6 and r["err_e_energy"] <= 1e-6


def test_hertz_closed_form_numbers() -> None:
    # T = 2.9432 delta_m / v (Johnson 1985, Sec. 11.4)
    dm, fm, T = V.hertz_closed_form(1.0, 1e11, 0.01, 1.0)
    assert T * 1.0 / dm == pytest.approx(2.9432, rel=1e-4)
    assert fm == pytest.approx(4 / 3 * 1e11 * 0.1 * dm**1.5, rel=1e-12)
    # energy: the work of the Hertz force up to delta_m equals the kinetic energy
    assert 0.4 * fm * dm == pytest.approx(0.5 * 1.0 * 1.0**2, rel=1e-12)


def test_hertz_converges_with_rtol() -> None:
    conv = V.hertz_convergence((1e-5, 1e-9))
    assert conv["T"][1] < conv["T"][0] and conv["delta"][1] < 1e-8


def test_thornton_closed_form() -> None:
    t = V.verify_thornton(7)
    assert t.passed, t.to_markdown()
    assert t.worst <= 2e-6
    ratios = [r["ratio"] for r in t.records]
    assert min(ratios) == 0.5 and max(ratios) == pytest.approx(1000.0)
    assert t.records[0]["e_engine"] == pytest.approx(1.0, abs=1e-6)  # elastic below V_y


def test_rigid_limits_slip_and_stick() -> None:
    t = V.verify_rigid_limits((0.5, 1.5))
    assert t.passed, t.to_markdown()
    assert [r["regime"] for r in t.records] == ["slip", "stick"]
    assert t.worst <= 1e-6


def test_rigid_impulse_is_consistent_at_mu_c() -> None:
    # the rigid-body solution the rigid-limit table uses (impactlab.bodies.rigid_impulse, e = 1)
    th = math.radians(20.0)
    mu_c = float(critical_friction(th, PAPER_ROD))
    below = rigid_impulse(PAPER_ROD, th, (0.0, -1.0), e=1.0, mu=mu_c * (1 - 1e-12))
    above = rigid_impulse(PAPER_ROD, th, (0.0, -1.0), e=1.0, mu=mu_c)
    # at mu_c the slip solution has v_t = 0 and joins the stick solution continuously
    assert below.regime == "slip" and above.regime == "stick"
    assert below.normal_impulse == pytest.approx(above.normal_impulse, rel=1e-9)
    assert abs(below.contact_velocity_out[0]) < 1e-9


def test_critical_friction_boundary() -> None:
    t = V.verify_critical_friction((10, 45, 80), iterations=24)
    assert t.passed, t.to_markdown()
    assert t.worst <= 1e-6


def test_engine_vs_reference() -> None:
    t = V.verify_reference(
        V.reference_cases(["hertz", "ghaednia", "thornton"], ["impulse_ratio", "mindlin"])
    )
    failed = [r for r in t.records if str(r["status"]).startswith("reference failed")]
    assert not failed, failed
    assert t.passed, t.to_markdown()
    # the accuracy contract of the engine's default tolerance (tests/dynamics/test_accuracy.py,
    # docs/engine/benchmarks.md): within 1e-5 of a reference at rtol = 1e-11
    assert t.worst <= 1e-5 and V.TOLERANCES["reference"] == 1e-5
    text = " ".join(t.text.split())
    assert V.reference.REFERENCE_RTOL == 1e-11
    assert "default tolerance rtol = 2e-7) against" in text and "at rtol = 1e-11:" in text
    assert "the tolerance, 1e-5, is the engine's accuracy contract" in text


def test_reference_runs_at_the_stated_rtol(monkeypatch: pytest.MonkeyPatch) -> None:
    # the errors are the engine's: the reference runs at REFERENCE_RTOL, not the engine's rtol
    seen: list[object] = []
    real = V.reference.simulate_reference

    def spy(*args: object, **kw: object) -> object:
        seen.append(kw.get("rtol"))
        return real(*args, **kw)  # type: ignore[arg-type]

    monkeypatch.setattr(V.reference, "simulate_reference", spy)
    V.verify_reference(V.reference_cases(["hertz"], ["coulomb"]))
    assert seen == [1e-11]


def test_reference_is_converged_at_its_rtol() -> None:
    # the page: "The reference changes by less than 1e-9 of these scales from rtol = 1e-11 to
    # 1e-12" (every case of the page)
    from impactlab.dynamics.reference import simulate_reference

    worst = 0.0
    for c in V.reference_cases():
        body, kw = case_inputs(c)
        a = simulate_reference(body, rtol=1e-11, **kw)
        b = simulate_reference(body, rtol=1e-12, **kw)
        scale = {
            "e": 1.0,
            "delta_p": b["delta_max"],
            "sliding_length": max(abs(b["sliding_length"]), b["delta_max"]),
            "duration": abs(b["duration"]),
            "max_force": abs(b["max_force"]),
        }
        worst = max(worst, *(abs(a[q] - b[q]) / s for q, s in scale.items()))
    assert worst < 1e-9
    assert "less than 1e-9 of these scales from rtol = 1e-11 to 1e-12" in " ".join(
        V.verify_reference(V.reference_cases(["hertz"], ["coulomb"])).text.split()
    )


def test_paper_durations() -> None:
    t = V.verify_paper_durations(500)
    assert t.passed, t.to_markdown()
    by_angle = {r["angle"]: r for r in t.records}
    assert by_angle[20.0]["T"] == pytest.approx(4.106, abs=0.002)  # ms, docs/analytic.md
    assert by_angle[45.0]["T"] == pytest.approx(1.382, abs=0.002)
    assert by_angle[70.0]["err_T"] is None  # the paper prints no T at 70 deg


def test_invariants() -> None:
    t = V.verify_invariants(3, laws=["ghaednia", "hertz"], frictions=["coulomb", "mindlin"])
    assert t.passed, t.to_markdown()
    assert all(r["n"] == 3 for r in t.records)


def test_markdown_marks_a_failure() -> None:
    t = V.verify_paper_durations(200)
    bad = V.VerificationTable(
        t.key, t.title, t.text, t.columns, t.records, t.metric, 1.0, 0.05, False
    )
    assert "**FAIL**" in bad.to_markdown() and "**pass**" in t.to_markdown()
    assert "| 20 |" in t.to_markdown()


def test_main_writes_page_and_figures(tmp_path: Path) -> None:
    tables = V.main(tmp_path / "ver", fast=True, log=None)
    page = (tmp_path / "ver" / "index.md").read_text()
    for t in tables:
        assert f"## {t.title}" in page
        assert f"(#{V.anchor(t.title)})" in page
    for name in ("thornton_restitution.png", "critical_friction.png", "hertz_convergence.png"):
        assert (tmp_path / "ver" / name).stat().st_size > 1000
    assert sorted(p.name for p in (tmp_path / "ver").iterdir()) == [
        "critical_friction.png",
        "hertz_convergence.png",
        "index.md",
        "partial_slip_kharaz.png",
        "partial_slip_mbf.png",
        "partial_slip_thornton.png",
        "thornton_restitution.png",
    ]


def test_published_page_is_generated() -> None:
    page = PAGE.read_text()
    assert "Generated by `python -m impactlab.verification docs/verification`" in page
    for name in ("thornton_restitution.png", "critical_friction.png", "hertz_convergence.png"):
        assert f"]({name})" in page and (PAGE.parent / name).exists()
    for key, tol in V.TOLERANCES.items():
        if key != "invariants":  # stated inside the invariants text
            assert f"| {tol:.3g} |" in page, key


#: Lines of the page that depend on the installation, not on the results: the versions.
MACHINE_LINES = ("Generated with impactlab ",)


def _content(text: str) -> list[str]:
    return [ln for ln in text.splitlines() if not ln.startswith(MACHINE_LINES)]


@pytest.mark.slow
def test_published_page_is_what_the_generator_writes() -> None:
    """The committed page is the generator's output, line for line, except the versions line
    (regenerate it with ``python -m impactlab.verification docs/verification``)."""
    fresh = _content(V.page_markdown())
    published = _content(PAGE.read_text())
    diff = [
        f"line {i}: published {a!r} / generated {b!r}"
        for i, (a, b) in enumerate(zip(published, fresh, strict=False), 1)
        if a != b
    ]
    assert len(published) == len(fresh) and not diff, "\n".join(diff[:10]) or (
        f"{len(published)} published lines, {len(fresh)} generated"
    )


def test_page_markdown_is_what_main_writes(tmp_path: Path) -> None:
    V.main(tmp_path, fast=True, figures=False, log=None)
    assert (tmp_path / "index.md").read_text() == V.page_markdown(fast=True)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["index.md"]


def test_partial_slip_cost_is_that_of_its_benchmark_page() -> None:
    # the cost sentence quotes docs/engine/partial-slip-steps.md; nothing is timed at page time
    from impactlab.verification.partial_slip_page import TEXT

    steps = (ROOT / "docs" / "engine" / "partial-slip-steps.md").read_text()
    flat = " ".join(steps.split())
    cost = " ".join(
        TEXT[TEXT.index("**Convergence and cost.**") : TEXT.index("**Validity.**")].split()
    )
    assert "docs/engine/partial-slip-steps.md" in cost and "bench_partial_slip.py" in cost
    for quoted in ("13.3 and 13.9 times", "168-169 us", "14.6 and 15.2", "182-183"):
        assert quoted in cost and quoted in flat, quoted
    assert "0.26 ms" not in cost and "16-18 times" not in cost


def test_page_carries_the_corrected_doi() -> None:
    page = PAGE.read_text()
    assert "doi:10.1016/0043-1648(76)90201-5" in page  # Maw, Barber & Fawcett, Wear 38 (1976) 101
    assert "90063-6" not in page
