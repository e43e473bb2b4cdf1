"""``fe.tabulated_law`` uses stored curves (shipped or cached) only when they match every option
asked: the hardening, ``mu``, ``mesh_level`` (given or their defaults), and ``sphere`` and the
reach of ``maxima_over_delta_c`` where given. Before, any stored curves of the pair were
returned whatever was asked (the shipped perfectly plastic, frictionless, level-1 curves for
``flat_hardening=...``, ``mesh_level=3``, ``mu=0.5``; a cached 100-delta_c curve for a request
to 300), the runs never made. Without ``run_fe`` the refusal names each option that differs.
The FE runs are the shipped paper case's, rescaled to the pair: no ccx."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path
from typing import Any

import pytest

from impactlab.contact._common import jg_critical
from impactlab.contact.tabulated import curves_cache_dir
from impactlab.fe.curves import load_case
from impactlab.fe.tabulated import tabulated_law
from impactlab.materials import AISI_201, AISI_1010, ContactPair

R = 8.8e-3
PAPER = ContactPair(AISI_201, AISI_1010)
#: A pair no shipped curves fit (its flat's S_y lowered).
OTHER = ContactPair(AISI_201, dataclasses.replace(AISI_1010, yield_strength=200e6))
SY = AISI_1010.yield_strength
TABLE = [(SY, 0.0), (1.2 * SY, 0.1)]


def _runner(pair: ContactPair, made: list[dict[str, Any]]) -> Any:
    """A stand-in for ``indent``: the paper case's runs up to the largest maximum asked,
    rescaled to ``pair``; each call's arguments in ``made``."""
    case = load_case("paper-aisi201-on-aisi1010")
    dc0, fc0 = jg_critical(case.pair.E_star, case.radius, case.pair.yield_strength, case.pair.nu)
    dc1, fc1 = jg_critical(pair.E_star, R, pair.yield_strength, pair.nu)

    def run(flat: Any, body: Any, *, radius: float, delta_max: Any, **kw: Any) -> Any:
        top = max(delta_max) / dc1
        made.append({"top": top, **kw})
        return [
            dataclasses.replace(
                r,
                delta_max=r.delta_max / dc0 * dc1,
                loading_delta=r.loading_delta / dc0 * dc1,
                loading_force=r.loading_force / fc0 * fc1,
                residual_depth=r.residual_depth / dc0 * dc1,
            )
            for r in case.runs
            if r.delta_max / dc0 <= top * (1.0 + 1e-9)
        ]

    return run


@pytest.fixture(autouse=True)
def _own_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))


@pytest.mark.parametrize(
    "asked",
    [
        {"flat_hardening": TABLE},
        {"mesh_level": 3},
        {"mu": 0.5},
        {"maxima_over_delta_c": (1.0, 2000.0)},
        {"sphere": "elastic"},
    ],
    ids=["hardening", "mesh", "mu", "reach", "sphere"],
)
def test_shipped_curves_that_differ_in_an_option_are_not_used(asked: dict[str, Any]) -> None:
    made: list[dict[str, Any]] = []
    model = tabulated_law(PAPER, R, runner=_runner(PAPER, made), **asked)
    assert len(made) == 1 and "FE runs of impactlab.fe.indent" in model.source
    assert {k: v for k, v in made[0].items() if k != "top"} == {
        k: v for k, v in asked.items() if k != "maxima_over_delta_c"
    }
    record = json.loads(next(curves_cache_dir().glob("*.json")).read_text())
    assert record["fe_inputs"]["mesh_level"] == asked.get("mesh_level", 1)


@pytest.mark.parametrize(
    "asked",
    [{}, {"mesh_level": 1, "mu": 0.0}, {"flat_hardening": [(SY, 0.0)]},
     {"maxima_over_delta_c": (1.0, 1000.0)}, {"sphere": "elastic-plastic"}],
)  # fmt: skip
def test_shipped_curves_that_match_every_option_are_used(asked: dict[str, Any]) -> None:
    def never(*args: Any, **kwargs: Any) -> Any:
        pytest.fail("FE runs started")

    model = tabulated_law(PAPER, R, runner=never, **asked)
    assert model.source.startswith("paper-aisi201-on-aisi1010: ")


def test_without_runs_the_refusal_names_each_option_that_differs() -> None:
    with pytest.raises(ValueError, match=r"^the stored curves that fit") as err:
        tabulated_law(
            PAPER, R, run_fe=False, mesh_level=3, mu=0.5, flat_hardening=TABLE,
            maxima_over_delta_c=(1.0, 2000.0),
        )  # fmt: skip
    assert str(err.value) == (
        "the stored curves that fit the pair ('paper-aisi201-on-aisi1010') do not match the "
        "options asked: flat_hardening "
        "perfectly plastic, not a hardening table of 2 rows; mu 0, not 0.5; mesh_level 1, not "
        "3; reach 1000 delta_c, not 2000; run_fe=True makes curves with these options (FE "
        "runs: CalculiX)"
    )
    with pytest.raises(ValueError, match="no indentation curves for E"):  # as before
        tabulated_law(OTHER, R, run_fe=False)


def test_cached_curves_serve_only_the_options_they_were_made_with() -> None:
    made: list[dict[str, Any]] = []
    run = _runner(OTHER, made)
    first = tabulated_law(OTHER, R, runner=run, maxima_over_delta_c=(1.0, 3.0, 10.0, 100.0))
    assert [m["top"] for m in made] == [pytest.approx(100.0)]
    assert tabulated_law(OTHER, R, runner=run).source == first.source  # defaults: cached
    assert tabulated_law(OTHER, R, runner=run, maxima_over_delta_c=(1.0, 30.0)).source == (
        first.source
    )
    assert len(made) == 1
    further = tabulated_law(OTHER, R, runner=run, maxima_over_delta_c=(1.0, 3.0, 10.0, 300.0))
    assert len(made) == 2 and further.source != first.source
    assert further.max_interference > 2.9 * first.max_interference
    tabulated_law(OTHER, R, runner=run, mu=0.5)
    assert len(made) == 3 and made[-1]["mu"] == 0.5
    tabulated_law(OTHER, R, runner=run, mu=0.5)  # now cached with its mu
    assert len(made) == 3


def test_curves_cached_without_their_options_are_taken_as_the_defaults() -> None:
    """A file written by an earlier release records no options."""
    made: list[dict[str, Any]] = []
    run = _runner(OTHER, made)
    model = tabulated_law(OTHER, R, runner=run)
    (path,) = curves_cache_dir().glob("*.json")
    record = json.loads(path.read_text())
    del record["fe_inputs"]
    path.write_text(json.dumps(record))
    assert tabulated_law(OTHER, R, runner=run).source == model.source and len(made) == 1
    assert tabulated_law(OTHER, R, runner=run, mesh_level=1).source == model.source
    tabulated_law(OTHER, R, runner=run, mesh_level=2)
    assert len(made) == 2
