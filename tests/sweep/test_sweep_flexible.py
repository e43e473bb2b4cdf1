"""Study files with a flexible rod (``body = "flexible_rod"``, impactlab.sweep.flexible): a tiny
study runs through the sweep machinery into a store whose flexible cases equal the drop
(``impactlab.simulate`` with the same FlexibleRod), rejected cases carry status codes, and the
study-level checks refuse what a flexible rod cannot take."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import impactlab
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.kernels import status as S
from impactlab.schema import FIELDS
from impactlab.sweep import Study, run_sweep

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "study-flexible.toml"
TABLE = {
    "study": {"name": "flex", "chunk_size": 4},
    "fixed": {"vy": -1.41, "mu": 0.2, "n_axial": 2, "n_bending": 4, "damping": 0.01},
    "grid": {
        "body": ["rod", "flexible_rod"],
        "angle": ["20 deg", "45 deg"],
        "friction": ["coulomb", "mindlin"],
    },
    "outputs": {
        "keep": [
            *("e", "delta_p", "duration", "dent_depth", "sequence_sliding_length"),
            *("sequence_duration", "sequence_mean_force", "scar_length", "regime"),
        ]
    },
}


def test_tiny_flexible_study(tmp_path: Path) -> None:
    """Rigid and flexible rods side by side in one store; each flexible case is the drop of
    the same FlexibleRod (to the last bit), outputs the drop lacks are missing values: its
    sequence totals have columns of their own, NaN for the rigid rod's cases, and the impact
    columns of one contact (delta_p, duration) are NaN for the flexible cases."""
    ds = run_sweep(Study.from_dict(TABLE), tmp_path / "f.zarr", quiet=True).dataset.load()
    assert set(ds.data_vars) >= {"e", "delta_p", "dent_depth", "sequence_mean_force", "status"}
    assert (ds["status"].values == 0).all()
    body = FlexibleRod.paper(n_axial=2, n_bending=4, axial_residual=True, damping=0.01)
    for fr in ("coulomb", "mindlin"):
        for th in (20.0, 45.0):
            case = ds.sel(body="flexible_rod", friction=fr, angle=math.radians(th))
            r = impactlab.simulate(
                body, friction=fr, mu=0.2, angle=math.radians(th), velocity=(0.0, -1.41),
                history=False,
            )  # fmt: skip
            assert float(case["e"]) == r.e and float(case["dent_depth"]) == r.dent_depth
            assert float(case["sequence_mean_force"]) == r.sequence_mean_force
            assert float(case["sequence_duration"]) == r.sequence_duration
            assert float(case["sequence_sliding_length"]) == r.sequence_sliding_length
            assert float(case["scar_length"]) == r.scar_length > 0
            assert math.isnan(float(case["delta_p"])) and math.isnan(float(case["duration"]))
            assert int(case["flags"]) == int(r.flags) and int(case["regime"]) == -1
            rigid = ds.sel(body="rod", friction=fr, angle=math.radians(th))
            assert float(rigid["e"]) != r.e and int(rigid["regime"]) >= 0
            assert float(rigid["delta_p"]) > 0 and math.isnan(float(rigid["dent_depth"]))
            assert math.isnan(float(rigid["scar_length"]))  # its mark: |contact_travel|
    spec = FIELDS["scar_length"]  # unit and meaning from the schema
    assert ds["scar_length"].attrs == {"units": spec.unit, "long_name": spec.description}


def test_rejected_cases_have_status(tmp_path: Path) -> None:
    """A rod whose spin makes it recede: a status code, never an exception; the good case is
    computed. A flexible rod with an inertia (its inertia follows its beam: no case could run)
    and a non-integer mode count are refused when the study is read."""
    table = {
        "study": {"name": "bad", "chunk_size": 8},
        "fixed": {
            "body": "flexible_rod",
            "mu": 0.1,
            "angle": "30 deg",
            "n_bending": 2,
            "n_axial": 1,
        },
        "grid": {"vy": [-1.0, 0.5], "inertia": [0.004], "damping": [0.0]},
    }
    table["fixed"]["spin"] = 1.0  # vy = 0.5 m/s then recedes: 0.5 - 1 * (L/2) cos 30 deg > 0
    with pytest.raises(ValueError, match="inertia: only a rigid rod takes it"):
        Study.from_dict(table)
    del table["fixed"]["n_bending"]
    table["grid"] = {"vy": [-1.0, 0.5], "n_bending": [2, 3]}
    ds = run_sweep(Study.from_dict(table), tmp_path / "c.zarr", quiet=True).dataset.load()
    st = ds["status"].transpose("vy", "n_bending").values
    np.testing.assert_array_equal(st[1], [S.ST_NOT_APPROACHING] * 2)
    assert (st[0] == 0).all() and np.isfinite(float(ds["e"].sel(vy=-1.0, n_bending=2)))
    table["grid"] = {"vy": [-1.0], "n_bending": [2, 2.5]}
    with pytest.raises(ValueError, match=r"n_bending must be an integer >= 0, got 2.5"):
        Study.from_dict(table)


def test_study_level_checks() -> None:
    """Flexible inputs without a flexible rod, constant_angle with one, and a friction model
    the drop lacks are refused when the study is read or run."""
    with pytest.raises(ValueError, match=r"n_bending.*flexible_rod"):
        Study.from_dict(
            {"fixed": {"angle": "20 deg", "vy": -1, "n_bending": 3}, "grid": {"mu": [0.1, 0.2]}}
        )
    with pytest.raises(ValueError, match="constant_angle"):
        Study.from_dict(
            {"fixed": {"angle": "20 deg", "vy": -1, "body": "flexible_rod"},
             "grid": {"mu": [0.1, 0.2]}, "engine": {"constant_angle": True}}
        )  # fmt: skip
    fixed = {"angle": "20 deg", "vy": -1, "mu": 0.1, "body": "flexible_rod"}
    bad = Study.from_dict({"fixed": fixed, "grid": {"friction": ["coulomb", "nonsense"]}})
    with pytest.raises(ValueError, match=r"friction 'nonsense'.*flexible rod"):
        run_sweep(bad, quiet=True)


def test_a_sequence_total_without_a_drop_is_refused_by_name(tmp_path: Path) -> None:
    """A rigid study asking for a drop's sequence total is told why, not "unknown output"."""
    rigid = Study.from_dict(
        {"fixed": {"angle": "20 deg", "mu": 0.1}, "grid": {"vy": [-1.0, -2.0]},
         "outputs": {"keep": ["e", "sequence_duration"]}}
    )  # fmt: skip
    with pytest.raises(ValueError, match=r"\['sequence_duration'\] are totals of a drop's"):
        run_sweep(rigid, tmp_path / "r.zarr", quiet=True)


