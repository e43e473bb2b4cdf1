"""``fe.tabulated_law`` for a pair no curves fit: each pair's curves in a file of their own
(two flats whose long names differ past 60 characters, or one name with two yield strengths,
wrote one file before, each overwriting the other), and a soft pair's too large maxima named
as the default ``maxima_over_delta_c``. The FE runs are the shipped aluminium case's, rescaled
to the pair (the same dimensionless curves): no ccx."""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Any

import pytest

from impactlab.contact import get_law
from impactlab.contact._common import jg_critical
from impactlab.contact.tabulated import curves_cache_dir
from impactlab.fe.curves import load_case
from impactlab.fe.tabulated import RUN_MAXIMA_OVER_DELTA_C, curves_file_name, tabulated_law
from impactlab.materials import AISI_201, ContactPair, Material

R = 8.8e-3
SPHERE = Material("AISI 201 stainless steel sphere for a long named experiment", 200e9, 0.3, 760e6)
LONG = "Aluminium alloy 7075-T6 from supplier A, batch 1 of the spring deliveries"


def _runner(pair: ContactPair, made: list[Any]) -> Any:
    """A stand-in for ``indent``: the aluminium case's runs, rescaled to ``pair``."""
    case = load_case("aisi201-on-al6061t6")
    dc0, fc0 = jg_critical(case.pair.E_star, case.radius, case.pair.yield_strength, case.pair.nu)
    dc1, fc1 = jg_critical(pair.E_star, R, pair.yield_strength, pair.nu)

    def run(flat: Material, body: Material, *, radius: float, delta_max: Any, **kw: Any) -> Any:
        made.append(flat.name)
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


@pytest.mark.parametrize(
    ("second", "why"),
    [
        (Material(LONG.replace("batch 1", "batch 2"), 71.7e9, 0.33, 400e6), "names past 60"),
        (Material(LONG, 71.7e9, 0.33, 400e6), "one name, two S_y"),
    ],
)
def test_each_pair_keeps_its_own_curves(
    second: Material, why: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))
    first = Material(LONG, 71.7e9, 0.33, 503e6)
    made: list[Any] = []
    models = []
    for flat in (first, second):
        pair = ContactPair(SPHERE, flat)
        models.append(tabulated_law(pair, R, runner=_runner(pair, made)))
    files = sorted(curves_cache_dir().glob("*.json"))
    assert len(made) == 2 and len(files) == 2, why
    assert all(f.stem.startswith("fe-aisi-201-stainless-steel-sphere") for f in files)
    for flat, model in zip((first, second), models, strict=True):  # both found again by name
        again = get_law("tabulated").build(ContactPair(SPHERE, flat), R)
        assert again.source == model.source
    assert models[0].source != models[1].source


def test_the_file_name_holds_every_value_of_the_runs() -> None:
    pair = ContactPair(SPHERE, Material(LONG, 71.7e9, 0.33, 503e6))
    softer = dataclasses.replace(SPHERE, nu=0.29)
    base = curves_file_name(pair, R, RUN_MAXIMA_OVER_DELTA_C, {})
    assert len(base) <= 48 + 13 and base[-13] == "-"
    others = [
        curves_file_name(pair, 2 * R, RUN_MAXIMA_OVER_DELTA_C, {}),
        curves_file_name(pair, R, (1.0, 10.0), {}),
        curves_file_name(pair, R, RUN_MAXIMA_OVER_DELTA_C, {"mu": 0.2}),
        curves_file_name(pair, R, RUN_MAXIMA_OVER_DELTA_C, {"flat_hardening": [(503e6, 0.0)]}),
        curves_file_name(ContactPair(softer, pair.flat), R, RUN_MAXIMA_OVER_DELTA_C, {}),
    ]
    assert len({base, *others}) == 6
    assert curves_file_name(pair, R, RUN_MAXIMA_OVER_DELTA_C, {"workers": 3}) == base


def test_a_soft_pair_is_told_which_maxima_are_too_large(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Before: "delta_max (0.0035935... m) is too large for radius ...", a delta_max the user
    never gave. Refused before any run."""
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))
    pair = ContactPair(AISI_201, Material("soft polymer", 2e9, 0.35, 100e6))

    def never(*args: Any, **kwargs: Any) -> Any:
        pytest.fail("FE runs started")

    with pytest.raises(ValueError, match=r"^maxima_over_delta_c \(the default\)") as err:
        tabulated_law(pair, R, runner=never)
    text = str(err.value)
    assert text.startswith("maxima_over_delta_c (the default) asks for 30 delta_c = 0.003594 m")
    assert "allowed delta_max < 0.003424 m = 28.58 delta_c" in text
    assert text.endswith("pass maxima_over_delta_c below that, e.g. (1.0, 1.5, 2.0, 3.0, 10.0)")
    with pytest.raises(ValueError, match=r"^maxima_over_delta_c asks for 29 delta_c"):
        tabulated_law(pair, R, runner=never, maxima_over_delta_c=(1.0, 29.0))
