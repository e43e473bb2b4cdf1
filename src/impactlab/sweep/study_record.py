"""The study a store records, read back (its canonical form, ``Study.to_dict``), and the user's
laws it records, for a resume in a process that has not registered them."""

from __future__ import annotations

import dataclasses
import json
import warnings
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from impactlab._validation import ImplausibleInputWarning
from impactlab.contact import law_names
from impactlab.sweep.limits import SweepSizeWarning
from impactlab.sweep.study import Study

__all__ = ["recorded_study", "with_recorded_laws"]


def recorded_study(data: Mapping[str, Any]) -> Study:
    """The study a store records, read back without the warnings (chunking, an implausible
    speed) it gave when it was built (a store is opened many times)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SweepSizeWarning)
        warnings.simplefilter("ignore", ImplausibleInputWarning)
        return Study.from_dict(data)


def with_recorded_laws(study: Study, path: Path) -> Study:
    """``study`` with the laws it names that this process does not know taken from the store
    at ``path``: their records in its study record (``.sweep/study.json``), registered here, as
    a worker registers them (a sweep begun with ``impactlab --law-file`` resumed without it).
    The study as it is where it names no unknown law or the store records none of them."""
    laws = next((a.values for a in study.axes if a.name == "law"), (study.value_of("law"),))
    unknown = [str(n) for n in laws if n not in law_names()]
    if not unknown:
        return study
    try:
        records = json.loads((path / ".sweep" / "study.json").read_text()).get("laws")
    except (OSError, ValueError, AttributeError):  # no store yet, or no readable record
        return study
    found = {n: records[n] for n in unknown if isinstance(records, dict) and n in records}
    if not found:
        return study
    with warnings.catch_warnings():  # given once already, when the study was built
        warnings.simplefilter("ignore")
        return dataclasses.replace(study, laws={**study.laws, **found})
