"""``DropBatchResult``: the results of ``simulate_drops`` (SI units), one row per drop, read by
name (inputs, outputs, derived fields), with its DataFrame, xarray Dataset and pint views.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab import schema
from impactlab.dynamics.batch_fields import batch_counts, field_dir, no_field
from impactlab.dynamics.batch_status import BatchStatus, batch_summary_html, flag_column
from impactlab.dynamics.derived import batch_derived
from impactlab.dynamics.drop_batch_data import (
    DATASET_OUTPUTS,
    DROP_BATCH_FIELDS,
    ENGINE_NAME,
    PUBLIC_FIELDS,
    drop_dataframe,
    drop_dataset,
    output_unit,
)
from impactlab.dynamics.history import readonly_copy
from impactlab.dynamics.pint_fields import pint_registry, pint_unit
from impactlab.references import Reference
from impactlab.references import dois as doi_list

__all__ = ["DropBatchResult", "DropSetup"]


class DropSetup(dict[str, Any]):
    """``DropBatchResult.setup``: its key before 0.3, ``"t_max"``, still reads
    ``"time_limit"`` with a DeprecationWarning; it is not among its keys (nor the attributes
    of ``to_xarray``)."""

    def __missing__(self, key: str) -> Any:
        if key != "t_max":
            raise KeyError(key)
        schema.warn_renamed("t_max", "time_limit", "DropBatchResult.setup key")
        return self["time_limit"]


@dataclass(frozen=True, eq=False)
class DropBatchResult(BatchStatus):
    """Results of ``simulate_drops`` (SI units): ``out`` (N, len(DROP_OUTPUT_FIELDS)) in the
    order of ``flexcore.layout.DROP_FIELDS``, ``status`` (N,) (0: finished; ``STATUS_MESSAGES``),
    ``flags`` (N,) the ``ResultFlag`` bits (int64), ``initial_energy`` [J] and ``max_delta_ratio``
    (delta_max / delta_ref) per case; NaN (flags 0) where a case failed.

    Compared and hashed by identity, as ``BatchResult`` is (``==`` never compares arrays).

    Fields by name (listed by ``dir()``; another name: AttributeError with the nearest field):
    ``drops["e"]`` or ``drops.e``, every column of ``to_dataframe`` (``drops["status"]``;
    ``drops["flags"]`` as ``BatchResult``'s, float, NaN where a case failed, where the
    ``flags`` attribute is the int bitmask, 0 there), the inputs (``angle``, ``vx``, ``vy``,
    ``spin``, ``mu``), ``velocity_out`` (vx_out, vy_out), the sequence totals
    (``sequence_duration``, ``dent_depth``, ``sequence_sliding_length``,
    ``sequence_mean_force`` = P_n / sequence_duration) as ``DropResult`` has them; the names
    before 0.3 warn (``schema.RENAMED_DROP_FIELDS``). ``computed``, ``ok``, ``flagged`` and
    ``messages`` per case as every batch has them (``batch_status.BatchStatus``; a refused
    input's message names the input and its rule). ``law_range``: the law's range for the
    pair in one line (``contact.range_note``), as ``BatchResult`` and ``DropResult`` have it;
    ``to_dataframe`` and ``to_xarray`` (NetCDF-ready; the same columns, in the same order),
    ``to_pint`` and ``setup`` as ``BatchResult``'s."""

    out: np.ndarray = field(repr=False)
    status: np.ndarray = field(repr=False)
    flags: np.ndarray = field(repr=False)
    initial_energy: np.ndarray = field(repr=False)
    max_delta_ratio: np.ndarray = field(repr=False)
    inputs: dict[str, np.ndarray] = field(repr=False)
    body: str
    law: str
    friction: str
    gravity: float
    rtol: float
    references: tuple[Reference, ...] = field(default=(), repr=False)
    #: the range the law is held to for the batch's pair, one line (``contact.range_note``)
    law_range: str | None = field(default=None, repr=False)
    #: why each case refused with ST_BAD_INPUT is refused, by case index (``case_problem``);
    #: a failed drop's whole message, as ``simulate_drop``'s error words it
    refusals: Mapping[int, str] = field(default_factory=dict, repr=False)
    #: what was simulated besides the per-case inputs, as ``to_xarray``'s attributes, those of
    #: ``BatchResult.setup`` (``export.batch_setup``: body_record, flat, flat_record, gravity,
    #: rtol, law_params) with the drop's ``stop`` and ``time_limit`` [s] (``DropSetup``)
    setup: Mapping[str, Any] = field(default_factory=dict, repr=False)
    #: whether the rod's material yields before the flat's (``materials.body_yields_first``;
    #: one pair per call): dent_depth is then the rod's flattening, not a dent in the flat;
    #: None: not known
    body_yields_first: bool | None = None
    #: the batch's advisory sentences, each once per call (``dynamics.dent.flattening_warning``
    #: for the largest dent_depth when the rod yields first); ``()`` if none
    warnings: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        for name in ("out", "initial_energy", "max_delta_ratio"):
            object.__setattr__(self, name, readonly_copy(getattr(self, name)))
        object.__setattr__(self, "flags", readonly_copy(flag_column(self.flags), np.int64))
        object.__setattr__(self, "status", readonly_copy(self.status, np.int32))
        object.__setattr__(self, "inputs", {k: readonly_copy(v) for k, v in self.inputs.items()})

    def __len__(self) -> int:
        return int(self.status.shape[0])

    def __getitem__(self, name: str) -> np.ndarray:
        old = ENGINE_NAME.get(name)
        if old is not None:  # a sequence total: the engine's column under its own name
            return self.sequence_mean_force if old == "mean_force" else self._column(old)
        new = schema.RENAMED_DROP_FIELDS.get(name)
        if new is not None:
            schema.warn_renamed(name, new, "DropBatchResult field")
            return self[new]
        if name in DROP_BATCH_FIELDS:
            return self._column(name)
        if name in ("initial_energy", "max_delta_ratio", "status"):
            return np.asarray(getattr(self, name))
        if name == "flags":  # as BatchResult["flags"] reads: NaN where the case failed
            return np.where(self.computed, self.flags, np.nan)
        if name in self.inputs:
            return self.inputs[name]
        if name in schema.DERIVED_FIELDS:  # schema.register_output, as DropResult reads it
            return np.where(self.computed, batch_derived(self._engine_output, name), np.nan)
        known = ", ".join(self)
        raise KeyError(f"unknown field {name!r}; known: {known}")

    def _column(self, name: str) -> np.ndarray:
        return self.out[:, DROP_BATCH_FIELDS.index(name)]

    def _engine_output(self, name: str) -> np.ndarray:
        """An ``OUTPUT_FIELDS`` output as ``DropResult`` reads it (``derived.result_output``)."""
        if name == "flags":
            return np.where(self.computed, self.flags, np.nan)
        keep = name in DROP_BATCH_FIELDS and name not in schema.RENAMED_DROP_FIELDS
        return self._column(name) if keep else np.full(len(self), np.nan)  # NaN: a drop has none

    def __contains__(self, name: object) -> bool:
        """Whether ``drops[name]`` reads a column (``"e" in drops``; an old name does not)."""
        return (
            isinstance(name, str)
            and (
                name in ENGINE_NAME
                or name in DROP_BATCH_FIELDS
                or name in ("initial_energy", "max_delta_ratio", "status", "flags")
                or name in self.inputs
                or name in schema.DERIVED_FIELDS
            )
            and name not in schema.RENAMED_DROP_FIELDS
        )

    def __iter__(self) -> Iterator[str]:
        """Every name ``drops[name]`` reads (those listed by ``dir``, then ``status`` and
        ``flags``), as a mapping's keys; the drops' rows: ``to_dataframe()``."""
        names = self._fields()
        return iter((*names, *(n for n in ("status", "flags") if n not in names)))

    def _fields(self) -> tuple[str, ...]:
        """The names read as ``drops[name]`` or ``drops.name``: inputs, outputs, derived."""
        extra = ("initial_energy", "max_delta_ratio")
        return (*self.inputs, *PUBLIC_FIELDS, *extra, *schema.DERIVED_FIELDS)

    def __dir__(self) -> list[str]:
        return field_dir(self, self._fields())

    def __getattr__(self, name: str) -> np.ndarray:
        if name.startswith("_") or name in ("out", "status", "inputs", "warnings"):
            raise AttributeError(name)
        try:
            return self[name]
        except KeyError:
            raise no_field(self, name, self._fields()) from None

    @property
    def velocity_out(self) -> tuple[np.ndarray, np.ndarray]:
        """(vx_out, vy_out) of the centre of mass after the last contact [m/s]."""
        return self["vx_out"], self["vy_out"]

    @property
    def sequence_mean_force(self) -> np.ndarray:
        """P_n / sequence_duration [N], as ``DropResult.sequence_mean_force``."""
        return self._column("normal_impulse") / self._column("duration")

    def to_dataframe(self) -> Any:
        """A pandas DataFrame: inputs, outputs (``PUBLIC_FIELDS``), status and flags per case,
        SI units in ``df.attrs["units"]`` (column -> unit); counts, codes and ``flags`` as
        nullable integers, ``<NA>`` where a case failed (``drop_batch_data.drop_dataframe``)."""
        return drop_dataframe(self)

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset`` over ``case``, as ``BatchResult.to_xarray``: the inputs and
        outputs (``PUBLIC_FIELDS``, ``initial_energy``, ``max_delta_ratio``; SI, ``units`` and
        ``long_name`` attributes), the counts and ``next_end`` as integers (-2 where the case
        failed: its status says why), ``flags`` and ``status`` as integer codes whose meanings
        are in their attributes (flags -1 where the case failed). ``ds.to_netcdf(path)``
        writes it as it is."""
        return drop_dataset(self)

    def to_pint(self, registry: Any = None) -> dict[str, Any]:
        """Each output (``PUBLIC_FIELDS``, ``initial_energy``, ``max_delta_ratio``) as a pint
        Quantity of an array (SI; NaN where a case failed); ``registry``: your pint
        registry."""
        ureg = pint_registry(registry)
        return {
            name: ureg.Quantity(np.array(self[name]), pint_unit(output_unit(name)[0]))
            for name in (*DATASET_OUTPUTS, *schema.DERIVED_FIELDS)
        }

    def dois(self) -> tuple[str, ...]:
        """DOIs of ``references``, in order, without repeats."""
        return doi_list(self.references)

    def _repr_html_(self) -> str:  # BatchResult's notebook summary, the sequence totals' names
        return batch_summary_html(self, schema.RENAMED_DROP_FIELDS)

    def __repr__(self) -> str:
        """One line: the counts (as ``BatchResult``'s), law, friction, body, gravity, rtol."""
        return (
            f"DropBatchResult({batch_counts(self)}, law={self.law!r}, friction={self.friction!r}"
            f", body={self.body!r}, gravity={self.gravity:.6g} m/s^2, rtol={self.rtol:g})"
        )
