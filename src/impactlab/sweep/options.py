"""Study-wide options: the study format, the default chunk size (and a store's, kept on
resume), the engine options and what the uncertainty report summarises."""

from __future__ import annotations

import dataclasses
import json
import math
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from impactlab.dynamics.input_checks import check_partial_slip_cells
from impactlab.dynamics.kernels.inputs import (
    MAX_GRAVITY,
    RTOL_MAX,
    RTOL_MIN,
    gravity_allowed,
    rtol_allowed,
)
from impactlab.friction import PARTIAL_SLIP_CELLS
from impactlab.sweep.inputs import OUTPUT_ALIASES
from impactlab.sweep.limits import TINY_CHUNK, study_cost
from impactlab.units import is_quantity, magnitude

#: Version of the study/store format; part of the study hash.
STUDY_FORMAT = "impactlab-sweep/1"
#: Default number of cases per chunk of a study of rigid bodies, the largest default
#: (:func:`default_chunk_size`); a study's ``chunk_size`` replaces it.
DEFAULT_CHUNK_SIZE = 65536
#: What a chunk of the default size costs on one core, at most [s]: a few seconds, so that the
#: progress bar moves and Ctrl-C (which lands after the chunk in progress) acts soon.
CHUNK_TARGET_S = 4.0
#: What the uncertainty report summarises by default: outputs, and percentiles in [0, 100].
DEFAULT_UNCERTAINTY_OUTPUTS = ("e", "delta_p", "sliding_length", "duration", "mean_force")
DEFAULT_PERCENTILES = (2.5, 50.0, 97.5)


def default_chunk_size(study: Any) -> int:
    """Cases per chunk of a ``Study`` that sets no ``chunk_size``: the largest power of two
    whose chunk costs at most ``CHUNK_TARGET_S`` on one core (``limits.study_cost``, estimated
    from the benchmarks), within [``limits.TINY_CHUNK``, ``DEFAULT_CHUNK_SIZE``]: 65536 for
    rigid bodies, 8192 for ``partial_slip``, 512 for a flexible rod's drops, 2048 for a Monte
    Carlo over material properties (a contact model per case)."""
    fit = CHUNK_TARGET_S / study_cost(study).chunk_case_s()
    size = 2 ** math.floor(math.log2(fit)) if fit >= 1.0 else 1
    return int(min(DEFAULT_CHUNK_SIZE, max(TINY_CHUNK, size)))


def recorded_chunk_size(path: Path) -> int | None:
    """The chunk size the store at ``path`` was built with (its study record
    ``.sweep/study.json``, else its root attribute ``study``); None: no store, or none
    readable."""
    for read in (
        lambda: json.loads((path / ".sweep" / "study.json").read_text()),
        lambda: json.loads(json.loads((path / "zarr.json").read_text())["attributes"]["study"]),
    ):
        try:
            size = read()["study"]["chunk_size"]
        except (OSError, ValueError, KeyError, TypeError):
            continue
        if isinstance(size, int) and not isinstance(size, bool) and size >= 1:
            return size
    return None


def with_recorded_chunk_size(study: Any, path: Path) -> Any:
    """``study`` (a ``Study``) with the chunk size of the store at ``path`` when the study sets
    no ``chunk_size`` and the store was built with another: a store keeps its chunking, so
    that a change of :func:`default_chunk_size` does not make an unchanged study refuse to
    resume its store. The study as it is otherwise."""
    size = None if study.chunk_size is not None else recorded_chunk_size(path)
    if size is None or size == study.cases_per_chunk:
        return study
    with warnings.catch_warnings():  # the study's warnings were given when it was built
        warnings.simplefilter("ignore")
        return dataclasses.replace(study, chunk_size=size)


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


