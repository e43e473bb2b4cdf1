"""The engine adapter: per-case contact models and bodies from numeric inputs, rejections as
status codes (no exception), and (when the compiled engine is present) the real engine."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.bodies import PAPER_ROD, Rod, Sphere
from impactlab.contact import get_law
from impactlab.materials import AISI_201, AISI_1010, ContactPair
from impactlab.sweep.engine import (
    STATUS_BAD_BODY,
    STATUS_BAD_LAW,
    STATUS_BAD_MATERIAL,
    Statics,
    build_models,
)
from impactlab.sweep.inputs import INPUTS


def _cases(n: int, **cols) -> dict[str, np.ndarray]:
    out = {
        name: np.full(n, math.nan if s.default is None else float(s.default))
        for name, s in INPUTS.items()
        if s.kind == "float"
    }
    out.update({"angle": np.full(n, 0.35), "vy": np.full(n, -1.41), "mu": np.full(n, 0.2)})
    for k, v in cols.items():
        out[k] = np.asarray(v, dtype=np.float64)
    return out


#: The paper's flat (AISI 1010) defined whole by its values: a study changes no library material
#: in part (impactlab.sweep.material_inputs).
FLAT_1010 = {"flat_E": 200e9, "flat_nu": 0.3, "flat_brinell_hardness": 105.0}


def _flat_cases(n: int, **cols) -> dict[str, np.ndarray]:
    return _cases(n, **{k: np.full(n, v) for k, v in FLAT_1010.items()}, **cols)


def _statics(**cat) -> Statics:
    base = {
        "law": "hertz",
        "friction": "coulomb",
        "body": "rod",
        "body_material": "aisi-201",
        "flat_material": "aisi-1010",
    }
    base.update(cat)
    return Statics(base)


def test_one_model_for_constant_inputs() -> None:
    lp, bp, status = build_models(_cases(5), _statics(law="ghaednia"))
    assert lp.ndim == 1 and bp.ndim == 1 and (status == 0).all()
    ref = get_law("ghaednia").build(ContactPair(AISI_201, AISI_1010), PAPER_ROD.tip_radius)
    np.testing.assert_array_equal(lp, ref.params)
    np.testing.assert_array_equal(bp, PAPER_ROD.to_params(AISI_1010))


def test_per_case_models_and_rejections() -> None:
    sy = [305e6, 250e6, 305e6, 300e9, 305e6]  # 300 GPa > E: Material rejects it
    tip = [0.0088, 0.0088, 0.005, 0.0088, -1.0]  # negative radius: Rod rejects it
    lp, bp, status = build_models(
        _flat_cases(5, flat_yield_strength=sy, tip_radius=tip),
        _statics(law="ghaednia", flat_material="custom"),
    )
    assert lp.shape[0] == 5 and bp.shape[0] == 5
    np.testing.assert_array_equal(status, [0, 0, 0, STATUS_BAD_MATERIAL, STATUS_BAD_BODY])
    from dataclasses import replace

    flat = replace(AISI_1010, yield_strength=250e6)
    ref = get_law("ghaednia").build(ContactPair(AISI_201, flat), 0.0088)
    np.testing.assert_array_equal(lp[1], ref.params)
    rod = Rod(length=PAPER_ROD.L, tip_radius=0.005, mass=PAPER_ROD.mass, material=AISI_201)
    np.testing.assert_array_equal(bp[2], rod.to_params(AISI_1010))
    assert np.isnan(lp[3]).all() and np.isnan(bp[4]).all()


def test_sphere_and_bad_law_parameters() -> None:
    _lp, bp, status = build_models(_cases(2, radius=[0.01, 0.02]), _statics(body="sphere"))
    assert (status == 0).all()
    np.testing.assert_array_equal(
        bp[1], Sphere(radius=0.02, material=AISI_201).to_params(AISI_1010)
    )
    _, _, status = build_models(
        _cases(2), Statics(_statics().categories, law_params={"bogus": 1.0})
    )
    assert (status == STATUS_BAD_LAW).all()
    _, _, status = build_models(_cases(1), _statics(body="sphere"))  # no radius
    assert status[0] == STATUS_BAD_BODY


def test_a_library_material_is_never_partly_changed() -> None:
    """Property values beside a library name: every case refused as a bad material (a study
    refuses them when it is built); a custom flat lacking nu: refused as well."""
    _, _, status = build_models(_cases(2, flat_E=[69e9, 70e9]), _statics())
    assert (status == STATUS_BAD_MATERIAL).all()
    cols = {"flat_E": [69e9, 70e9], "flat_yield_strength": [276e6, 276e6]}
    _, _, status = build_models(_cases(2, **cols), _statics(flat_material="custom"))
    assert (status == STATUS_BAD_MATERIAL).all()


@pytest.mark.parametrize("law", ["hertz", "ghaednia"])
def test_models_are_cached(law) -> None:
    from impactlab.sweep import models as eng

    sy = np.linspace(200e6, 300e6, 7)
    build_models(_flat_cases(7, flat_yield_strength=sy), _statics(law=law, flat_material="custom"))
    n = len(eng._law_cache)
    build_models(
        _flat_cases(7, flat_yield_strength=sy[::-1]), _statics(law=law, flat_material="custom")
    )
    assert len(eng._law_cache) == n


def test_sweep_matches_direct_engine_calls(tmp_path, engine) -> None:
    from impactlab.dynamics.batch import FRICTION_IDS, OUTPUT_FIELDS, run_arrays
    from impactlab.sweep import Study, run_sweep

    spec = {
        "name": "e2e",
        "chunk_size": 7,
        "fixed": {"vy": -1.41, "mu": 0.2, "law": "ghaednia", **FLAT_1010},
        "outputs": ["e", "delta_p", "sliding_length", "duration", "mean_force", "regime"],
    }
    # an angle outside (0, 90] deg is refused when the study is built, as in a study file
    with pytest.raises(ValueError, match=r"grid dimension 'angle': angle must lie in \(0, 90\]"):
        Study(grid={"angle": np.radians([0.0, 20.0]), "flat_yield_strength": [250e6]}, **spec)
    st = Study(
        grid={
            "angle": np.radians([20.0, 45.0, 70.0]),
            "flat_yield_strength": [250e6, 305e6, 400e9],
        },
        **spec,
    )
    ds = run_sweep(st, tmp_path / "e2e.zarr", evaluator=engine, quiet=True).dataset
    status = ds["status"].values
    assert (status[:, 2] == STATUS_BAD_MATERIAL).all()  # S_y >= E: rejected before the engine
    assert (status[:, :2] == 0).all()
    assert np.isnan(ds["e"].values[status != 0]).all()
    from dataclasses import replace

    for i, th in enumerate([20.0, 45.0, 70.0]):
        for j, sy in enumerate([250e6, 305e6]):
            flat = replace(AISI_1010, yield_strength=sy)
            model = get_law("ghaednia").build(ContactPair(AISI_201, flat), 0.0088)
            args = (
                model.law_id,
                FRICTION_IDS["coulomb"],
                np.array(model.params),
                PAPER_ROD.to_params(flat),
                np.array([[math.radians(th), 0.0, -1.41, 0.0]]),
                np.array([0.2]),
            )
            # a study of few law rows: each case with its row's table, as simulate
            tab, stt = run_arrays(*args)
            out, _st = run_arrays(*args, tabulate=False)
            assert stt[0] == 0
            for name in ("e", "delta_p", "sliding_length", "duration", "mean_force"):
                k = OUTPUT_FIELDS.index(name)
                assert ds[name].values[i, j] == tab[0, k]
                # the closed form (within 1e-13 of the table) changes the last digits
                assert out[0, k] == pytest.approx(tab[0, k], rel=1e-9, abs=1e-15)
            assert ds["regime"].values[i, j] == int(tab[0, OUTPUT_FIELDS.index("regime")])
    assert ds["regime"].attrs["regimes"]["1"] == "slip"


def test_python_study_refuses_a_receding_contact_point() -> None:
    """The Python API applies the study file's kinematic rule: vy < 0 when the spin is zero."""
    from impactlab.sweep import Study

    with pytest.raises(ValueError, match=r"input 'vy': the contact point must approach the flat"):
        Study(name="up", grid={"mu": [0.1, 0.2]}, fixed={"vy": 0.5, "angle": 0.35})
    Study(
        name="spun", grid={"mu": [0.1, 0.2]}, fixed={"vy": 0.5, "angle": 0.35, "spin": -300.0}
    )  # may approach
