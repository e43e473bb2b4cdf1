"""A worker process of the ``processes`` backend that dies (killed by hand, or by the system when
memory runs out) stops the sweep with one line, the finished chunks stored: a run of the same
study continues. The worker kills itself on a chosen chunk (its cases' vy), no timing involved."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator, store_files

from impactlab.sweep import Study, SweepStore, run_sweep
from impactlab.sweep.backends import WorkerLostError

pytestmark = pytest.mark.slow  # spawned pools

_DIE_AT = -3.0  # the vy of the chunk whose worker dies


class DyingEvaluator(FakeEvaluator):
    """FakeEvaluator (same identity and numbers) whose process exits at once, as a killed one
    does, on the chunk of vy = ``_DIE_AT`` while the file ``armed`` exists."""

    def __init__(self, armed: str) -> None:
        super().__init__()
        self.armed = armed

    def __call__(self, cases: Any, statics: Any, outputs: Any) -> Any:
        if os.path.exists(self.armed) and (np.asarray(cases["vy"]) == _DIE_AT).any():
            os._exit(9)
        return super().__call__(cases, statics, outputs)


def _study() -> Study:
    # one chunk per vy value: 4 chunks
    return Study(
        name="lost",
        chunk_size=3,
        fixed={"mu": 0.2},
        grid={"vy": [-1.0, -2.0, _DIE_AT, -4.0], "angle": np.radians([20.0, 40.0, 60.0])},
    )


def test_a_dead_worker_stops_the_sweep_with_one_line(tmp_path: Path) -> None:
    armed = tmp_path / "armed"
    armed.touch()
    store = tmp_path / "lost.zarr"
    ev = DyingEvaluator(str(armed))
    with pytest.raises(WorkerLostError) as caught:
        run_sweep(_study(), store, evaluator=ev, backend="processes", workers=2, quiet=True)
    message = str(caught.value)
    assert "\n" not in message
    assert "a worker process of the processes backend died" in message
    assert "memory" in message and "run the same command again to continue" in message
    stored = len(SweepStore(store).done_chunks())
    assert f"{stored} of 4 chunks stored" in message
    armed.unlink()
    again = run_sweep(_study(), store, evaluator=ev, backend="processes", workers=2, quiet=True)
    assert again.stats.chunks_computed == 4 - stored
    ref = run_sweep(_study(), tmp_path / "ref.zarr", evaluator=FakeEvaluator(), quiet=True)
    assert store_files(store) == store_files(ref.path)


def test_the_command_says_it_in_one_line(cli_main: Any, tmp_path: Path, monkeypatch) -> None:
    import impactlab.sweep as sweep_pkg

    armed = tmp_path / "armed"
    armed.touch()
    real = sweep_pkg.run_sweep

    def run_sweep(*args: Any, **kwargs: Any) -> Any:
        return real(*args, **{**kwargs, "evaluator": DyingEvaluator(str(armed))})

    monkeypatch.setattr(sweep_pkg, "run_sweep", run_sweep)
    study = tmp_path / "s.toml"
    study.write_text(
        "[study]\nchunk_size = 3\n[fixed]\nmu = 0.2\n"
        "[grid]\nvy = [-1.0, -2.0, -3.0, -4.0]\nangle = ['20 deg', '40 deg', '60 deg']\n"
    )
    args = ("sweep", "run", str(study), "--out", str(tmp_path / "s.zarr"), "--quiet")
    code, _, err = cli_main(*args, "--backend", "processes", "--workers", "2")
    assert code == 1
    assert err.count("\n") == 1, err
    assert err.startswith("error: a worker process of the processes backend died"), err
    assert "chunks stored; run the same command again to continue" in err
