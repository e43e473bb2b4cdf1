"""Repairing a store's metadata on resume: result arrays whose ``zarr.json`` is gone are
created again (their chunk files, where still there, are kept), and an unreadable
``.sweep/study.json`` is written again, for the study the store was made for (same hash).

Only what the study itself defines is rewritten; no computed value is touched. The chunks
whose files are gone no longer match their completion markers, so the resume that follows
computes exactly those again (``SweepStore.verify``); every intact chunk is kept.
"""

from __future__ import annotations

from pathlib import Path

import zarr

from impactlab.sweep.integrity import RepairableStoreError
from impactlab.sweep.storebuild import (
    StoreMeta,
    consolidate,
    create_result_array,
    write_study_record,
)
from impactlab.sweep.study import Study

__all__ = ["repair_metadata"]


def repair_metadata(
    path: Path, problem: RepairableStoreError, study: Study, meta: StoreMeta
) -> None:
    """Create the arrays ``problem.missing_arrays`` of the store at ``path`` again (empty, as
    when the store was built), write its study record again when ``problem.study_record`` says
    it is unreadable, and consolidate the metadata. The caller holds the store's lock and has
    checked that the store holds ``study`` (its hash)."""
    if problem.missing_arrays:
        group = zarr.open_group(str(path), mode="r+")
        for name in problem.missing_arrays:
            create_result_array(group, name, meta, study)
        consolidate(path)
    if problem.study_record is not None:
        write_study_record(path, study)
