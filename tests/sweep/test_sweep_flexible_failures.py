"""A flexible sweep with failing cases: every failing case gets a status code, never an
exception, and the valid cases of the same chunk are stored (impactlab.sweep.flexible)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from impactlab.sweep import Study, run_sweep
from impactlab.sweep.status import STATUS_BAD_BODY, STATUS_BAD_INPUT


def test_bad_cases_get_a_status_and_valid_cases_are_stored(tmp_path: Path) -> None:
    table = {
        "study": {"name": "flex-bad", "chunk_size": 8},
        "fixed": {"body": "flexible_rod", "mu": 0.2, "angle": "20 deg", "n_axial": 1},
        "grid": {"vy": [-1.41, -1e-300], "n_bending": [2, 300]},
    }
    ds = run_sweep(Study.from_dict(table), tmp_path / "f.zarr", quiet=True).dataset.load()
    st = ds["status"].transpose("vy", "n_bending").values
    assert st[0, 0] == 0 and np.isfinite(float(ds["e"].sel(vy=-1.41, n_bending=2)))
    assert st[1, 0] == STATUS_BAD_INPUT  # an approach speed below the drop's floor
    assert (st[:, 1] == STATUS_BAD_BODY).all()  # more modes than the rod takes
    e = ds["e"].transpose("vy", "n_bending").values
    assert np.isnan(e[1, 0]) and np.isnan(e[:, 1]).all()