def test_a_drop_study_keeps_the_mark_extent(tmp_path: Path) -> None:
    """``scar_length`` (the x-extent of the tip's path over all its contacts) is an output a
    study with a flexible rod keeps, by name, as its drop gives it; a rigid study asking for it
    is told it is a drop's."""
    table = {
        "fixed": {"body": "flexible_rod", "mu": 0.2, "n_axial": 2, "n_bending": 4},
        "grid": {"angle": ["20 deg", "45 deg"]},
        "outputs": {"keep": ["e", "scar_length"]},
    }
    table["fixed"]["vy"] = -1.41
    ds = run_sweep(Study.from_dict(table), tmp_path / "s.zarr", quiet=True).dataset.load()
    assert [v for v in ds.data_vars if v in ("e", "scar_length")] == ["e", "scar_length"]
    body = FlexibleRod.paper(n_axial=2, n_bending=4, axial_residual=True)
    r = impactlab.simulate(
        body, friction="coulomb", mu=0.2, angle=math.radians(45.0), velocity=(0.0, -1.41),
        history=False,
    )  # fmt: skip
    assert float(ds["scar_length"].sel(angle=math.radians(45.0))) == r.scar_length > 0
    rigid = Study.from_dict(
        {"fixed": {"angle": "20 deg", "mu": 0.1}, "grid": {"vy": [-1.0, -2.0]},
         "outputs": {"keep": ["e", "scar_length"]}}
    )  # fmt: skip
    with pytest.raises(ValueError, match=r"\['scar_length'\] are totals of a drop's"):
        run_sweep(rigid, tmp_path / "r.zarr", quiet=True)


def test_example_study_reads() -> None:
    """examples/study-flexible.toml is a valid, small study of flexible rods."""
    st = Study.from_toml(EXAMPLE)
    assert st.layout.n_cases <= 200 and "flexible_rod" in str(st.to_dict())
