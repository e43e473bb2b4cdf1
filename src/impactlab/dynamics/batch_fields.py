"""How a batch of results (``BatchResult``, ``DropBatchResult``) shows itself: its fields in
``dir()`` and tab completion, the AttributeError of a name it has not (with the nearest field),
the counts of its one-line ``repr``, and the conventions of its ``to_dataframe`` (SI units in
``df.attrs["units"]`` and ``regime`` by name, as ``History.to_dataframe`` has them)."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

import numpy as np

from impactlab._validation import did_you_mean
from impactlab.dynamics.kernels.status import REGIME_NAMES, ST_OK, STATUS_MESSAGES
from impactlab.flags import ADVISORY_FLAGS, ResultFlag, messages

__all__ = [
    "BATCH_NAMES",
    "batch_counts",
    "field_dir",
    "flagged_messages",
    "no_field",
    "regime_series",
    "with_units",
]


def field_dir(obj: object, fields: Iterable[str]) -> list[str]:
    """``dir(obj)`` with the batch's ``fields`` (read as attributes through ``__getattr__``)."""
    return sorted({*object.__dir__(obj), *fields})


#: A one-impact result's field (``ImpactResult``, ``DropResult``) or ``simulate``'s keyword ->
#: the batch's columns of the same quantity (a pair as two columns, under the inputs' names).
BATCH_NAMES: dict[str, str] = {
    "velocity_in": "vx, vy",
    "spin_in": "spin",
    "velocity": "vx, vy",
}


def no_field(obj: object, name: str, fields: Iterable[str]) -> AttributeError:
    """The AttributeError of a batch's ``obj.name`` for a name that is no field: the type, the
    batch's name of a one-impact result's field (:data:`BATCH_NAMES`: ``velocity_in -> vx,
    vy``), else the nearest field (``_validation.did_you_mean``), and the known fields."""
    known = list(dict.fromkeys(fields))
    columns = BATCH_NAMES.get(name)
    if columns is not None and set(columns.split(", ")) <= set(known):
        hint = f" (a batch's columns: {name} -> {columns})"
    else:
        hint = did_you_mean(name, known)
    return AttributeError(
        f"{type(obj).__name__} has no field or attribute {name!r}{hint}; "
        f"its fields: {', '.join(known)}"
    )


def batch_counts(batch: Any) -> str:
    """``"3 cases, 3 computed, 1 ok (1 marked: law extrapolated), 2 not ok (brittle: 2)"``:
    the counts of a batch's one-line ``repr``. As ``ok`` reads them, the advisory flags
    (``impactlab.flags.ADVISORY_FLAGS``) leave a case ok, counted as marked; "not ok" counts
    the computed cases with another flag (computed = ok + not ok) and, as a sweep's summary
    does, the cases with each such flag."""
    computed, ok = np.asarray(batch.computed, dtype=bool), np.asarray(batch.ok, dtype=bool)
    all_flags = np.asarray(batch.flags, dtype=np.int64)
    flags = np.where(ok, all_flags, 0)
    marked = ""
    if np.any(flags):
        names = [_FLAG_NAME[f] for f in ResultFlag if f & ADVISORY_FLAGS and np.any(flags & f)]
        marked = f" ({int(np.count_nonzero(flags))} marked: {', '.join(names)})"
    n, n_ok, bad = (int(np.count_nonzero(m)) for m in (computed, ok, computed & ~ok))
    cases = f"{len(batch)} case{'s' * (len(batch) != 1)}"
    why = _reasons(all_flags[computed & ~ok])
    return f"{cases}, {n} computed, {n_ok} ok{marked}, {bad} not ok{why}"


def _reasons(flags: np.ndarray) -> str:
    """``" (brittle: 2, energy gain: 1)"``: the cases with each flag that makes a case not ok
    among the not-ok cases' ``flags`` ("" for none)."""
    counts = [(f, int(np.count_nonzero(flags & f))) for f in ResultFlag if f & ~ADVISORY_FLAGS]
    named = ", ".join(f"{_FLAG_NAME[f]}: {k:,}" for f, k in counts if k)
    return f" ({named})" if named else ""


#: Each flag's name as its message begins (``"law extrapolated"``).
_FLAG_NAME = {f: messages(int(f))[0].split(":")[0] for f in ResultFlag if f.value}


def flagged_messages(texts: list[str], flags: np.ndarray, ok: np.ndarray) -> list[str]:
    """A batch's ``messages`` (``texts``, one per case) with that of each computed case that is
    not ``ok`` naming its flags by the names their messages begin with (``impactlab.flags``),
    ``"computed, not ok (flags 17): energy gain, beyond the tip"``, instead of the status's
    ``"ok"``: first the flags that make it not ok, then any advisory one
    (``impactlab.flags.ADVISORY_FLAGS``, which leave a case ok) after ``"; advisory: "``,
    ``"computed, not ok (flags 20): beyond the tip; advisory: law extrapolated"``; an ok case
    (no flag, or advisory ones only) keeps its text."""
    out = list(texts)
    f = np.asarray(flags, dtype=np.int64)
    for i in np.flatnonzero((f & ~ADVISORY_FLAGS) != 0):
        if not bool(ok[i]) and out[i] == STATUS_MESSAGES[ST_OK]:
            bits = [b for b in ResultFlag if b.value and f[i] & b]
            names = ", ".join(_FLAG_NAME[b] for b in bits if not b & ADVISORY_FLAGS)
            advisory = ", ".join(_FLAG_NAME[b] for b in bits if b & ADVISORY_FLAGS)
            more = f"; advisory: {advisory}" if advisory else ""
            out[i] = f"computed, not ok (flags {int(f[i])}): {names}{more}"
    return out


def regime_series(values: np.ndarray, computed: np.ndarray) -> Any:
    """The ``regime`` codes as a pandas categorical of the regime names (``REGIME_NAMES``, in
    code order, as ``ImpactResult.regime`` reads them; string categories, so that a failed
    case shows ``<NA>`` as the nullable integer columns do)."""
    import pandas as pd  # heavy, needed only here

    f = np.asarray(values, dtype=np.float64)
    keep = np.asarray(computed, dtype=bool) & np.isfinite(f)
    codes = np.where(keep, f, -1.0).astype(np.int64)
    names = pd.Index([REGIME_NAMES[k] for k in sorted(REGIME_NAMES)], dtype="string")
    return pd.Series(pd.Categorical.from_codes(codes, categories=names))


def with_units(df: Any, unit_of: Callable[[str], str]) -> Any:
    """``df`` with ``df.attrs["units"]``: column -> SI unit (``unit_of(column)``, from
    ``impactlab.schema``; ``"1"`` for the ``status`` code)."""
    df.attrs["units"] = {c: "1" if c == "status" else unit_of(c) for c in df.columns}
    return df
