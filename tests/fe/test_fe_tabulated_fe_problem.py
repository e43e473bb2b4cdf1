"""``fe.tabulated_law`` makes its curves dimensionless with the FE problem's own delta_c, F_c and
E*/S_y (``Problem.pair``) and refuses, before any run, a rigid sphere whose problem is another
contact than the pair's (before: the rigid-sphere runs were scaled with the deformable pair's
delta_c and F_c, labelled with its E*/S_y, cached and returned as its law); it builds and
checks the law before writing the curves to the cache (before: written first, so a law that
failed was kept and ``law="tabulated"`` read it); and it refuses ``unload=False`` before any
run (a loading-only run has no residual depth). The FE runs are stand-ins: no ccx."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab.contact import get_law
from impactlab.contact._common import jg_critical
from impactlab.contact.tabulated import curves_cache_dir
from impactlab.fe.curves import load_case
from impactlab.fe.problem import make_problem
from impactlab.fe.tabulated import tabulated_law
from impactlab.materials import AISI_201, AISI_1010, PMMA, ContactPair

R = 8.8e-3
PAIR = ContactPair(AISI_201, AISI_1010)


def never(*args: Any, **kwargs: Any) -> Any:
    pytest.fail("FE runs started")


def _jackson_green_runs(seen: list[dict[str, Any]]) -> Any:
    """A stand-in for ``indent``: what the FE problem asked computes, taken as Jackson-Green's
    law of that problem's own pair (``Problem.pair``: a rigid sphere's E* is the flat's)."""

    def run(flat: Any, body: Any, *, radius: float, delta_max: Any, **kw: Any) -> Any:
        seen.append({"delta_max": list(delta_max), **kw})
        out = []
        for d in delta_max:
            p = make_problem(flat, body, radius=radius, delta_max=d, **kw)
            law = get_law("jackson-green").build(p.pair, radius)
            ld = np.geomspace(p.delta_low, d, 60)
            f = np.array([law.force(x) for x in ld])
            out.append(_Run(d, ld, f, law.unload(d).delta_r))
        return out

    return run


@dataclasses.dataclass
class _Run:
    delta_max: float
    loading_delta: np.ndarray
    loading_force: np.ndarray
    residual_depth: float
    converged: bool = True


def test_a_rigid_sphere_whose_problem_is_another_contact_is_refused_before_running(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))
    with pytest.raises(
        ValueError, match=r"^sphere='rigid' makes FE curves of the flat against a "
    ) as e:
        tabulated_law(PAIR, R, runner=never, sphere="rigid")
    text = str(e.value)
    assert "E*/S_y = 720.6 (E* = 219.8 GPa, the flat's alone)" in text
    assert "has E*/S_y = 360.3 (E* = 109.9 GPa)" in text
    assert "within 5 % of the pair's E*/S_y" in text
    assert text.endswith(
        "leave sphere='elastic-plastic' (the default) or give sphere='elastic', so that the FE "
        "models the pair's sphere"
    )
    assert not list(tmp_path.rglob("*.json"))


def test_a_near_rigid_spheres_curves_are_in_the_fe_problems_own_scale(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Steel on PMMA: the rigid problem's E*/S_y is within 5 % of the pair's (1.8 % off), so
    it runs; the curves are the FE problem's, F/F_c and delta/delta_c of that problem."""
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))
    pair = ContactPair(AISI_201, PMMA)
    fe = make_problem(PMMA, AISI_201, radius=R, delta_max=1e-6, sphere="rigid").pair
    fe_ratio, ratio = fe.E_star / fe.yield_strength, pair.E_star / pair.yield_strength
    assert 0.01 < fe_ratio / ratio - 1.0 < 0.05
    seen: list[dict[str, Any]] = []
    maxima = (1.0, 2.0, 3.0, 6.0, 10.0)
    model = tabulated_law(
        pair, R, runner=_jackson_green_runs(seen), sphere="rigid", maxima_over_delta_c=maxima
    )
    dc, fc = jg_critical(fe.E_star, R, fe.yield_strength, fe.nu)
    assert seen[0]["delta_max"] == [m * dc for m in maxima]  # the FE problem's delta_c
    (path,) = curves_cache_dir().glob("*.json")
    (record,) = json.loads(path.read_text())["curves"]
    assert record["e_star_over_sy"] == fe_ratio  # before: the pair's E*/S_y
    assert record["nu"] == fe.nu
    assert np.allclose(record["delta_max"], maxima, rtol=1e-12)
    jg = get_law("jackson-green").build(fe, R)
    d = np.array(record["delta"][-5:]) * dc
    assert np.allclose(np.array(record["force"][-5:]) * fc, [jg.force(x) for x in d], rtol=1e-12)
    assert model.details["curves_e_star_over_sy"] == fe_ratio
    assert model.source.startswith(f"{path.stem}: FE runs of impactlab.fe.indent")


def _stiffer_runs(seen: list[Any]) -> Any:
    """The shipped aluminium case's runs, rescaled to the paper's pair and made stiffer than
    Hertz past delta_c (F ~ delta^1.8), which the law's fit cannot follow."""
    case = load_case("aisi201-on-al6061t6")
    dc0, _ = jg_critical(case.pair.E_star, case.radius, case.pair.yield_strength, case.pair.nu)
    dc1, fc1 = jg_critical(PAIR.E_star, R, PAIR.yield_strength, PAIR.nu)

    def run(flat: Any, body: Any, *, radius: float, delta_max: Any, **kw: Any) -> Any:
        seen.append(kw)
        out = []
        for r in case.runs:
            x = r.loading_delta / dc0
            out.append(
                dataclasses.replace(
                    r,
                    delta_max=r.delta_max / dc0 * dc1,
                    loading_delta=x * dc1,
                    loading_force=x**1.8 * fc1 / x[x > 0][0] ** 0.3,
                    residual_depth=r.residual_depth / dc0 * dc1,
                )
            )
        return out

    return run


def test_the_law_is_checked_before_its_curves_are_cached(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))
    seen: list[Any] = []
    with pytest.raises(ValueError, match=r"the law's loading fit departs from the data's force"):
        tabulated_law(PAIR, R, runner=_stiffer_runs(seen), mesh_level=2)
    assert len(seen) == 1
    assert not list(tmp_path.rglob("*.json"))
    # law="tabulated" still takes the shipped curves: nothing bad was kept
    assert get_law("tabulated").build(PAIR, R).source.startswith("paper-aisi201-on-aisi1010: ")


@pytest.mark.parametrize("unload", [False, 0, "no", None])
def test_loading_only_runs_are_refused_before_running(
    unload: Any, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))
    with pytest.raises(
        ValueError, match=r"^unload must be True \(the default\) for tabulated_law, "
    ):
        tabulated_law(PAIR, R, runner=never, unload=unload, mesh_level=2)
