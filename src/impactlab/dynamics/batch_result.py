"""The results of ``simulate_batch``: one row per impact, with each case's status and flags."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab import schema
from impactlab.dynamics.batch import blank_failed
from impactlab.dynamics.batch_fields import (
    batch_counts,
    field_dir,
    no_field,
    regime_series,
    with_units,
)
from impactlab.dynamics.batch_status import (
    INTEGER_FIELDS,
    BatchStatus,
    flag_column,
    integer_series,
)
from impactlab.dynamics.derived import batch_derived
from impactlab.dynamics.export import BATCH_DIAGNOSTICS, batch_columns, batch_dataset, batch_html
from impactlab.dynamics.history import readonly_copy
from impactlab.dynamics.kernels.layout import OUTPUT_FIELDS
from impactlab.dynamics.pint_fields import pint_registry, pint_unit
from impactlab.references import Reference
from impactlab.references import dois as doi_list

__all__ = ["BatchResult"]


@dataclass(frozen=True, eq=False)
class BatchResult(BatchStatus):
    """Results of ``simulate_batch``: ``out`` (N, len(OUTPUT_FIELDS)) and ``status`` (N,).

    Fields are available by name (``batch["e"]`` or ``batch.e``, listed by ``dir()``; another
    name: AttributeError with the nearest field), every column of ``to_dataframe`` among them
    (``batch["status"]``, ``batch["max_delta_ratio"]``); cases with a non-zero status
    hold NaN results (see ``messages``), except the incoming ``vn_in`` and ``vt_in``, which are
    kept wherever the inputs define them (a case refused for ``vn_in >= 0`` shows why): what a
    failed case reached before it stopped (delta_max, max_force, ...) is no result, and reads
    NaN in every output, derived output (``schema.register_output``), ``max_delta_ratio``,
    ``to_dataframe``, ``to_xarray`` and ``to_pint``, as a sweep stores it and as
    ``DropBatchResult`` has it. A failed case has no ``regime`` and no ``flags``: NaN in
    ``batch["regime"]`` and ``batch["flags"]``, ``<NA>`` in ``to_dataframe``, -1 in
    ``to_xarray``, and 0 in the ``flags`` bitmask (``computed``, ``flagged`` and ``ok`` are
    False). A case refused for its inputs names the input, its value and its rule in
    ``messages``. The engine's diagnostics ``energy_rise`` and ``friction_excess`` are not
    computed here (NaN in ``batch[name]``; a sweep that keeps one computes it): ``dir()``,
    ``to_dataframe``, ``to_xarray`` and ``to_pint`` leave them out.
    ``references`` are the sources the batch used (contact law, friction model if any mu > 0,
    the integrator); ``dois()`` their DOIs.
    """

    out: np.ndarray = field(repr=False)
    status: np.ndarray = field(repr=False)
    inputs: dict[str, np.ndarray] = field(repr=False)
    law: str
    friction: str
    references: tuple[Reference, ...] = field(default=(), repr=False)
    #: delta_max / delta_ref of each case, the law's own reference interference (NaN where
    #: it failed; None: not computed)
    max_delta_ratio: np.ndarray | None = field(default=None, repr=False)
    #: the range the law is held to for the batch's pair, one line (``contact.range_note``:
    #: verified against FE up to ..., or unverified and why); None: not known
    law_range: str | None = field(default=None, repr=False)
    #: why each case refused for its inputs (ST_BAD_INPUT) is refused, by case index (the input,
    #: its value and its rule: ``messages``); a case the engine stopped: its whole message, in
    #: the words of ``simulate``'s ValueError (``simulate_many.engine_failures``)
    refusals: Mapping[int, str] = field(default_factory=dict, repr=False)
    #: what was simulated besides the per-case inputs (body, flat, gravity, rtol,
    #: constant_angle, law_params), as ``to_xarray``'s attributes (``export.batch_setup``)
    setup: Mapping[str, Any] = field(default_factory=dict, repr=False)
    #: whether the body's material yields before the flat's (``materials.body_yields_first``;
    #: one pair per call): delta_p is then the body's flattening, not a dent in the flat;
    #: None: not known
    body_yields_first: bool | None = None
    #: the batch's advisory sentences, each once per call (``dynamics.dent.flattening_warning``
    #: for the largest delta_p when the body yields first); ``()`` if none
    warnings: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        status = readonly_copy(self.status, np.int32)
        object.__setattr__(self, "status", status)
        object.__setattr__(self, "out", readonly_copy(blank_failed(np.array(self.out), status)))
        if self.max_delta_ratio is not None:
            ratio = np.where(status == 0, self.max_delta_ratio, np.nan)
            object.__setattr__(self, "max_delta_ratio", readonly_copy(ratio))
        object.__setattr__(self, "inputs", {k: readonly_copy(v) for k, v in self.inputs.items()})

    def __len__(self) -> int:
        return int(self.status.shape[0])

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            return self.out[:, OUTPUT_FIELDS.index(name)]
        except ValueError:
            if name in self.inputs:
                return self.inputs[name]
            if name == "status" or (name == "max_delta_ratio" and self.max_delta_ratio is not None):
                return np.asarray(getattr(self, name))  # to_dataframe's columns, by name too
            if name in schema.DERIVED_FIELDS:  # NaN where a case failed, whatever compute does
                return np.where(self.computed, batch_derived(self.__getitem__, name), np.nan)
            known = ", ".join(self)
            raise KeyError(f"unknown field {name!r}; known: {known}") from None

    def __contains__(self, name: object) -> bool:
        """Whether ``batch[name]`` reads a column (``"e" in batch``)."""
        return isinstance(name, str) and (
            name in OUTPUT_FIELDS
            or name in self.inputs
            or name == "status"
            or (name == "max_delta_ratio" and self.max_delta_ratio is not None)
            or name in schema.DERIVED_FIELDS
        )

    def __iter__(self) -> Iterator[str]:
        """Every name ``batch[name]`` reads (those listed by ``dir``, then ``status``,
        ``max_delta_ratio`` where held and the diagnostics), as a mapping's keys; the cases'
        rows: ``to_dataframe()``."""
        ratio = ("max_delta_ratio",) if self.max_delta_ratio is not None else ()
        return iter((*self._fields(), "status", *ratio, *BATCH_DIAGNOSTICS))

    def _fields(self) -> tuple[str, ...]:
        """The names read as ``batch.name`` and listed: inputs, outputs (the diagnostics that
        are not computed aside), derived."""
        outputs = (n for n in OUTPUT_FIELDS if n not in BATCH_DIAGNOSTICS)
        return (*self.inputs, *outputs, *schema.DERIVED_FIELDS)

    def __dir__(self) -> list[str]:
        return field_dir(self, self._fields())

    def __getattr__(self, name: str) -> np.ndarray:
        if name.startswith("_") or name in (
            "out",
            "status",
            "inputs",
            "law",
            "friction",
            "references",
            "law_range",
            "refusals",
            "setup",
            "body_yields_first",
            "warnings",
        ):
            raise AttributeError(name)
        try:
            return self[name]
        except KeyError:
            raise no_field(self, name, self._fields()) from None

    def dois(self) -> tuple[str, ...]:
        """DOIs of ``references``, in order, without repeats."""
        return doi_list(self.references)

    @property
    def flags(self) -> np.ndarray:
        """The ``ResultFlag`` bitmask of each case (int64; 0 for failed cases, whose status
        says why)."""
        return flag_column(self.out[:, OUTPUT_FIELDS.index("flags")])

    @property
    def velocity_out(self) -> tuple[np.ndarray, np.ndarray]:
        """(vx_out, vy_out) of the centre of mass after the impact [m/s], as
        ``ImpactResult.velocity_out`` and ``DropBatchResult.velocity_out``."""
        return self["vx_out"], self["vy_out"]

    def to_dataframe(self) -> Any:
        """A pandas DataFrame: inputs, outputs, ``max_delta_ratio`` and status per case, the
        columns of ``to_xarray`` in its order (``export.batch_columns``), SI units in
        ``df.attrs["units"]`` (column -> unit, ``impactlab.schema``); ``regime`` as a categorical
        of the regime names (``"slip"``, as ``ImpactResult.regime``), ``flags`` and ``n_steps``
        as nullable integers, each ``<NA>`` where a case failed."""
        import pandas as pd  # heavy, needed only here

        df = pd.DataFrame({k: np.array(v) for k, v in self.inputs.items()})
        for name in batch_columns(self):
            if name == "status":
                df[name] = np.array(self.status)
            elif name == "max_delta_ratio":
                df[name] = np.array(self.max_delta_ratio, dtype=np.float64)
            elif name == "regime":
                df[name] = regime_series(self[name], self.computed)
            elif name in INTEGER_FIELDS:
                df[name] = integer_series(self[name], self.computed)
            else:
                df[name] = np.array(self[name])
        return with_units(df, schema.unit)

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset`` over ``case`` (units in attributes; what was simulated, the
        sources and the impactlab version in the dataset's attributes; ``dynamics.export``)."""
        return batch_dataset(self)

    def to_pint(self, registry: Any = None) -> dict[str, Any]:
        """Each output column with a unit (``impactlab.schema``; the diagnostics that are not
        computed aside), every derived output (``schema.register_output``) and
        ``max_delta_ratio`` as a pint Quantity of an array (SI; NaN where a case failed);
        ``registry``: your pint registry."""
        ureg = pint_registry(registry)
        out: dict[str, Any] = {}
        for name in (*OUTPUT_FIELDS, *schema.DERIVED_FIELDS):
            if name in BATCH_DIAGNOSTICS:
                continue
            try:
                unit = schema.unit(name)
            except KeyError:
                continue
            out[name] = ureg.Quantity(np.array(self[name]), pint_unit(unit))
        if self.max_delta_ratio is not None:
            out["max_delta_ratio"] = ureg.Quantity(np.array(self.max_delta_ratio), "dimensionless")
        return out

    def _repr_html_(self) -> str:
        return batch_html(self)

    def __repr__(self) -> str:
        return f"BatchResult({batch_counts(self)}, law={self.law!r}, friction={self.friction!r})"
