"""A study whose ``[law_params]`` the contact law refuses for every case is refused when it is
built, in the law's own words, as ``simulate`` words them; where only some cases are refused
(or the law's inputs take too many combinations to check), each refused case keeps its status
and the sweep's summary carries the law's words for the first of them."""

from __future__ import annotations

import pytest

from impactlab import ImplausibleInputWarning
from impactlab.sweep import FailedCasesWarning, Study, run_sweep, status_counts
from impactlab.sweep.models import MAX_PROBES

BASE = {"vy": -1.41, "mu": 0.2}


@pytest.mark.parametrize(
    ("law", "params", "message"),
    [
        ("brake", {"hardness": -5.0}, r"hardness must be > 0 kgf/mm\^2, got -5\.0 kgf/mm\^2"),
        ("ghaednia", {"published_switch": 2.0}, r"published_switch must be 0 .* got 2\.0"),
        ("ghaednia", {"published_switch": float("nan")}, r"published_switch must be finite"),
    ],
)
def test_law_params_refused_for_every_case_refuse_the_study(law, params, message) -> None:
    with pytest.raises(ValueError, match=r"^\[law_params\]: " + message) as caught:
        Study(name="bad", grid={"angle": [0.35]}, fixed={**BASE, "law": law}, law_params=params)
    assert f"(contact law {law!r}); the law refuses every case" in str(caught.value)


def test_law_params_refused_for_some_pairs_only_keep_the_case_status(tmp_path) -> None:
    """Brake's law with hardness = 20 kgf/mm^2: refused for the flat of 1 GPa yield strength
    (delta_p <= delta_y), accepted for 200 MPa. The study runs; the refused case has status
    103, and the summary gives the law's words for it, at its grid coordinates."""
    flat = {"flat_E": 2e11, "flat_nu": 0.29, "flat_brinell_hardness": 120.0,
            "flat_meyer_index": 2.3}  # fmt: skip
    study = Study(name="some", grid={"flat_yield_strength": [1e9, 2e8]},
                  fixed={**BASE, **flat, "angle": 0.35, "law": "brake"},
                  law_params={"hardness": 20.0})  # fmt: skip
    ds = run_sweep(study, tmp_path / "some.zarr", quiet=True).dataset
    assert ds["status"].values.tolist() == [103, 0]
    refused = next(k for k in status_counts(ds) if k.startswith("103:"))
    assert refused.endswith(
        "; first at flat_yield_strength = 1e+09 Pa: hardness = 20.0 kgf/mm^2 gives P0 = "
        "1.961e+08 Pa and delta_p = 6.266e-07 m <= delta_y = 2.719e-06 m; Brake's Eq. 24 needs "
        "delta_p > delta_y, i.e. P0 > 4.086e+08 Pa"
    )


def test_a_pair_the_law_refuses_whatever_its_parameters_is_not_blamed_on_them(tmp_path) -> None:
    """Brake's law on a flat by values without a hardness fails with or without a
    meyer_index: not the [law_params]' fault, so the study is built; each case says in its
    status what the pair lacks."""
    flat = {"flat_E": 69e9, "flat_nu": 0.33, "flat_yield_strength": 276e6}
    for i, params in enumerate(({"meyer_index": 2.5}, {})):
        study = Study(name="nohb", grid={"angle": [0.35]}, fixed={**BASE, **flat, "law": "brake"},
                      law_params=params)  # fmt: skip
        with pytest.warns(FailedCasesWarning, match="no case succeeded"):
            ds = run_sweep(study, tmp_path / f"nohb{i}.zarr", quiet=True).dataset
        ((key, n),) = status_counts(ds).items()
        assert n == 1 and key.startswith("103: ")
        assert key.endswith(
            "first at angle = 0.35 rad: hardness: Brake's law needs the Brinell hardness of both "
            "materials, and 'flat material by values' has none; give it a brinell_hardness in "
            "kgf/mm^2 (HB=...; in a sweep study: flat_brinell_hardness), or the combined value "
            "as a law parameter, law_params={'hardness': ...} in kgf/mm^2 (a [law_params] table "
            "in a --config file on the command line, or in a study whose only law is brake)"
        )


def test_the_summary_carries_the_law_s_words(tmp_path) -> None:
    """Too many tip radii to check up front: every case is refused (status 103), and the status
    counts end with the law's message for the first case, at its grid coordinates."""
    radii = [0.005 + 1e-5 * i for i in range(MAX_PROBES + 1)]
    with pytest.warns(ImplausibleInputWarning, match="keeps the paper's rod's mass"):
        study = Study(name="many", grid={"tip_radius": radii}, fixed={**BASE, "angle": 0.35,
                      "law": "brake"}, law_params={"hardness": -5.0})  # fmt: skip
    with pytest.warns(FailedCasesWarning, match="no case succeeded"):
        ds = run_sweep(study, tmp_path / "many.zarr", quiet=True).dataset
    ((key, n),) = status_counts(ds).items()
    assert n == len(radii)
    assert key.startswith("103: contact law rejected its parameters")
    assert key.endswith(
        "; first at tip_radius = 0.005 m: hardness must be > 0 kgf/mm^2, got -5.0 kgf/mm^2"
    )


def test_a_law_parameter_with_its_unit_is_taken_as_simulate_takes_it(tmp_path) -> None:
    """'105 HB' was refused: "law parameter 'hardness' must be a number"."""
    from impactlab.sweep import Study, load_study

    fixed = {"vy": -1.0, "mu": 0.2, "angle": 0.5, "law": "brake"}
    study = Study(name="x", fixed=fixed, grid={"vx": [0.0, 0.1]}, law_params={"hardness": "105 HB"})
    assert study.law_params == {"hardness": 105.0}
    with pytest.raises(ValueError, match=r"hardness: '105 m' has the wrong dimension"):
        Study(name="x", fixed=fixed, grid={"vx": [0.0, 0.1]}, law_params={"hardness": "105 m"})
    f = tmp_path / "s.toml"
    f.write_text(
        '[study]\nname = "s"\n[fixed]\nvy = "-1 m/s"\nangle = "30 deg"\nlaw = "brake"\n'
        '[grid]\nmu = [0.1, 0.2]\n[law_params]\nhardness = "1030 MPa"\n'
    )
    assert load_study(f).law_params["hardness"] == pytest.approx(105.03, rel=1e-3)


def test_law_params_none_is_no_parameters_as_simulate_takes_it() -> None:
    fixed = {**BASE, "angle": 0.35}
    assert Study(name="s", grid={"vx": [0.0]}, fixed=fixed, law_params=None).law_params == {}
    with pytest.raises(ValueError, match=r"^law_params must be a mapping .* got list \[1\.0\]"):
        Study(name="s", grid={"vx": [0.0]}, fixed=fixed, law_params=[1.0])
