"""``fe.tabulated_law`` for a pair whose sphere yields (an aluminium sphere on a bearing-steel
flat) runs the FE of that pair instead of taking the shipped aluminium flat's curves, labels
the curves it keeps "sphere", and ``law="tabulated"`` finds them for that pair only; an FE
model that would make the other body yield (an elastic sphere) is refused before any run.
``fe.indent`` refuses a ``workers`` that is not an integer (1.5 and "2" were int()-ed). The FE
runs are the shipped aluminium case's, rescaled to the pair: no ccx."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path
from typing import Any

import pytest

from impactlab import fe
from impactlab.contact import get_law
from impactlab.contact._common import jg_critical
from impactlab.contact.tabulated import curves_cache_dir
from impactlab.fe.curves import load_case
from impactlab.fe.tabulated import shipped_fe_curves, tabulated_law
from impactlab.materials import AISI_201, AISI_1010, AISI_52100, AL_6061_T6, ContactPair

R = 8.8e-3
PAIR = ContactPair(AL_6061_T6, AISI_52100)  # the sphere yields


def _runner(pair: ContactPair, seen: list[dict[str, Any]]) -> Any:
    case = load_case("aisi201-on-al6061t6")
    dc0, fc0 = jg_critical(case.pair.E_star, case.radius, case.pair.yield_strength, case.pair.nu)
    dc1, fc1 = jg_critical(pair.E_star, R, pair.yield_strength, pair.nu)

    def run(flat: Any, body: Any, *, radius: float, delta_max: Any, **kw: Any) -> Any:
        seen.append({"flat": flat, "body": body, **kw})
        return [
            dataclasses.replace(
                r,
                delta_max=r.delta_max / dc0 * dc1,
                loading_delta=r.loading_delta / dc0 * dc1,
                loading_force=r.loading_force / fc0 * fc1,
                residual_depth=r.residual_depth / dc0 * dc1,
            )
            for r in case.runs
        ]

    return run


def test_a_pair_whose_sphere_yields_gets_curves_of_its_own(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))
    seen: list[dict[str, Any]] = []
    model = tabulated_law(PAIR, R, runner=_runner(PAIR, seen))
    assert len(seen) == 1 and seen[0]["flat"] is AISI_52100 and seen[0]["body"] is AL_6061_T6
    assert "sphere" not in seen[0]  # indent's default: an elastic-plastic sphere
    assert model.source.startswith("fe-") and "FE runs of impactlab.fe.indent" in model.source
    (path,) = curves_cache_dir().glob("*.json")
    assert [c["yielding"] for c in json.loads(path.read_text())["curves"]] == ["sphere"]
    again = get_law("tabulated").build(PAIR, R)  # found in the cache, no run
    assert again.source == model.source and again.params.tobytes() == model.params.tobytes()
    assert tabulated_law(PAIR, R, runner=_runner(PAIR, seen)).source == model.source
    assert len(seen) == 1
    # the aluminium case's own pair (its flat yields) keeps the shipped curves
    flat_pair = load_case("aisi201-on-al6061t6").pair
    assert get_law("tabulated").build(flat_pair, R).source.startswith("aisi201-on-al6061t6: ")


def test_an_fe_model_whose_other_body_yields_is_refused_before_running(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))

    def never(*args: Any, **kwargs: Any) -> Any:
        pytest.fail("FE runs started")

    for sphere in ("elastic", "rigid"):
        with pytest.raises(ValueError, match=rf"^sphere='{sphere}' makes FE curves whose flat "):
            tabulated_law(PAIR, R, runner=never, sphere=sphere)
    flat_yields = ContactPair(AISI_201, dataclasses.replace(AISI_1010, yield_strength=200e6))
    with pytest.raises(ValueError, match=r"^flat_hardening='elastic' makes FE curves whose sphere"):
        tabulated_law(flat_yields, R, runner=never, flat_hardening="elastic")


def test_the_shipped_fe_cases_are_of_a_yielding_flat() -> None:
    assert {c.yielding for c in shipped_fe_curves()} == {"flat"}


@pytest.mark.parametrize("workers", [1.5, "2", True, 2.0, 0])
def test_indent_refuses_a_workers_that_is_no_count(workers: Any) -> None:
    with pytest.raises(ValueError, match=r"^workers must be a positive integer .*got"):
        fe.indent(AISI_1010, AISI_201, radius=R, delta_max=1e-6, workers=workers)
