"""The ``partial_slip_cells`` option of ``simulate``, ``simulate_batch``, ``run_arrays`` and
``impactlab simulate --partial-slip-cells``: the default (16) gives the results of a call without
it bit for bit; 64 cells bring e_t near normal incidence closer to the exact
Mindlin-Deresiewicz values (``NU_EXACT``, solved by ``verification.partial_slip_mdr``); a
64-cell result records its cells and reruns to the same bits; a batch of 32 cells gives the
single impacts' values; a bad value, another friction model or a drop is refused in one line
naming the option."""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics import BATCH_FRICTION_IDS, contact_model, run_arrays
from impactlab.friction import PARTIAL_SLIP_CELLS
from impactlab.verification.partial_slip import NU_EXACT, nu_case

ROD = il.Rod.paper()
SPHERE = il.Sphere(radius=5e-3, material=il.AISI_201)
ANGLES = np.radians([15.0, 40.0, 75.0])
KW: dict[str, Any] = {"friction": "partial_slip", "mu": 0.3, "history": False}


def _rod(**kw: Any) -> il.ImpactResult:
    return il.simulate(ROD, angle=math.radians(30.0), velocity=(0.2, -1.41), **KW, **kw)


def _sphere(**kw: Any) -> il.ImpactResult:
    return il.simulate(SPHERE, velocity=(0.05, -1.0), law="hertz", **KW, **kw)


def _text(r: Any) -> str:
    return json.dumps(r.to_dict(), sort_keys=True)


def _input(r: Any) -> dict[str, Any]:
    """The result's record of its call."""
    return r.to_dict()["input"]  # type: ignore[no-any-return]


def test_the_default_is_bit_for_bit_the_call_without_it() -> None:
    """Omitted or given as 16: the same result and record, to the last bit."""
    assert PARTIAL_SLIP_CELLS == 16
    for run in (_rod, _sphere):
        plain, given = run(), run(partial_slip_cells=16)
        assert _text(plain) == _text(given)
        assert plain.to_dict()["input"]["partial_slip_cells"] == 16
    mindlin = il.simulate(ROD, angle=0.5, velocity=(0.0, -1.41), mu=0.3, friction="mindlin")
    again = il.simulate(ROD, angle=0.5, velocity=(0.0, -1.41), mu=0.3, friction="mindlin",
                        partial_slip_cells=16)  # fmt: skip
    assert _text(mindlin) == _text(again) and "partial_slip_cells" not in _input(mindlin)
    args: dict[str, Any] = {
        "law": "hertz",
        "friction": "partial_slip",
        "mu": 0.3,
        "vy": -1.41,
        "angle": ANGLES,
    }
    a = il.simulate_batch(ROD, **args)
    b = il.simulate_batch(ROD, **args, partial_slip_cells=16)
    assert np.array_equal(a.out, b.out, equal_nan=True) and np.array_equal(a.status, b.status)
    assert dict(a.setup) == dict(b.setup) and a.setup["partial_slip_cells"] == 16


def _et(nu: float, psi1: float, cells: int) -> tuple[float, float]:
    """e_t and the contact point's v_t,out / v_t,in of the NU_EXACT sphere at ``psi1``."""
    case = nu_case(nu)
    vt = psi1 * case.mu * case.vn / case.eta
    r = il.simulate(case.body, case.flat, law=case.law, friction="partial_slip", mu=case.mu,
                    velocity=(vt, -case.vn), gravity=False, history=False,
                    partial_slip_cells=cells)  # fmt: skip
    vx = r.velocity_out[0]
    return vx / vt, (vx + r.spin_out * case.body.radius) / vt


def test_64_cells_converge_near_normal_incidence() -> None:
    """nu = 0.45, psi1 = 0.05 (the largest error of 16 cells): e_t 2.70e-3 above the exact value
    with 16 cells, 1.71e-4 with 64; psi1 = 0.03: the contact point's rebound, exact -0.0062,
    is +0.0021 (the wrong way) with 16 cells and -0.0051 with 64."""
    _nu, psi1, et, _psi2 = next(r for r in NU_EXACT if r[0] == 0.45 and r[1] == 0.05)
    err16, err64 = (_et(0.45, psi1, n)[0] - et for n in (16, 64))
    assert 2.4e-3 < err16 < 3.0e-3
    assert 0.0 < err64 < 2.1e-4
    _nu, psi1, _et_exact, psi2 = next(r for r in NU_EXACT if r[0] == 0.45 and r[1] == 0.03)
    exact = psi2 / psi1  # the same ratio of the contact point's velocities (eta cancels)
    assert exact == pytest.approx(-0.0062, abs=5e-5)
    assert _et(0.45, psi1, 16)[1] > 0.0 > _et(0.45, psi1, 64)[1] > exact


def test_a_64_cell_result_reruns_to_the_same_bits() -> None:
    r = _rod(partial_slip_cells=64)
    assert _input(r)["partial_slip_cells"] == 64
    assert _text(r) != _text(_rod())  # the cells reach the engine
    assert _text(il.rerun(r)) == _text(r)
    assert _text(il.rerun(json.loads(json.dumps(r.to_dict())))) == _text(r)
    other = il.rerun(r, friction="mindlin")  # another model: the recorded cells left out
    assert other.friction == "mindlin" and "partial_slip_cells" not in _input(other)
    assert _input(il.rerun(r, partial_slip_cells=32))["partial_slip_cells"] == 32


