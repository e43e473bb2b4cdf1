"""In a study of several bodies each body takes the inputs it has (a sphere's radius is no
rod's, a rod's length and inertia no sphere's, a flexible rod's inertia follows its beam);
what no case could use is refused when the study is built, naming the input and the body."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import impactlab.sweep.engine as engine_module
from impactlab import ImplausibleInputWarning
from impactlab.sweep import Study, open_sweep, run_sweep
from impactlab.sweep.engine import ENGINE, Statics
from impactlab.sweep.inputs import INPUTS

_KIN = {"vy": -1.41, "mu": 0.2}


def _cases(n: int, **cols: float) -> dict[str, np.ndarray]:
    out = {
        k: np.full(n, math.nan if s.default is None else float(s.default))
        for k, s in INPUTS.items()
        if s.kind == "float"
    }
    out.update(angle=np.full(n, 0.5), vy=np.full(n, -1.41), mu=np.full(n, 0.2))
    out.update({k: np.full(n, v) for k, v in cols.items()})
    return out


def _statics(body: str) -> Statics:
    cats = {k: str(s.default) for k, s in INPUTS.items() if s.kind == "category"}
    return Statics({**cats, "body": body})


@pytest.mark.usefixtures("engine")
def test_a_sphere_leaves_a_rods_inputs_unset() -> None:
    mine, _ = ENGINE(_cases(2, radius=0.01), _statics("sphere"), ("e", "delta_p"))
    given, status = ENGINE(
        _cases(2, radius=0.01, length=0.2, tip_radius=0.004, inertia=1e-3),
        _statics("sphere"),
        ("e", "delta_p"),
    )
    assert (status == 0).all()
    for o in ("e", "delta_p"):
        np.testing.assert_array_equal(given[o], mine[o])
    rod, _ = ENGINE(_cases(2), _statics("rod"), ("e",))
    with_radius, status = ENGINE(_cases(2, radius=0.01), _statics("rod"), ("e",))
    assert (status == 0).all() and np.array_equal(rod["e"], with_radius["e"])


def test_a_flexible_rod_leaves_radius_and_inertia_unset(monkeypatch) -> None:
    seen = {}

    def capture(cases, statics, outputs):
        seen.update(cases)
        return {o: np.zeros(1) for o in outputs}, np.zeros(1, dtype=np.int32)

    monkeypatch.setattr(engine_module, "evaluate_flexible", capture)
    ENGINE(_cases(1, radius=0.01, inertia=1e-3, length=0.2), _statics("flexible_rod"), ("e",))
    assert math.isnan(seen["radius"][0]) and math.isnan(seen["inertia"][0])
    assert seen["length"][0] == 0.2


@pytest.mark.usefixtures("engine")
def test_a_mixed_study_runs_every_body(tmp_path) -> None:
    """A fixed length (a rod's) and radius (a sphere's) with rods and spheres: every case
    computed, the sphere's as in a study of spheres alone."""
    mixed = Study(
        name="mixed",
        grid={"body": ["rod", "sphere"], "angle": [0.3, 0.9]},
        fixed={**_KIN, "length": 0.3048, "radius": 0.01},  # another length needs the mass
    )
    ds = open_sweep(run_sweep(mixed, tmp_path / "m.zarr", quiet=True).path)
    assert (ds["status"].values == 0).all()
    sphere = {**_KIN, "radius": 0.01, "body": "sphere"}
    spheres = Study(name="s", grid={"vx": [0.0, 0.1]}, fixed=sphere)
    alone = open_sweep(run_sweep(spheres, tmp_path / "s.zarr", quiet=True).path)
    assert float(ds["e"].sel(body="sphere").values[0]) == float(alone["e"].values[0])


@pytest.mark.parametrize(
    ("grid", "fixed", "message"),
    [
        (
            {"body": ["rod", "sphere"]},
            {"angle": 0.3},
            r"^radius: body 'sphere' needs it .*set radius in \[fixed\], \[grid\] or \[sample\]$",
        ),
        (
            {"body": ["flexible_rod", "sphere"]},
            {"angle": 0.3, "radius": 0.01, "inertia": 1e-3},
            r"^inertia: only a rigid rod takes it, and the study's bodies are flexible_rod, sphere",
        ),
        (
            {"flat_material": ["custom", "pmma"]},
            {"angle": 0.3},
            r"^flat_material = 'custom': a flat material by values needs flat_E, flat_nu, "
            r"flat_yield_strength",
        ),
        (
            {"body_material": ["custom"], "angle": [0.3]},
            {},
            r"^body_material = 'custom': a body material by values needs body_E, body_nu, "
            r"body_yield_strength, body_density",
        ),
    ],
)
def test_what_no_case_could_use_is_refused(grid, fixed, message) -> None:
    with pytest.raises(ValueError, match=message):
        Study(name="r", grid={**grid, "vx": [0.0, 0.1]}, fixed={**_KIN, **fixed})


def test_a_custom_flat_beside_a_library_one_is_refused_when_read(tmp_path) -> None:
    f = tmp_path / "flat.toml"
    f.write_text(
        "[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nflat_material = ['custom', 'pmma']\n"
        "angle = ['20 deg', '45 deg']\n"
    )
    with pytest.raises(ValueError, match="flat_material = 'custom'"):
        Study.from_toml(f)


_PAPER_MASS = r"keeps the paper's rod's mass \(0\.4607 kg\)"


def _rod_study(fixed: dict, grid: dict | None = None, sample: dict | None = None) -> Study:
    spec = {"study": {"name": "x"}, "fixed": {"angle": "20 deg", "vy": "-1.41 m/s", **fixed},
            "grid": {"mu": [0.1, 0.2], **(grid or {})}}  # fmt: skip
    return Study.from_dict(spec if sample is None else {**spec, "sample": sample})


@pytest.mark.parametrize(
    ("fixed", "grid"),
    [
        ({"length": "0.3048 m"}, {}),
        ({"tip_radius": "8.8 mm"}, {}),
        ({"length": "304.8 mm", "tip_radius": "0.0088 m"}, {}),
        ({}, {"tip_radius": ["8.8 mm"], "length": ["0.3048 m"]}),
        ({"tip_radius": "5 mm", "mass": "0.4 kg"}, {}),
    ],
    ids=["paper length", "paper tip_radius", "both in other units", "on the grid", "with mass"],
)
def test_the_papers_own_rod_keeps_its_mass_without_a_warning(fixed, grid) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        _rod_study(fixed, grid)


def test_another_tip_radius_without_mass_warns_it_keeps_the_papers_mass() -> None:
    words = (r"^mass: the study's rod takes another tip radius than the paper's \(tip_radius = "
             r"0\.005 m, the paper's 0\.0088 m\) but " + _PAPER_MASS)  # fmt: skip
    with pytest.warns(ImplausibleInputWarning, match=words):
        _rod_study({"tip_radius": "5 mm"})
    with pytest.warns(ImplausibleInputWarning, match=words):
        _rod_study({}, {"tip_radius": ["8.8 mm", "5 mm"]})
    sample = {"size": 4, "seed": 1,
              "tip_radius": {"dist": "uniform", "low": "8 mm", "high": "9 mm"}}  # fmt: skip
    with pytest.warns(ImplausibleInputWarning, match=r"\(a sampled tip_radius, the paper's"):
        _rod_study({}, sample=sample)


def test_another_length_without_mass_is_refused_without_the_warning() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        with pytest.raises(ValueError, match=r"^mass: give it for a rod other than the paper's"):
            _rod_study({"length": "0.5 m"})
