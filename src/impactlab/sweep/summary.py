"""Summaries of a sweep store: case status counts and its progress and contents (what
``impactlab sweep info`` and ``impactlab sweep run`` print)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from impactlab.sweep.store import SweepStore, open_sweep


def status_counts(ds: Any) -> dict[str, int]:
    """Number of cases per status, keyed "<code>: <message>" (code 0: ok)."""
    msgs = ds.attrs.get("status_messages", {})
    codes, counts = np.unique(np.asarray(ds["status"].values), return_counts=True)
    return {
        f"{int(c)}: {msgs.get(str(int(c)), '?')}": int(n)
        for c, n in zip(codes, counts, strict=True)
    }


def store_info(path: str | Path) -> dict[str, Any]:
    """Progress and contents of the store at ``path``: title, study hash, mode, dimensions,
    cases, chunks done, outputs and status counts."""
    ds = open_sweep(path)
    done = len(SweepStore(path).done_chunks())
    return {
        "title": ds.attrs.get("title"),
        "study_hash": ds.attrs.get("study_hash"),
        "mode": ds.attrs.get("mode"),
        "dims": {str(k): int(v) for k, v in ds.sizes.items()},
        "cases": ds.attrs.get("n_cases"),
        "chunks_done": f"{done} of {ds.attrs.get('n_chunks')}",
        "outputs": list(ds.attrs.get("outputs", [])),
        "status": status_counts(ds),
    }
