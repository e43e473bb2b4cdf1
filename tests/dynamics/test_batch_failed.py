"""A case of ``simulate_batch`` that fails (status != 0) holds no numbers that look like results:
every output but the incoming ``vn_in`` and ``vt_in`` is NaN (the interference, force and time
it reached before it stopped included), in ``batch[...]``, the derived outputs,
``max_delta_ratio``, ``to_dataframe``, ``to_xarray`` and ``to_pint``; it has no regime and no
flags. The computed cases are untouched."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

import impactlab as il
from impactlab import schema
from impactlab.contact import IndentationCurves, get_law, register_law, unregister_law
from impactlab.dynamics.batch import KEPT_WHEN_FAILED, blank_failed
from impactlab.dynamics.kernels.layout import N_OUT, OUTPUT_FIELDS
from impactlab.dynamics.kernels.status import ST_LAW_LIMIT
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = 8.8e-3
LAW = "failed-case-steel"
DERIVED = "always_one"
KEPT = [OUTPUT_FIELDS.index(n) for n in KEPT_WHEN_FAILED]
BLANK = [j for j in range(N_OUT) if j not in KEPT]


@pytest.fixture(scope="module")
def law() -> Iterator[str]:
    """The Ghaednia law of the paper's pair sampled up to 300 um: a law of one's own whose
    range a fast impact leaves."""
    ref = get_law("ghaednia").build(PAIR, R)
    delta = np.geomspace(1e-8, 300e-6, 64)
    force = np.array([float(ref.force(d)) for d in delta])
    delta_max = delta[31::4]
    delta_r = np.array([ref.unload(float(d)).delta_r for d in delta_max])
    register_law(LAW, IndentationCurves.from_arrays(PAIR, R, delta, force, delta_max, delta_r))
    yield LAW
    unregister_law(LAW)


@pytest.fixture(scope="module")
def constant() -> Iterator[str]:
    """A derived output that ignores its input (so NaN in would not give NaN out)."""
    schema.register_output(DERIVED, "1", "one", ("e",), lambda e: np.ones_like(e))
    yield DERIVED
    schema.unregister_output(DERIVED)


def _check_failed(b: il.BatchResult, i: int) -> None:
    assert not b.computed[i] and not b.ok[i] and not b.flagged[i] and b.flags[i] == 0
    row = b.out[i]
    assert np.isnan(row[BLANK]).all(), dict(zip(OUTPUT_FIELDS, row, strict=True))
    assert np.isfinite(row[KEPT]).all()  # vn_in, vt_in: the inputs define them
    for name in ("delta_max", "max_force", "duration", "t_max", "n_steps", "regime", "flags"):
        assert math.isnan(b[name][i]), name
    assert b.max_delta_ratio is not None and math.isnan(b.max_delta_ratio[i])
    for name in schema.DERIVED_FIELDS:
        assert math.isnan(b[name][i]), name
    df = b.to_dataframe()
    assert df["delta_max"].isna()[i] and df["max_force"].isna()[i] and df["t_max"].isna()[i]
    assert df["regime"].isna()[i] and df["flags"].isna()[i] and df["n_steps"].isna()[i]
    assert df["vn_in"][i] == b["vn_in"][i]
    ds = b.to_xarray()
    assert math.isnan(float(ds["delta_max"][i])) and math.isnan(float(ds["max_delta_ratio"][i]))
    assert int(ds["regime"][i]) == -1 and int(ds["flags"][i]) == -1
    q = b.to_pint()
    assert math.isnan(q["max_force"].magnitude[i]) and math.isnan(q["duration"].magnitude[i])
    assert math.isnan(q["max_delta_ratio"].magnitude[i])


def test_a_case_beyond_a_user_laws_range_holds_no_partial_numbers(law: str, constant: str) -> None:
    b = il.simulate_batch(il.Rod.paper(), law=law, angle=np.radians(40), vy=[-1.4, -6.0], mu=0.2)
    assert b.status.tolist() == [0, ST_LAW_LIMIT]
    _check_failed(b, 1)
    assert np.isnan(b.to_pint()[constant].magnitude[1])
    # the computed case is the one simulate gives, and its derived output is computed
    r = il.simulate(il.Rod.paper(), law=law, angle=np.radians(40), velocity=(0.0, -1.4), mu=0.2)
    assert b["e"][0] == r.e and b["delta_max"][0] == r.delta_max
    assert b[constant][0] == 1.0 and b.max_delta_ratio is not None
    assert b.max_delta_ratio[0] == pytest.approx(r.max_delta_ratio, rel=1e-12)


def test_the_tabulated_law_beyond_its_last_point_too() -> None:
    b = il.simulate_batch(il.Rod.paper(), law="tabulated", angle=np.radians(40), vy=[-1.4, -60.0])
    assert b.status.tolist() == [0, ST_LAW_LIMIT]
    _check_failed(b, 1)
    assert np.isfinite([b["e"][0], b["delta_max"][0], b["regime"][0], b["flags"][0]]).all()


def test_blank_failed_keeps_the_computed_rows_bit_for_bit() -> None:
    rng = np.random.default_rng(7)
    out = rng.normal(size=(4, N_OUT))
    before = out.copy()
    status = np.array([0, 1, 4, 0], dtype=np.int32)
    assert blank_failed(out, status) is out
    assert np.array_equal(out[[0, 3]], before[[0, 3]])
    assert np.isnan(out[1:3][:, BLANK]).all()
    assert np.array_equal(out[1:3][:, KEPT], before[1:3][:, KEPT])


def test_a_failed_drop_of_a_batch_has_no_derived_output(constant: str) -> None:
    """``simulate_drops``: a case the drop refuses (an angle beyond 90 deg) reads NaN in a
    derived output even where its ``compute`` gives a number for NaN inputs."""
    with pytest.warns(il.ImplausibleInputWarning, match="every refused angle .* degrees"):
        b = il.simulate_drops(il.Rod.paper(), angle=[np.radians(40), 3.0], vy=-1.4, mu=0.2)
    assert b.computed.tolist() == [True, False]
    assert b[constant][0] == 1.0 and math.isnan(b[constant][1])
    assert math.isnan(getattr(b, constant)[1])