def test_a_batch_of_32_cells_gives_the_single_impacts() -> None:
    b = il.simulate_batch(ROD, law="hertz", friction="partial_slip", mu=0.3, vx=0.2, vy=-1.41,
                          angle=ANGLES, partial_slip_cells=32)  # fmt: skip
    assert b.setup["partial_slip_cells"] == 32 and list(b.status) == [0, 0, 0]
    for i, th in enumerate(ANGLES):
        r = il.simulate(ROD, law="hertz", angle=float(th), velocity=(0.2, -1.41),
                        partial_slip_cells=32, **KW)  # fmt: skip
        for name in ("e", "spin_out", "sliding_length", "duration", "delta_max"):
            assert b[name][i] == getattr(r, name), name
        assert b["vx_out"][i] == r.velocity_out[0]
    default = il.simulate_batch(ROD, law="hertz", friction="partial_slip", mu=0.3, vx=0.2,
                                vy=-1.41, angle=ANGLES)  # fmt: skip
    assert not np.array_equal(default["spin_out"], b["spin_out"])


def _refusal(exc: pytest.ExceptionInfo[ValueError]) -> str:
    text = str(exc.value)
    assert "\n" not in text and "partial_slip_cells" in text
    return text


@pytest.mark.parametrize("bad", [0, 3, 65, 16.5, True, "64", None])
def test_a_bad_value_is_refused_in_one_line(bad: Any) -> None:
    model = contact_model(SPHERE, il.AISI_1010, "hertz")
    calls = (
        lambda: _sphere(partial_slip_cells=bad),
        lambda: il.simulate_batch(
            SPHERE, law="hertz", friction="partial_slip", mu=0.3, vy=-1.0, partial_slip_cells=bad
        ),
        lambda: run_arrays(
            model.law_id,
            BATCH_FRICTION_IDS["partial_slip"],
            model.params,
            SPHERE.to_params(il.AISI_1010),
            [math.pi / 2, 0.0, -1.0, 0.0],
            0.3,
            partial_slip_cells=bad,
        ),
    )
    for call in calls:
        with pytest.raises(ValueError, match="partial_slip_cells") as exc:
            call()
        assert "[4, 64]" in _refusal(exc) and repr(bad) in str(exc.value)


def test_another_friction_model_or_a_drop_is_refused() -> None:
    with pytest.raises(ValueError, match="partial_slip_cells") as exc:
        il.simulate(ROD, angle=0.5, velocity=(0.0, -1.41), mu=0.3, friction="mindlin",
                    partial_slip_cells=32)  # fmt: skip
    assert "'mindlin'" in _refusal(exc)
    with pytest.raises(ValueError, match="partial_slip_cells") as exc:
        il.simulate_batch(ROD, angle=0.5, vy=-1.41, mu=0.3, partial_slip_cells=64)
    assert "'coulomb'" in _refusal(exc)
    with pytest.raises(ValueError, match="partial_slip_cells") as exc:
        il.simulate(il.FlexibleRod.paper(), angle=0.5, velocity=(0.0, -1.41), mu=0.3,
                    friction="partial_slip", partial_slip_cells=32)  # fmt: skip
    assert "compiled 16 cells" in _refusal(exc)
    # the default is no change: accepted for every model and for a drop
    assert il.simulate(ROD, angle=0.5, velocity=(0.0, -1.41), partial_slip_cells=16).e > 0.0


def test_the_command_line_option(cli_main, tmp_path) -> None:  # type: ignore[no-untyped-def]
    args = ("simulate", "sphere", "--radius", "5 mm", "--vy", "-1 m/s", "--vx", "0.05 m/s",
            "--law", "hertz", "--mu", "0.3", "--friction", "partial_slip")  # fmt: skip
    code, out, err = cli_main(*args, "--partial-slip-cells", "64", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["input"]["partial_slip_cells"] == 64
    want = _sphere(partial_slip_cells=64)
    assert data["e"]["value"] == want.e
    saved = tmp_path / "r.json"
    saved.write_text(out)
    code, again, err = cli_main("simulate", "--from", str(saved), "--json")
    assert code == 0, err
    assert json.loads(again)["e"] == data["e"]
    code, _, err = cli_main(*args[:-2], "--partial-slip-cells", "64")
    assert code != 0 and err.count("\n") == 1 and "--partial-slip-cells = 64" in err
    code, _, err = cli_main(*args, "--partial-slip-cells", "3")
    assert code != 0 and err.count("\n") == 1 and "--partial-slip-cells must be" in err
    drop = il.simulate_drop(ROD, angle="20 deg", velocity=(0.0, -1.41), mu=0.3,
                            friction="partial_slip")  # fmt: skip
    saved.write_text(json.dumps(drop.to_dict()))
    code, _, err = cli_main("simulate", "--from", str(saved),
                        "--partial-slip-cells", "32")  # fmt: skip
    assert code != 0 and err.count("\n") == 1 and "compiled cells" in err
