"""A sweep store records the range and source of each law of its study (``law_ranges`` in its
attributes): a law of one's own its curves' end in delta_c (past which a case has status 1) and
their name and source; a built-in law its stand-in range."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from impactlab.contact import IndentationCurves, register_law, unregister_law
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = 8.8e-3


def _curves() -> IndentationCurves:
    d = np.geomspace(1e-6, 300e-6, 40)
    f = 4.0 / 3.0 * PAIR.E_star * math.sqrt(R) * d**1.5 / np.sqrt(1.0 + (d - 1e-6) / 3e-6)
    dm = np.geomspace(1e-6, 300e-6, 10)
    ratio = 0.85 * np.clip(np.log(dm / 1e-6) / np.log(300.0), 0.0, 1.0) ** 0.5
    return IndentationCurves.from_arrays(
        PAIR, R, d, f, dm, ratio * dm, name="rig", source="lab notebook 12"
    )


def test_the_store_records_each_laws_range_and_source(tmp_path: Path) -> None:
    """Formerly a store of a user law carried neither its range nor its source."""
    from impactlab.sweep import Study, run_sweep

    law = register_law("stored-law", _curves())
    try:
        study = Study(
            name="ranges",
            grid={"law": ["stored-law", "ghaednia"]},
            fixed={"vy": -1.4, "mu": 0.2, "angle": np.radians(40.0)},
            outputs=["e"],
        )
        ds = run_sweep(study, tmp_path / "ranges.zarr", quiet=True).dataset
    finally:
        unregister_law("stored-law")
    ranges = ds.attrs["law_ranges"]
    assert set(ranges) == {"stored-law", "ghaednia"}
    end = f"{law.own_curves.max_delta:.4g} delta_c"
    assert f"interpolated from its curves up to their end, {end}" in ranges["stored-law"]["range"]
    assert "status 1" in ranges["stored-law"]["range"]
    assert ranges["stored-law"]["source"] == "rig: lab notebook 12"
    assert ranges["ghaednia"]["range"].startswith("delta <= 1 delta_c")
    assert "verified range of the case's pair" in ranges["ghaednia"]["range"]