@dataclass(frozen=True)
class EngineOptions:
    """Options passed to the impact engine (None: the engine's default); ``gravity`` true,
    false, a number in m/s^2 or a quantity (``"9.81 m/s^2"``, converted);
    ``partial_slip_cells`` the cells of ``partial_slip`` (an integer in [4, 64], default 16),
    for the study's ``partial_slip`` cases (:func:`check_cells_study`)."""

    gravity: bool | float | None = None
    constant_angle: bool | None = None
    rtol: float | None = None
    partial_slip_cells: int | None = None

    def __post_init__(self) -> None:
        allowed = (
            f"true/false, a number in [0, {MAX_GRAVITY:g}] (m/s^2) or a quantity such as "
            "'9.81 m/s^2'"
        )
        if isinstance(self.gravity, str) or is_quantity(self.gravity):  # "9.81 m/s^2"
            try:
                g = float(magnitude("engine gravity", self.gravity, "m/s^2"))
            except ValueError as exc:  # its reason (a comma, the wrong dimension), then the rule
                raise ValueError(f"{exc}; allowed: {allowed}") from None
            object.__setattr__(self, "gravity", g if math.isfinite(g) else self.gravity)
        if self.rtol is not None and not (_number(self.rtol) and rtol_allowed(float(self.rtol))):
            raise ValueError(
                f"engine rtol must be a number in [{RTOL_MIN:g}, {RTOL_MAX:g}], got {self.rtol!r}"
            )
        if self.gravity is not None and not isinstance(self.gravity, bool):
            g = self.gravity
            if not (_number(g) and gravity_allowed(float(g))):
                raise ValueError(f"engine gravity must be {allowed}, got {g!r}")
        if self.constant_angle is not None and not isinstance(self.constant_angle, bool):
            raise ValueError(
                f"engine constant_angle must be true or false, got {self.constant_angle!r}"
            )
        if self.partial_slip_cells is not None:
            try:
                cells = check_partial_slip_cells(self.partial_slip_cells)
            except ValueError as exc:
                raise ValueError(f"engine {exc}") from None
            object.__setattr__(self, "partial_slip_cells", cells)

    def kwargs(self) -> dict[str, Any]:
        return {k: v for k, v in self.to_dict().items() if v is not None}

    def to_dict(self) -> dict[str, Any]:
        """The options by name (None: not set; a study's record leaves those out, so that an
        option added later leaves the hash of a study without it as it was)."""
        return {"gravity": self.gravity, "constant_angle": self.constant_angle, "rtol": self.rtol,
                "partial_slip_cells": self.partial_slip_cells}  # fmt: skip


def check_cells_study(engine: EngineOptions, bodies: set[str], frictions: set[str]) -> None:
    """ValueError when ``[engine] partial_slip_cells`` is set to another value than the default
    and the study has no ``partial_slip`` case (``frictions``), or has a flexible rod's drops
    (``bodies``), whose compiled cells are fixed. With several friction models it applies to
    the ``partial_slip`` cases."""
    n = engine.partial_slip_cells
    if n is None or n == PARTIAL_SLIP_CELLS:
        return
    if "partial_slip" not in frictions:
        raise ValueError(
            f"[engine] partial_slip_cells = {n} sets the cells of friction 'partial_slip' only, "
            f"and the study's friction is {', '.join(sorted(frictions))}: leave it out"
        )
    if "flexible_rod" in bodies:
        raise ValueError(
            f"[engine] partial_slip_cells = {n}: a flexible rod's drop has its compiled "
            f"{PARTIAL_SLIP_CELLS} cells per end, which cannot be changed; leave it out for "
            "body = 'flexible_rod'"
        )


#: Outputs whose values are codes, not quantities: the report refuses them (what they hold).
NOT_SUMMARISED = {
    "regime": "category codes (each case's regime: slip, stick, ...; count them instead)",
    "flags": "bitmasks of result flags (the report counts the flagged cases: n_flagged)",
}


@dataclass(frozen=True)
class UncertaintySpec:
    """What the uncertainty report summarises (see ``impactlab.sweep.uncertainty``)."""

    outputs: tuple[str, ...] = DEFAULT_UNCERTAINTY_OUTPUTS
    percentiles: tuple[float, ...] = DEFAULT_PERCENTILES

    def __post_init__(self) -> None:
        outs = tuple(OUTPUT_ALIASES.get(o, o) for o in self.outputs)
        if not outs:
            raise ValueError("uncertainty outputs must not be empty")
        codes = next((o for o in outs if o in NOT_SUMMARISED), None)
        if codes is not None:
            raise ValueError(
                f"uncertainty outputs: {codes!r} holds {NOT_SUMMARISED[codes]}, not a quantity: "
                "a mean, a spread or a sensitivity of it means nothing; summarise quantities "
                "(e, delta_p, duration, ...)"
            )
        object.__setattr__(self, "outputs", outs)
        ps = tuple(float(p) for p in self.percentiles)
        for p in ps:
            if not 0.0 <= p <= 100.0:
                raise ValueError(f"uncertainty percentiles must lie in [0, 100], got {p!r}")
        object.__setattr__(self, "percentiles", ps)
