"""The layout of a sweep's plots: which slice of the study a panel shows, and facets.

A map shows two dimensions; every other dimension is sliced, and the title says where
(``law = brake, vy = -1.41 m/s``). Without ``ax`` a study with a third dimension is drawn as
facets, one panel per value of that dimension (at most ``MAX_FACETS``, evenly spaced), and one
with a fourth as rows x columns of panels (at most ``MAX_FACETS_SIDE`` values each way).
Further dimensions take the value in ``sel``, else their first: the figure's title and a
:class:`SliceWarning` (one line) name the values shown and how to choose others (``sel``).
The plots themselves: ``impactlab.sweep.plots``.
"""

from __future__ import annotations

import textwrap
import warnings
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from impactlab._mpl import pyplot
from impactlab.sweep.display import plot_unit, slice_note, value_text

__all__ = [
    "MAX_FACETS",
    "MAX_FACETS_SIDE",
    "EmptyPanel",
    "SliceWarning",
    "empty_panel",
    "facets",
    "label",
    "select",
    "title",
]


def label(ds: Any, name: str) -> tuple[float, str]:
    units = str(ds[name].attrs.get("units", "")) if name in ds.variables else ""
    scale, unit = plot_unit(name, units)
    return scale, f"{name} [{unit}]" if unit and unit != "1" else name


#: The most panels a faceted map draws (a longer dimension shows evenly spaced values).
MAX_FACETS = 16
#: The most values per dimension of a map faceted on two dimensions (rows x columns).
MAX_FACETS_SIDE = 4


class SliceWarning(UserWarning):
    """A plot shows one slice of dimensions it cannot draw (a fifth dimension and beyond): the
    message names the values shown and how to choose others (``sel``)."""


def select(ds: Any, keep: Sequence[str], sel: Mapping[str, Any] | None) -> Any:
    """Reduce ``ds`` to the dimensions ``keep``: ``sel`` picks values (nearest) of the others,
    an index along a dimension without a coordinate (``sample``); dimensions not in ``sel`` take
    their first index. The slice is named by ``where``."""
    sel = dict(sel or {})
    for d in list(ds.dims):
        if d in keep:
            continue
        if d in sel:
            v = sel.pop(d)
            if d not in ds.coords:
                i = _index(d, v, ds.sizes[d])
                ds = ds.isel({d: i}).assign_coords({d: i})  # the title names it: sample = 3
            elif isinstance(v, str):
                ds = ds.sel({d: v})
            else:
                ds = ds.sel({d: v}, method="nearest")
        else:
            ds = ds.isel({d: 0})
    if sel:
        raise ValueError(f"sel names {sorted(sel)}, which are not dimensions to select on")
    return ds


def _index(dim: str, value: Any, size: int) -> int:
    """``value`` as an index along ``dim`` (no coordinate: ``sel`` gives the index), or a
    ValueError naming it and the allowed range."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or not 0 <= value < size:
        raise ValueError(
            f"sel[{dim!r}] must be an index in [0, {size - 1}] ({dim} has no coordinate), "
            f"got {value!r}"
        )
    return int(value)


class EmptyPanel(UserWarning):
    """A panel of a plot shows no value: the message names the panel's slice and why (no case
    there has a result, with the commonest status; or the output has no value where cases
    have one, as a flexible rod's drop has no ``duration`` of one contact)."""


def empty_reason(sub: Any, out: str, messages: Mapping[str, str]) -> str:
    """Why the slice ``sub`` (with ``status``) shows no value of ``out``."""
    st = np.asarray(sub["status"].values).ravel()
    if not (st == 0).any():
        codes, counts = np.unique(st, return_counts=True)
        code = int(codes[np.argmax(counts)])
        text = str(messages.get(str(code), "?")).split(" (")[0]
        return f"no case there has a result (status {code}: {text})"
    raw = np.asarray(sub[out].values)
    vals = raw.astype(float).ravel()[st == 0]
    if (np.isfinite(vals) & ((vals >= 0) if raw.dtype.kind in "iu" else True)).any():
        return "every case with a result there is flagged (not plain success)"
    return f"{out} has no value where the cases have a result (not an output of theirs)"


def empty_panel(ax: Any, full: Any, sub: Any, out: str, shown: Any) -> None:
    """When the values ``shown`` of ``out`` on ``ax`` (the slice ``sub`` of ``full``) hold no
    finite number: the reason written on the panel and an :class:`EmptyPanel` warning."""
    if np.isfinite(np.asarray(shown, dtype=float)).any():
        return
    why = empty_reason(sub, out, full.attrs.get("status_messages", {}))
    ax.text(0.5, 0.5, textwrap.fill(f"no value: {why}", 30), ha="center", va="center",
            fontsize="small", transform=ax.transAxes,
            bbox={"facecolor": "white", "edgecolor": "0.6"})  # fmt: skip
    at = where(full, sub) or "the only panel"
    warnings.warn(f"{out}: empty panel ({at}): {why}", EmptyPanel, stacklevel=3)


