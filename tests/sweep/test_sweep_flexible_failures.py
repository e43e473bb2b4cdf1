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


def test_a_failed_drop_is_stored_with_its_own_code(tmp_path: Path, monkeypatch) -> None:
    """Every engine shares one status table: a drop that missed a contact is stored as
    ``ST_MISSED_CONTACT`` with its own message, not as the nearest rigid-engine meaning."""
    from dataclasses import replace

    from impactlab.dynamics import STATUS_MESSAGES
    from impactlab.dynamics.kernels import status as S
    from impactlab.sweep import flexible

    codes = [S.ST_TMAX, S.ST_TOO_MANY_CONTACTS, S.ST_MAX_STEPS, S.ST_MISSED_CONTACT]
    assert len(set(STATUS_MESSAGES)) == len(STATUS_MESSAGES) and set(codes) <= set(STATUS_MESSAGES)
    assert len({STATUS_MESSAGES[c] for c in codes}) == len(codes)

    drops = flexible.simulate_drops

    def missed(*args: object, **kwargs: object) -> object:
        """The drops, every one of them reported as a missed contact."""
        r = drops(*args, **kwargs)
        return replace(r, status=np.full(len(r), S.ST_MISSED_CONTACT))

    monkeypatch.setattr(flexible, "simulate_drops", missed)
    table = {
        "study": {"name": "flex-missed", "chunk_size": 4},
        "fixed": {
            "body": "flexible_rod",
            "mu": 0.2,
            "angle": "20 deg",
            "n_axial": 1,
            "n_bending": 2,
        },
        "grid": {"vy": [-1.41, -1.2]},
    }
    ds = run_sweep(Study.from_dict(table), tmp_path / "m.zarr", quiet=True).dataset.load()
    assert (ds["status"].values == S.ST_MISSED_CONTACT).all()
    assert "missed contact" in ds.attrs["status_messages"][str(S.ST_MISSED_CONTACT)]
