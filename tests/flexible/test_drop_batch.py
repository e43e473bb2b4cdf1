"""``simulate_drops``: many drops in one compiled call equal, bit for bit, the drops of
``simulate_drop`` one by one (every output of the batch: the output vector, E0, the flags, the
law's range ratio, the status of a refused or failed case), over laws, friction models,
angles and speeds, with re-contacts; hypothesis draws further cases."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab import FlexibleRod, Rod
from impactlab.dynamics import simulate_drop, simulate_drops
from impactlab.dynamics.drop_checks import DropError
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.kernels.cells import N_CELLS
from impactlab.friction import PARTIAL_SLIP_CELLS
from impactlab.schema import RENAMED_DROP_FIELDS

#: A small flexible rod: few modes, fast drops.
ROD = FlexibleRod.paper(n_axial=1, n_bending=3, axial_residual=True, damping=0.01)

#: DropResult's value of each output of the drop's vector (``layout.DROP_OUTPUT_FIELDS``).
_READ = {
    "vx_out": lambda r: r.velocity_out[0],
    "vy_out": lambda r: r.velocity_out[1],
    "n_dents": lambda r: len(r.dents),
}
#: Outputs that DropResult does not keep.
_UNKEPT = {"n_jumps", "t_final"}


def _expected(body, kwargs: dict, case: dict) -> tuple[int, np.ndarray, list[float]]:
    """(status, the output vector, [E0, flags, max_delta_ratio]) of one simulate_drop call."""
    nan = np.full(F.N_DROP_OUT, np.nan)
    try:
        r = simulate_drop(
            body, angle=case["angle"], velocity=(case["vx"], case["vy"]), spin=case["spin"],
            mu=case["mu"], **kwargs,
        )  # fmt: skip
    except DropError as exc:
        return exc.status, nan, [math.nan, 0.0, math.nan]
    except ValueError as exc:
        text = str(exc)
        code = S.ST_BAD_ANGLE if text.startswith("angle") else S.ST_BAD_INPUT
        if "does not approach" in text:
            code = S.ST_NOT_APPROACHING
        return code, nan, [math.nan, 0.0, math.nan]

    def read(n: str) -> float:
        return float(_READ.get(n, lambda r: getattr(r, RENAMED_DROP_FIELDS.get(n, n)))(r))

    row = [math.nan if n in _UNKEPT else read(n) for n in F.DROP_OUTPUT_FIELDS]
    return 0, np.array(row), [r.initial_energy, float(int(r.flags)), r.max_delta_ratio]


def _check_equal(body, kwargs: dict, cases: dict[str, np.ndarray]) -> np.ndarray:
    """Run the batch and each case alone; assert every output equal to the last bit."""
    drops = simulate_drops(body, **kwargs, **cases)
    kept = [i for i, n in enumerate(F.DROP_OUTPUT_FIELDS) if n not in _UNKEPT]
    for i in range(len(drops)):
        case = {k: float(v[i]) for k, v in cases.items()}
        status, row, extra = _expected(body, kwargs, case)
        assert drops.status[i] == status, (case, drops.messages[i])
        got = drops.out[i, kept]
        assert np.array_equal(got, row[kept], equal_nan=True), (case, got - row[kept])
        mine = [drops.initial_energy[i], float(drops.flags[i]), drops.max_delta_ratio[i]]
        assert np.array_equal(mine, extra, equal_nan=True), (case, mine, extra)
    return drops.status


@pytest.mark.parametrize(
    ("law", "friction"),
    [
        ("ghaednia", "coulomb"),
        ("hertz", "impulse_ratio"),
        ("jackson-green", "mindlin"),
        ("kogut-komvopoulos", "coulomb"),
        ("thornton", "partial_slip"),
    ],
)
def test_batch_equals_drop_by_drop(law: str, friction: str) -> None:
    """Steep and shallow drops, slow and fast, with spin and without friction, and refused
    cases (an angle outside (0, pi/2], a receding tip, NaN, mu < 0)."""
    cases = {
        "angle": np.array([0.15, 0.35, 0.8, 1.3, math.pi / 2, -0.2, 0.5, 0.5, 0.5]),
        "vx": np.array([0.0, 0.4, -0.3, 0.2, 0.0, 0.0, 0.0, np.nan, 0.0]),
        "vy": np.array([-1.41, -0.6, -2.5, -1.0, -0.3, -1.0, 2.0, -1.0, -1.0]),
        "spin": np.array([0.0, 0.0, 3.0, -2.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
        "mu": np.array([0.2, 0.3, 0.0, 0.15, 0.2, 0.2, 0.2, 0.2, -0.1]),
    }
    status = _check_equal(ROD, {"law": law, "friction": friction}, cases)
    assert (status[:5] == 0).all() and (status[5:] != 0).all()


def test_recontacts_and_a_failed_drop() -> None:
    """The flight through the other end's impacts (several contacts, both ends) and a drop
    that runs out of time (ST_TMAX), in one batch: equal to the drops one by one."""
    cases = {
        "angle": np.array([0.12, 0.2, 0.3]),
        "vx": np.zeros(3),
        "vy": np.array([-1.0, -1.41, -0.8]),
        "spin": np.zeros(3),
        "mu": np.full(3, 0.2),
    }
    kwargs = {"law": "ghaednia", "friction": "coulomb", "stop": "flight"}
    status = _check_equal(ROD, kwargs, cases)
    drops = simulate_drops(ROD, **kwargs, **cases)
    assert (status == 0).all() and drops["n_contacts"].max() > 1
    assert (drops["n_contacts"] > 1).any()
    short = _check_equal(ROD, {**kwargs, "time_limit": 1e-6}, cases)
    assert (short == S.ST_TMAX).all()


def test_ok_means_what_it_means_for_one_drop() -> None:
    """ok as DropResult.ok (computed, no flag but the advisory ones); computed is the status;
    flags are int64 and to_dataframe has every public field."""
    drops = simulate_drops(Rod.paper(), angle="20 deg", vy=[-0.04, -1.41], mu=0.2)
    speeds = (-0.04, -1.41)
    single = [simulate_drop(Rod.paper(), angle="20 deg", velocity=(0.0, v), mu=0.2) for v in speeds]
    assert drops.flags.dtype == np.int64 and list(drops.flags) == [r.flags for r in single]
    assert list(drops.ok) == [r.ok for r in single] == [False, True]  # gravity-dominated
    assert drops.computed.all() and drops.flagged.all()
    assert drops.messages[1] == "ok"  # a computed case that is not ok names its flags
    assert drops.messages[0].startswith(f"computed, not ok (flags {single[0].flags}): ")
    df = drops.to_dataframe()
    assert {"angle", "e", "sequence_mean_force", "status", "flags"} <= set(df.columns)
    assert str(df["n_contacts"].dtype) == str(df["flags"].dtype) == "Int64"
    assert df["flags"].tolist() == [r.flags for r in single]
    beyond = simulate_drops(Rod.paper(), angle="20 deg", vx=[2e4, 0.0], vy=-1.41, mu=[0.2, 2e3])
    assert list(beyond.status) == [S.ST_BAD_INPUT] * 2 and not beyond.computed.any()


def test_rigid_rod_and_units() -> None:
    """A rigid Rod (the drop's rigid limit) runs too; inputs with units; the result reads by
    name as DropResult does."""
    drops = simulate_drops(Rod.paper(), angle="20 deg", speed=[1.0, 1.5], incidence=0.1, mu=0.2)
    assert drops.ok.all() and len(drops) == 2
    r = simulate_drop(Rod.paper(), angle=math.radians(20), speed=1.5, incidence=0.1, mu=0.2)
    assert drops.e[1] == r.e and drops.sequence_mean_force[1] == r.sequence_mean_force
    assert drops.velocity_out[0][1] == r.velocity_out[0] and drops["angle"][0] > 0
    assert drops.dois() == r.dois()[: len(drops.dois())] or set(drops.dois()) >= set(r.dois())
    with pytest.raises(KeyError, match="unknown field 'nope'"):
        drops["nope"]


def test_bad_batch_input_is_one_message() -> None:
    with pytest.raises(ValueError, match=r"unknown friction model .lugre."):
        simulate_drops(ROD, angle=0.3, vy=-1.0, friction="lugre")
    with pytest.raises(ValueError, match="stop must be one of"):
        simulate_drops(ROD, angle=0.3, vy=-1.0, stop="never")
    with pytest.raises(ValueError, match="angle is required"):
        simulate_drops(ROD, angle=None, vy=-1.0)
    with pytest.raises(ValueError, match="do not broadcast"):
        simulate_drops(ROD, angle=[0.3, 0.4], vy=[-1.0, -2.0, -3.0])


def test_cell_count_is_the_friction_models() -> None:
    """The batch's partial-slip cells are those of ``impactlab.friction``."""
    assert N_CELLS == PARTIAL_SLIP_CELLS


@settings(max_examples=12)
@given(
    angle=st.floats(0.05, math.pi / 2),
    speed=st.floats(0.2, 3.0),
    incidence=st.floats(-0.6, 0.6),
    spin=st.floats(-5.0, 5.0),
    mu=st.floats(0.0, 0.5),
    friction=st.sampled_from(["coulomb", "mindlin", "impulse_ratio"]),
)
def test_batch_equals_drop_property(angle, speed, incidence, spin, mu, friction) -> None:
    """Random drops: batch and drop by drop agree to the last bit (or refuse or fail alike)."""
    cases = {
        "angle": np.array([angle, 0.5 * angle + 0.1]),
        "vx": np.array([speed * math.sin(incidence), 0.0]),
        "vy": np.array([-speed * math.cos(incidence), -speed]),
        "spin": np.array([spin, 0.0]),
        "mu": np.array([mu, mu]),
    }
    # time_limit bounds the time of a drawn drop that rocks (ST_TMAX, alike in both)
    _check_equal(ROD, {"law": "ghaednia", "friction": friction, "time_limit": 0.02}, cases)