def where(full: Any, sub: Any) -> str:
    """Where ``sub`` slices ``full``: ``"law = brake, vy = -1.41 m/s"`` ("" for no slice)."""
    parts = []
    for d in full.dims:
        if d in sub.dims or full.sizes[d] < 2:
            continue
        v = sub[d].values if d in sub.coords else None
        if v is not None and not np.ndim(v):
            parts.append(value_text(full, d, v.item()))
    return ", ".join(parts)


#: Characters of a panel title per inch of its panel's width (matplotlib's "medium" size).
TITLE_CHARS_PER_INCH = 11


def title(ax: Any, what: str, full: Any, sub: Any) -> None:
    """``what`` over the slice ``sub`` of ``full`` is (``where``), its ``name = value`` items
    broken into lines as wide as the panel, so that the titles of facets never overlap."""
    fig = ax.figure
    width = ax.get_position().width * fig.get_figwidth() * TITLE_CHARS_PER_INCH
    lines: list[str] = []
    for item in where(full, sub).split(", ") if where(full, sub) else []:
        if lines and len(lines[-1]) + 2 + len(item) <= max(width, 20):
            lines[-1] += f", {item}"
        else:
            lines.append(item)
    ax.set_title("\n".join([what, *lines]), fontsize="medium")


def _free_dims(ds: Any, keep: Sequence[str], sel: Mapping[str, Any] | None) -> list[str]:
    """The dimensions beside ``keep`` with more than one value that ``sel`` leaves free."""
    return [d for d in ds.dims if d not in keep and d not in (sel or {}) and ds.sizes[d] > 1]


def _picks(n: int, most: int) -> np.ndarray:
    """Up to ``most`` evenly spaced indices of ``n`` values (first and last included)."""
    return np.unique(np.linspace(0, n - 1, min(n, most)).round().astype(int))


def facets(ds: Any, keep: Sequence[str], sel: Mapping[str, Any] | None, draw: Any, ax: Any) -> Any:
    """``draw(sel, ax)`` once (given ``ax``, or no free third dimension), else once per value of
    the free dimension on a grid of panels, or per pair of values of two free dimensions on
    rows x columns; returns the axes (an array for facets). Free dimensions beyond two take
    their first value, named in the figure's title and in a :class:`SliceWarning`."""
    plt = pyplot()
    free = _free_dims(ds, keep, sel)
    if ax is not None or not free:
        if ax is None:
            _, ax = plt.subplots(figsize=(6.4, 4.8))
        draw(dict(sel or {}), ax)
        return ax
    dim, row_dim, hidden = free[0], (free[1] if len(free) > 1 else None), free[2:]
    base = {**dict(sel or {}), **{d: ds[d].values[0] for d in hidden}}
    n = int(ds.sizes[dim])
    if row_dim is None:
        picks = _picks(n, MAX_FACETS)
        cols = min(len(picks), 4)
        rows = -(-len(picks) // cols)
        cells = [(a, {dim: ds[dim].values[i]}) for a, i in enumerate(picks)]
        row_picks = picks[:0]
    else:
        picks, row_picks = _picks(n, MAX_FACETS_SIDE), _picks(ds.sizes[row_dim], MAX_FACETS_SIDE)
        cols, rows = len(picks), len(row_picks)
        cells = [
            (r * cols + c, {dim: ds[dim].values[i], row_dim: ds[row_dim].values[j]})
            for r, j in enumerate(row_picks)
            for c, i in enumerate(picks)
        ]
    fig, axes = plt.subplots(
        rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False, constrained_layout=True
    )
    for k, pick in cells:
        draw({**base, **pick}, axes.flat[k])
    for a in axes.flat[len(cells) :]:
        a.set_visible(False)
    lines = [f"columns: {dim}, rows: {row_dim}" if row_dim else f"panels: {dim}"]
    lines += [
        f"{len(p)} of the {ds.sizes[d]} values of {d}"
        for d, p in ((dim, picks), (row_dim, row_picks))
        if d is not None and len(p) < ds.sizes[d]
    ]
    if hidden:
        note = slice_note(ds, hidden)
        lines.append(
            f"fixed: {', '.join(value_text(ds, d, ds[d].values[0]) for d in hidden)} "
            f"(choose with sel={{{hidden[0]!r}: ...}})"
        )
        warnings.warn(note, SliceWarning, stacklevel=3)
    fig.suptitle("; ".join(lines), fontsize="small")
    return axes
