"""``DropBatchResult`` as ``BatchResult``: ``law_range``, ``to_xarray`` (units, codes and their
meanings in attributes, NetCDF-ready) and ``to_pint``; a case refused for its inputs says
which input and which rule in ``messages`` (its status code unchanged)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab import FlexibleRod
from impactlab.dynamics import simulate_drop, simulate_drops
from impactlab.dynamics.drop_checks import MIN_APPROACH_SPEED, input_status
from impactlab.dynamics.kernels import status as S
from impactlab.flags import ResultFlag
from impactlab.units import registry

#: A small flexible rod: few modes, fast drops.
ROD = FlexibleRod.paper(n_axial=1, n_bending=3, axial_residual=True)


@pytest.fixture(scope="module")
def drops():
    """Two drops that run (one through the other end's impacts) and one refused: the tip
    recedes."""
    return simulate_drops(ROD, angle=[0.35, 0.5, 0.5], vy=[-1.41, -2.0, 1.0], mu=0.2,
                          stop="flight")  # fmt: skip


def test_refused_inputs_name_their_rule() -> None:
    """vy = -1e-12 m/s and spin = 1e6 rad/s keep status 4, with the real cause, not the
    generic ranges every listed input holds; other codes keep their messages."""
    cases = {
        "angle": [0.3, 0.3, 0.3, 0.3, 0.0, 0.3],
        "vy": [-1e-12, -1.41, -1.41, -1.41, -1.41, 1.0],
        "spin": [0, 1e6, 0, 0, 0, 0],
        "mu": [0.2, 0.2, -0.1, np.nan, 0.2, 0.2],
    }
    b = simulate_drops(ROD, **cases)
    assert list(b.status) == [4, 4, 4, 4, S.ST_BAD_ANGLE, S.ST_NOT_APPROACHING]
    slow, spin, mu, nan, angle, receding = b.messages
    assert "approach speed" in slow and f"below {MIN_APPROACH_SPEED:g} m/s" in slow
    assert "1e-12 m/s" in slow and "mu in [0, 1e3]" not in slow
    assert spin.startswith("invalid input: spin = 1000000.0") and "10000 m/s" in spin
    assert mu == "invalid input: mu must be >= 0, got -0.1"  # as simulate_drop says it
    assert nan == "invalid input: mu = nan is not finite"
    assert angle == f"{S.STATUS_MESSAGES[S.ST_BAD_ANGLE]}: angle = 0.0 rad = 0 deg"
    values = "vy = 1.0 m/s, spin = 0.0 rad/s, angle = 0.3 rad"
    assert receding == f"{S.STATUS_MESSAGES[S.ST_NOT_APPROACHING]}: {values}"
    with pytest.raises(ValueError, match=r"approach speed .* is below 1e-09 m/s"):
        simulate_drop(ROD, angle=0.3, velocity=(0, -1e-12))  # the same limit, one drop


def test_input_status_codes_are_those_stored_sweeps_read() -> None:
    """``drop_batch.input_status`` (a flexible sweep's refusals) keeps its codes."""
    cols = {k: np.asarray(v, dtype=float) for k, v in {
        "angle": [0.3, 0.3, 2.0, math.nan, 0.3], "vx": [0.0] * 5,
        "vy": [-1.41, -1e-12, -1.41, -1.41, 1.0], "spin": [0.0] * 5, "mu": [0.2] * 5,
    }.items()}  # fmt: skip
    status = input_status(ROD.rigid(), cols, 9.81, 1e-7)
    assert list(status) == [0, S.ST_BAD_INPUT, S.ST_BAD_ANGLE, S.ST_BAD_INPUT, 2]


def test_law_range_is_the_drops(drops) -> None:
    one = simulate_drop(ROD, angle=0.35, velocity=(0, -1.41), mu=0.2, history=False)
    assert drops.law_range == one.law_range and "delta_c" in drops.law_range


def test_to_xarray_has_every_output_with_units_and_codes(drops) -> None:
    ds = drops.to_xarray()
    assert ds.sizes["case"] == 3
    assert ds["angle"].attrs["units"] == "rad" and ds["vy"].attrs["long_name"].startswith("input")
    assert ds["sequence_duration"].attrs["units"] == "s"
    assert ds["dent_depth"].attrs["units"] == "m" and ds["normal_impulse"].attrs["units"] == "N s"
    assert ds["initial_energy"].attrs["units"] == "J"
    assert ds["n_dents"].attrs["units"] == "1" and ds["t_final"].attrs["units"] == "s"
    np.testing.assert_array_equal(ds["e"].values, drops.e)
    np.testing.assert_array_equal(ds["sequence_mean_force"].values, drops.sequence_mean_force)
    np.testing.assert_array_equal(ds["max_delta_ratio"].values, drops.max_delta_ratio)
    assert ds["n_contacts"].dtype == np.int64
    assert list(ds["n_contacts"].values[:2]) == list(drops.n_contacts[:2].astype(int))
    assert ds["n_contacts"].values[2] == -2 and ds["next_end"].values[2] == -2
    assert list(ds["next_end"].values[:2]) == [-1, -1]  # stop="flight": the rod flies off
    assert list(ds["flags"].values) == [*drops.flags[:2], -1]
    assert int(ResultFlag.OTHER_END) in ds["flags"].attrs["flag_masks"]
    assert list(ds["status"].values) == [0, 0, S.ST_NOT_APPROACHING]
    assert S.ST_INACCURATE in ds["status"].attrs["flag_values"]
    assert ds.attrs["law"] == drops.law and ds.attrs["law_range"] == drops.law_range
    assert ds.attrs["source"] == "impactlab.simulate_drops" and ds.attrs["dois"]
    assert ds.attrs["rtol"] == drops.rtol and ds.attrs["body"] == drops.body


def test_to_xarray_writes_netcdf(drops, tmp_path) -> None:
    import xarray as xr

    path = tmp_path / "drops.nc"
    drops.to_xarray().to_netcdf(path)
    with xr.open_dataset(path) as back:
        np.testing.assert_array_equal(back["e"].values, drops.e)
        assert back["flags"].attrs["flag_meanings"].split()[0] == "energy_gain"


def test_to_pint_has_units(drops) -> None:
    q = drops.to_pint()
    ureg = registry()
    assert q["sequence_duration"].units == ureg.second
    assert q["normal_impulse"].to("N*s").magnitude.tolist()[:2] == drops.normal_impulse[:2].tolist()
    assert q["e"].units == ureg.dimensionless
    assert q["initial_energy"].to("mJ").magnitude[0] == pytest.approx(1e3 * drops.initial_energy[0])
    assert math.isnan(q["dent_depth"].magnitude[2])


def test_the_drops_e_says_what_it_leaves_out() -> None:
    """A drop's ``e`` removes the gravity impulse of its sequence: its column says so (the
    impact's long name would not)."""
    from impactlab import Rod, simulate_drops

    ds = simulate_drops(Rod.paper(), angle=0.35, vy=[-1.41, -1.0], mu=0.2).to_xarray()
    assert "gravity impulse of the sequence removed" in ds["e"].attrs["long_name"]
    assert "kept" in ds["e_raw"].attrs["long_name"]
