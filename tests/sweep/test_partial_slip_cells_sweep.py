"""``[engine] partial_slip_cells`` of a sweep: a study of 32 cells stores the values of
``simulate_batch(..., partial_slip_cells=32)`` bit for bit (a friction axis's other models
unchanged), enters the study hash (a study without it keeps its hash: the key is left out of
the record), sizes the chunks by its cost, and is refused in one line for a bad value, for a
study without ``partial_slip`` and for a flexible rod's drops."""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import impactlab as il
from impactlab.sweep import Study, load_study, run_sweep
from impactlab.sweep.options import EngineOptions, default_chunk_size

ANGLES = np.radians([20.0, 60.0])
FIXED = {"mu": 0.3, "vy": -1.41, "vx": 0.2, "law": "hertz"}


def _study(cells: int | None, friction: Any = "partial_slip", **kw: Any) -> Study:
    grid: dict[str, Any] = {"angle": ANGLES}
    fixed: dict[str, Any] = dict(FIXED)
    if isinstance(friction, list):
        grid = {"friction": friction, **grid}
    else:
        fixed["friction"] = friction
    return Study(name="cells", grid=grid, fixed=fixed | dict(kw),
                 engine=EngineOptions(partial_slip_cells=cells),
                 outputs=["e", "spin_out", "sliding_length"])  # fmt: skip


def test_a_sweep_of_32_cells_gives_the_batch_values(tmp_path: Path) -> None:
    ds = run_sweep(_study(32, ["mindlin", "partial_slip"]), tmp_path / "c.zarr", quiet=True).dataset
    want = il.simulate_batch(il.Rod.paper(), law="hertz", friction="partial_slip", mu=0.3,
                             vx=0.2, vy=-1.41, angle=ANGLES, partial_slip_cells=32)  # fmt: skip
    got = ds.sel(friction="partial_slip")
    assert got["status"].values.tolist() == [0, 0]
    for name in ("e", "spin_out", "sliding_length"):
        np.testing.assert_array_equal(got[name].values, want[name].astype(got[name].dtype))
    plain = il.simulate_batch(il.Rod.paper(), law="hertz", friction="mindlin", mu=0.3, vx=0.2,
                              vy=-1.41, angle=ANGLES)  # fmt: skip
    np.testing.assert_array_equal(ds.sel(friction="mindlin")["e"].values, plain["e"])
    default = il.simulate_batch(il.Rod.paper(), law="hertz", friction="partial_slip", mu=0.3,
                                vx=0.2, vy=-1.41, angle=ANGLES)  # fmt: skip
    assert not np.array_equal(got["spin_out"].values, default["spin_out"])


def test_the_option_enters_the_hash_only_when_set(tmp_path: Path) -> None:
    unset, sixteen, more = _study(None), _study(16), _study(32)
    assert "partial_slip_cells" not in unset.to_dict()["engine"]
    assert more.to_dict()["engine"]["partial_slip_cells"] == 32
    assert len({unset.hash(), sixteen.hash(), more.hash()}) == 3  # as rtol does
    f = tmp_path / "s.toml"
    f.write_text(
        '[study]\nname = "cells"\n[fixed]\nfriction = "partial_slip"\nmu = 0.3\nvy = -1.41\n'
        '[grid]\nangle = ["20 deg", "60 deg"]\n[engine]\npartial_slip_cells = 64\n'
    )
    st = load_study(f)
    assert st.engine.partial_slip_cells == 64
    assert load_study(st.to_dict()).hash() == st.hash()
    # dearer cases, smaller chunks: 64 cells cost about 4 times 16
    assert default_chunk_size(st) * 4 == default_chunk_size(
        dataclasses.replace(st, engine=EngineOptions())
    )


def _one_line(exc: pytest.ExceptionInfo[ValueError]) -> str:
    text = str(exc.value)
    assert "\n" not in text and "partial_slip_cells" in text
    return text


@pytest.mark.parametrize("bad", [0, 3, 65, 16.5, True, "64"])
def test_a_bad_value_is_refused(bad: Any) -> None:
    with pytest.raises(ValueError, match="partial_slip_cells") as exc:
        EngineOptions(partial_slip_cells=bad)
    assert _one_line(exc).startswith("engine partial_slip_cells must be an integer in [4, 64]")


def test_a_study_it_does_not_apply_to_is_refused() -> None:
    with pytest.raises(ValueError, match="partial_slip_cells") as exc:
        _study(32, "mindlin")
    assert "'partial_slip' only" in _one_line(exc) and "mindlin" in str(exc.value)
    with pytest.raises(ValueError, match="partial_slip_cells") as exc:
        _study(32, body="flexible_rod")
    assert "flexible rod" in _one_line(exc) and "compiled 16 cells" in str(exc.value)
    _study(16, "mindlin")  # the default changes nothing: accepted
