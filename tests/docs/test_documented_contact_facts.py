"""What the contact-law and engine pages state about the contact radius, Brake's unloading rule,
Jackson-Green's switch and the friction regime stays equal to what the code computes (paper's
pair and rod)."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import impactlab as il
from impactlab.bodies import rod as rod_module
from impactlab.bodies.layout import BP_GSTAR
from impactlab.contact import builtin_law_names, get_law, quasi_static_rebound
from impactlab.contact import history_kernels as hk
from impactlab.contact.base import ContactModel
from impactlab.materials import AISI_201, AISI_1010, ContactPair

ROOT = Path(__file__).resolve().parents[2]
LAWS = ROOT / "docs" / "laws"
R = 8.8e-3
MASS = 0.4607
PAIR = ContactPair(AISI_201, AISI_1010)


def _text(path: Path) -> str:
    return " ".join(path.read_text().split())


def _models() -> dict[str, ContactModel]:
    return {name: get_law(name).build(PAIR, R) for name in builtin_law_names()}


def _radius_ratios(m: ContactModel) -> np.ndarray:
    """a_unloading / a_loading at the turning point, for the turning points that are not
    elastic (no residual depth, force within 1e-4 of Hertz's: Kogut-Komvopoulos' elastic
    branch is Hertz's truncated), delta_m up to 1000 delta_c."""
    dc = m.critical_interference
    hi = min(1000.0 * dc, 0.999 * m.max_interference)
    out = []
    for dm in np.geomspace(1e-3 * dc, hi, 3000):
        b = m.unload(dm)
        hertz = 4.0 / 3.0 * m.E_star * math.sqrt(R) * dm**1.5
        if b.delta_r == 0.0 and abs(b.F_m / hertz - 1.0) < 1e-4:
            continue
        out.append(float(b.contact_radius(dm)) / float(m.contact_radius(dm)))
    return np.array(out)


def test_laws_page_lists_the_laws_with_a_continuous_radius() -> None:
    """The unloading radius starts at the loading radius for exactly the laws named, and the
    stated jumps of the others are the computed ones (to the digits given)."""
    text = _text(LAWS / "index.md")
    m = re.search(r"At the turning point it equals the loading radius at every `delta_m` for "
                  r"(.*?) \(Brake's residual depth", text)  # fmt: skip
    assert m, "the laws page names the laws whose radius is continuous"
    named = set(re.findall(r"`([\w-]+)`", m.group(1)))
    stated = {n: (float(lo), float(hi)) for lo, hi, n in
              re.findall(r"(\d[\d.]*)-(\d[\d.]*) for `([\w-]+)`", text)}  # fmt: skip
    continuous = set()
    for name, model in _models().items():
        r = _radius_ratios(model)
        if np.all(np.abs(r - 1.0) < 1e-9):
            continuous.add(name)
            continue
        lo, hi = stated[name]
        assert r.min() == pytest.approx(lo, abs=0.006), name
        assert r.max() == pytest.approx(hi, abs=0.006), name
    assert named == continuous == {"hertz", "brake", "thornton"}


def test_brake_unloading_is_thorntons_rule() -> None:
    """delta_r = delta_m - 3 F_m/(4 E* a_m), a_m = sqrt(R delta_m), and the page cites
    Thornton's paper with the DOI the package uses for it."""
    m = get_law("brake").build(PAIR, R)
    for dm in np.geomspace(2.0 * m.critical_interference, 0.5 * m.max_interference, 50):
        b = m.unload(dm)
        am = math.sqrt(R * dm)
        assert b.delta_r == pytest.approx(dm - 3.0 * b.F_m / (4.0 * m.E_star * am), rel=1e-12)
        assert b.R_r == pytest.approx(4.0 * m.E_star * am**3 / (3.0 * b.F_m), rel=1e-10)
    doi = get_law("thornton").build(PAIR, R).references[0].doi
    eq27 = _text(LAWS / "brake.md").split("**Eq. 27**")[1].split("## ")[0]
    assert "exactly Thornton's published unloading rule" in eq27
    assert f"doi:{doi}" in eq27


def test_loading_radius_of_brake_and_kogut_komvopoulos_is_hertz_and_said_so() -> None:
    for name in ("brake", "kogut-komvopoulos", "tabulated"):
        m = get_law(name).build(PAIR, R)
        d = np.geomspace(1e-3, 300.0, 20) * m.critical_interference
        assert np.allclose(m.contact_radius(d), np.sqrt(R * d), rtol=1e-14), name
    assert "kogut_komvopoulos" in (hk.__doc__ or "") and "brake" in (hk.__doc__ or "")
    assert "where it defines one" not in " ".join((hk.__doc__ or "").split())
    for page in ("brake.md", "kogut-komvopoulos.md"):
        assert "is Hertz's `sqrt(R delta)` on loading" in _text(LAWS / page), page
    assert "up to about 29 % smaller than FE's" in _text(LAWS / "index.md")


def test_mindlin_effect_of_a_larger_radius_is_as_stated(monkeypatch: pytest.MonkeyPatch) -> None:
    """k_t = 8 G* a: scaling G* scales a in every mindlin quantity; the laws page states the
    largest changes for a factor 1.1 and 1.41."""
    original = rod_module.Rod.to_params
    factor = [1.0]

    def scaled(self: il.Rod, flat: il.Material = AISI_1010) -> np.ndarray:
        p = original(self, flat)
        p[BP_GSTAR] *= factor[0]
        return p

    monkeypatch.setattr(rod_module.Rod, "to_params", scaled)
    rod = il.Rod.paper()
    de = dvt = stick = 0.0
    dj = {1.1: 0.0, 1.41: 0.0}
    for law in ("brake", "kogut-komvopoulos"):
        for angle in (20.0, 45.0):
            for v in (1.41, 3.45):
                runs = {}
                for c in (1.0, 1.1, 1.41):
                    factor[0] = c
                    runs[c] = il.simulate(rod, law=law, friction="mindlin", mu=0.2,
                                          angle=math.radians(angle), velocity=(0.0, -v),
                                          law_params={}, history=False)  # fmt: skip
                b = runs[1.0]
                for c in (1.1, 1.41):
                    r = runs[c]
                    de = max(de, abs(r.e - b.e))
                    dvt = max(dvt, abs(r.vt_out / b.vt_out - 1.0))
                    dj[c] = max(dj[c], abs(r.tangential_impulse / b.tangential_impulse - 1.0))
                    stick = max(stick, b.stick_time / b.duration - r.stick_time / r.duration)
    text = _text(LAWS / "index.md")
    assert (f"`e` changes by at most {de:.2g}, `vt_out` by at most {100 * dvt:.2g} %, the "
            f"tangential impulse by up to {100 * dj[1.1]:.2g} % (1.1) and {100 * dj[1.41]:.2g} % "
            f"(1.41), and the share of the contact without gross slip falls by up to "
            f"{100 * stick:.0f} points") in text  # fmt: skip


def test_jackson_green_switch_effect_on_e_is_as_stated() -> None:
    law = get_law("jackson-green")
    default, published = (law.build(PAIR, R, published_switch=s) for s in (0, 1))
    text = _text(LAWS / "jackson-green.md")
    assert "below 0.1 %" not in text
    for v, form in ((0.003864, "up to {d:.2f} % ({v:.2f} mm/s"), (0.004, "({a:.4f} vs {b:.4f},")):
        a = quasi_static_rebound(default, MASS, v).restitution
        b = quasi_static_rebound(published, MASS, v).restitution
        d = 100.0 * (b / a - 1.0)
        assert form.format(d=d, v=1e3 * v, a=a, b=b) in text
    assert f"{100.0 * (b / a - 1.0):.3f} %" in text


@pytest.mark.parametrize("friction", ["mindlin", "partial_slip"])
def test_tangential_models_report_stick_for_any_friction(friction: str) -> None:
    """Without initial slip the tangential force builds from zero, so the contact starts without
    gross slip: the regime is `stick` at the smallest mu the engine keeps, where coulomb slides
    throughout. A large initial slip, 4 G* |v_t| > mu E* |v_n|, starts in gross slip and is
    `slip` where the contact never leaves it; a smaller one is not `slip`."""
    kw: dict[str, Any] = {
        "angle": math.radians(45.0),
        "velocity": (0.0, -1.41),
        "mu": 1e-9,
        "history": False,
    }
    r = il.simulate(il.Rod.paper(), friction=friction, **kw)
    assert r.regime == "stick"
    assert 0.0 < r.stick_time < 1e-3 * r.duration
    assert il.simulate(il.Rod.paper(), friction="coulomb", **kw).regime == "slip"
    row = next(ln for ln in (ROOT / "docs/engine/index.md").read_text().splitlines()
               if ln.startswith("| `regime` |"))  # fmt: skip
    assert "so every contact starts without gross slip" not in row
    assert "every contact without initial slip" in row
    assert "starts without gross slip and is never `slip`" in row
    assert "is `slip` where the contact never leaves it" in row
    assert "velocity (2.0, -1.41) m/s, mu = 0.1, `ghaednia`: stick time 0" in row
    assert "read `stick_time` / `duration`" in row
    assert f"0.03 us of {r.duration * 1e6:.0f} us" in row
    start = 4.0 * PAIR.G_star / (0.1 * PAIR.E_star * 1.41)  # the start ratio per m/s of v_t
    for vx, regime in ((2.0, "slip"), (0.1, "reversal")):
        kw.update(velocity=(vx, -1.41), mu=0.1, law="ghaednia")
        hit = il.simulate(il.Rod.paper(), friction=friction, **kw)
        assert (start * abs(hit.vt_in) > 1.0) == (vx == 2.0)
        assert hit.regime == regime
        assert (hit.stick_time == 0.0) == (regime == "slip")
