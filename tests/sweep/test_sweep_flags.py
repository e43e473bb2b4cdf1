"""Sweeps always store the engine's result flags (``impactlab.flags``), also when ``[outputs]
keep`` leaves them out, and ``info`` and the run summary count the flagged cases."""

from __future__ import annotations

import json
import sys

import numpy as np
import pytest
from sweep_fakes import CrashingEvaluator, FakeEvaluator, FlaggingEvaluator, store_files

from impactlab.cli import main
from impactlab.flags import ResultFlag
from impactlab.sweep import Study, open_sweep, run_sweep, store_info


def _study() -> Study:
    return Study(
        name="flags",
        chunk_size=10,
        grid={"mu": np.linspace(0.0, 0.6, 7), "vy": [-1.41, -0.3]},
        fixed={"angle": 0.4},
        outputs=["e"],
    )


def test_flags_are_stored_and_counted_although_not_kept(tmp_path) -> None:
    res = run_sweep(_study(), tmp_path / "f.zarr", evaluator=FlaggingEvaluator(), quiet=True)
    ds = res.dataset
    assert list(ds.data_vars) == ["e", "flags", "status"]
    assert ds["flags"].dtype == np.int16
    assert ds["flags"].attrs["flag_masks"] == [1, 2, 4, 8, 16, 32]  # 16 BEYOND_TIP, 32 BRITTLE
    assert ds["flags"].attrs["flag_meanings"].split() == [  # ResultFlag's names, as everywhere
        "energy_gain", "gravity_dominated", "law_extrapolated", "other_end", "beyond_tip",
        "brittle",
    ]  # fmt: skip
    flags = ds["flags"].values
    mu, vy = np.meshgrid(ds["mu"].values, ds["vy"].values, indexing="ij")
    np.testing.assert_array_equal(flags, (mu > 0.4) * 1 | (vy > -0.5) * 2)
    info = store_info(res.path)
    assert info["outputs"] == ["e", "flags"]
    # mu > 0.4: 2 of 7 values x 2 velocities; vy = -0.3: 7 cases; 2 cases have both
    assert info["flagged"] == {"total": 9, "not_ok": 9, "energy_gain": 4, "gravity_dominated": 7}


def test_run_summary_counts_flags(tmp_path, monkeypatch, capsys) -> None:
    # the compiled engine: the paper's impulse-ratio friction gains energy at 89 degrees
    f = tmp_path / "ir.toml"
    f.write_text(
        "[fixed]\nangle = '89 deg'\nmu = 0.2\nvy = -1.41\nlaw = 'hertz'\n"
        "[grid]\nfriction = ['coulomb', 'impulse_ratio']\n[outputs]\nkeep = ['e']\n"
    )
    monkeypatch.setattr(
        sys, "argv", ["impactlab", "sweep", str(f), "-o", str(tmp_path / "ir.zarr"), "--json"]
    )
    main()
    summary = json.loads(capsys.readouterr().out)
    # hertz at 1.41 m/s is far beyond first yield: both cases extrapolate the law
    assert summary["flagged"] == {"total": 2, "not_ok": 1, "energy_gain": 1, "law_extrapolated": 2}
    ds = open_sweep(tmp_path / "ir.zarr").load()
    gained = int(ds["flags"].sel(friction="impulse_ratio"))
    assert gained & ResultFlag.ENERGY_GAIN and float(ds["e"].sel(friction="impulse_ratio")) > 1.0
    assert int(ds["flags"].sel(friction="coulomb")) == ResultFlag.LAW_EXTRAPOLATED


def test_store_made_without_flags_is_resumed_without_them(tmp_path) -> None:
    # a store begun before the engine had flags (same study and engine identity) goes on as it
    # was made: the outputs it holds are the outputs written
    store = tmp_path / "old.zarr"
    with pytest.raises(RuntimeError, match="simulated crash"):
        run_sweep(_study(), store, evaluator=CrashingEvaluator(after=1), quiet=True)
    assert "flags" not in open_sweep(store, verify=False).data_vars
    res = run_sweep(_study(), store, evaluator=FlaggingEvaluator(), quiet=True)
    assert res.complete and "flags" not in res.dataset.data_vars
    ref = run_sweep(_study(), tmp_path / "ref.zarr", evaluator=FakeEvaluator(), quiet=True)
    assert store_files(store) == store_files(ref.path)
