"""Plots of a sweep: regime maps with the analytic mu_c boundary, and output maps.

- ``plot_regime_map``: the friction regime (engine codes, e.g. slip / stick / reversal) over the
  angle and mu, with the rigid-body boundary mu_c(theta) = a b / (k^2 + b^2)
  (``impactlab.analytic.critical_friction``; physics notes Sec. 1) drawn on top.
- ``plot_output_map``: one output over two swept inputs (e.g. angle and vy), or a line over one.
- ``plot_sweep``: every plot the sweep's dimensions allow, written to a folder.

A map shows two dimensions; every other dimension is sliced, and the title says where
(``law = brake, vy = -1.41 m/s``). Without ``ax`` a study with a third dimension is drawn as
facets, one panel per value of that dimension (at most ``MAX_FACETS``, evenly spaced), and one
with a fourth as rows x columns of panels (at most ``MAX_FACETS_SIDE`` values each way).
Further dimensions take the value in ``sel``, else their first: the figure's title and a
:class:`SliceWarning` (one line) name the values shown and how to choose others (``sel``).

Values are shown in the display layer's units (``impactlab._display``: angles in deg, dent-scale
lengths in um, other lengths in mm, durations in ms); they stay SI in the Dataset.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._mpl import pyplot
from impactlab.analytic import critical_friction
from impactlab.bodies import PAPER_ROD, Rod
from impactlab.flags import ADVISORY_FLAGS
from impactlab.sweep.dimensions import SAMPLE_DIM
from impactlab.sweep.display import plot_unit, slice_note, value_text
from impactlab.sweep.inputs import OUTPUT_ALIASES, output_spec

_VELOCITY_DIMS = ("vy", "vx", "spin")


def _label(ds: Any, name: str) -> tuple[float, str]:
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


def _select(ds: Any, keep: Sequence[str], sel: Mapping[str, Any] | None) -> Any:
    """Reduce ``ds`` to the dimensions ``keep``: ``sel`` picks values (nearest) of the others;
    dimensions not in ``sel`` take their first index. The slice is named by ``_where``."""
    sel = dict(sel or {})
    for d in list(ds.dims):
        if d in keep:
            continue
        if d in sel:
            v = sel.pop(d)
            ds = ds.sel({d: v}) if isinstance(v, str) else ds.sel({d: v}, method="nearest")
        else:
            ds = ds.isel({d: 0})
    if sel:
        raise ValueError(f"sel names {sorted(sel)}, which are not dimensions to select on")
    return ds


def _where(full: Any, sub: Any) -> str:
    """Where ``sub`` slices ``full``: ``"law = brake, vy = -1.41 m/s"`` ("" for no slice)."""
    parts = []
    for d in full.dims:
        if d in sub.dims or full.sizes[d] < 2:
            continue
        v = sub[d].values if d in sub.coords else None
        if v is not None and not np.ndim(v):
            parts.append(value_text(full, d, v.item()))
    return ", ".join(parts)


def _title(ax: Any, what: str, full: Any, sub: Any) -> None:
    where = _where(full, sub)
    ax.set_title(f"{what}\n{where}" if where else what, fontsize="medium")


def _free_dims(ds: Any, keep: Sequence[str], sel: Mapping[str, Any] | None) -> list[str]:
    """The dimensions beside ``keep`` with more than one value that ``sel`` leaves free."""
    return [d for d in ds.dims if d not in keep and d not in (sel or {}) and ds.sizes[d] > 1]


def _picks(n: int, most: int) -> np.ndarray:
    """Up to ``most`` evenly spaced indices of ``n`` values (first and last included)."""
    return np.unique(np.linspace(0, n - 1, min(n, most)).round().astype(int))


def _facets(ds: Any, keep: Sequence[str], sel: Mapping[str, Any] | None, draw: Any, ax: Any) -> Any:
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


def _rod_for(ds: Any) -> Rod | None:
    """The rod of a sweep (fixed geometry) for mu_c, or None (a sphere, or varying geometry)."""
    body = str(ds["body"].values) if "body" in ds.variables else "rod"
    if body != "rod":
        return None
    vals: dict[str, float | None] = {
        "length": PAPER_ROD.length,
        "tip_radius": PAPER_ROD.tip_radius,
        "mass": PAPER_ROD.mass,
        "inertia": None,
    }
    for name in vals:
        if name in ds.variables:
            v = ds[name]
            if v.ndim:
                return None
            vals[name] = float(v.values)
    return Rod(
        length=float(vals["length"] or 0.0),
        tip_radius=float(vals["tip_radius"] or 0.0),
        mass=float(vals["mass"] or 0.0),
        inertia=vals["inertia"],
    )


def critical_friction_curve(ds: Any, angles: np.ndarray) -> np.ndarray | None:
    """mu_c at ``angles`` [rad] for the sweep's rod (None if not a rod with fixed geometry)."""
    rod = _rod_for(ds)
    if rod is None:
        return None
    return np.asarray(critical_friction(angles, rod), dtype=np.float64)


def plot_regime_map(
    ds: Any,
    *,
    x: str = "angle",
    y: str = "mu",
    sel: Mapping[str, Any] | None = None,
    ax: Any = None,
    show_mu_c: bool = True,
) -> Any:
    """Friction regime over ``x`` (angle) and ``y`` (mu), with mu_c(theta) drawn on it.

    Other dimensions: ``sel`` picks their values; without ``ax``, a free third dimension is
    drawn as facets (one panel per value). Titles name the slice. Returns the Axes (an array of
    Axes for facets)."""
    if "regime" not in ds.data_vars:
        raise ValueError("the sweep did not keep the output 'regime'")
    for d in (x, y):
        if d not in ds.dims:
            raise ValueError(f"a regime map needs {d!r} as a grid dimension; dims: {list(ds.dims)}")
    return _facets(ds, (x, y), sel, lambda s, a: _regime_panel(ds, x, y, s, a, show_mu_c), ax)


def _regime_panel(
    ds: Any, x: str, y: str, sel: Mapping[str, Any], ax: Any, show_mu_c: bool
) -> None:
    pyplot()
    # matplotlib modules load after pyplot() has settled the backend (see impactlab._mpl)
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.patches import Patch

    sub = _select(ds[["regime", "status"]], (x, y), sel)
    reg = np.asarray(sub["regime"].transpose(y, x).values, dtype=float)
    reg[np.asarray(sub["status"].transpose(y, x).values) != 0] = np.nan
    names = {int(k): v for k, v in ds["regime"].attrs.get("regimes", {}).items()}
    codes = sorted(names) or sorted({int(v) for v in reg[np.isfinite(reg)].ravel()})
    xs, xl = _label(ds, x)
    ys, yl = _label(ds, y)
    xv = np.asarray(sub[x].values, dtype=float) * xs
    yv = np.asarray(sub[y].values, dtype=float) * ys
    palette = ["#4c72b0", "#dd8452", "#55a868", "#c44e52", "#8172b3", "#937860"]
    if codes:
        lo, hi = min(codes), max(codes)
        cmap = ListedColormap([palette[(c - lo) % len(palette)] for c in range(lo, hi + 1)])
        norm = BoundaryNorm(np.arange(lo - 0.5, hi + 1.5), cmap.N)
        ax.pcolormesh(xv, yv, reg, cmap=cmap, norm=norm, shading="nearest")
        handles = [
            Patch(color=palette[(c - lo) % len(palette)], label=names.get(c, str(c))) for c in codes
        ]
    else:
        handles = []
    if show_mu_c and x == "angle":
        th = np.linspace(float(np.min(sub[x])), float(np.max(sub[x])), 200)
        mu_c = critical_friction_curve(sub, th)
        if mu_c is not None:
            (line,) = ax.plot(
                th * xs, mu_c * ys, "k-", lw=2, label=r"$\mu_c = ab/(k^2+b^2)$ (rigid body)"
            )
            handles.append(line)
    ax.set_xlim(xv.min(), xv.max())
    ax.set_ylim(yv.min(), yv.max())
    ax.set_xlabel(xl)
    ax.set_ylabel(yl)
    _title(ax, "friction regime", ds, sub)
    if handles:
        ax.legend(handles=handles, loc="best", fontsize="small")


def plot_output_map(
    ds: Any,
    output: str,
    *,
    x: str = "angle",
    y: str | None = None,
    sel: Mapping[str, Any] | None = None,
    ax: Any = None,
) -> Any:
    """``output`` over ``x`` and ``y`` (colour map) or over ``x`` alone (line); invalid cases
    (status != 0) are blank, and so are flagged ones (not plain success: energy gain,
    gravity-dominated, the other end), marked x and counted in the title. Other dimensions as
    in ``plot_regime_map`` (facets without ``ax``, the slice in the titles); returns the Axes
    (an array of Axes for facets)."""
    out = OUTPUT_ALIASES.get(output, output)
    if out not in ds.data_vars:
        raise ValueError(f"the sweep has no output {output!r}")
    keep = (x,) if y is None else (x, y)
    for d in keep:
        if d not in ds.dims:
            raise ValueError(f"{d!r} is not a grid dimension; dims: {list(ds.dims)}")
    return _facets(ds, keep, sel, lambda s, a: _output_panel(ds, out, x, y, s, a), ax)


def _flagged(sub: Any) -> np.ndarray:
    """True where a computed case carries a flag that says it is not plain success (energy
    gain, gravity-dominated, the other end; the advisory LAW_EXTRAPOLATED aside)."""
    st = np.asarray(sub["status"].values)
    if "flags" not in sub.data_vars:
        return np.zeros(st.shape, dtype=bool)
    f = np.asarray(sub["flags"].values)
    f = np.where(f < 0, 0, f).astype(np.int64)
    return (st == 0) & ((f & ~ADVISORY_FLAGS) != 0)


def _flag_note(n: int) -> str:
    """The title's note on the flagged cases left blank ("" for none)."""
    return f" ({n} flagged case{'s' if n != 1 else ''} blank, marked x)" if n else ""


def _variables(ds: Any, out: str) -> list[str]:
    return [out, "status"] + (["flags"] if "flags" in ds.data_vars else [])


def _output_panel(
    ds: Any, out: str, x: str, y: str | None, sel: Mapping[str, Any], ax: Any
) -> None:
    keep = (x,) if y is None else (x, y)
    sub = _select(ds[_variables(ds, out)], keep, sel)
    if y is not None:
        sub = sub.transpose(y, x)
    bad = _flagged(sub)
    vals = np.asarray(sub[out].values, dtype=float)
    vals = np.where((np.asarray(sub["status"].values) == 0) & ~bad, vals, np.nan)
    unit = output_spec(out).unit
    vs, vunit = plot_unit(out, unit)
    vlabel = f"{out} [{vunit}]" if vunit and vunit != "1" else out
    xs, xl = _label(ds, x)
    xv = np.asarray(sub[x].values, dtype=float) * xs
    if y is None:
        ax.plot(xv, vals * vs, "o-", ms=3)
        if bad.any():
            raw = np.asarray(sub[out].values, dtype=float)[bad] * vs
            ax.plot(xv[bad], np.where(np.isfinite(raw), raw, np.nanmin(vals * vs)), "rx", ms=5)
        ax.set_ylabel(vlabel)
    else:
        ys, yl = _label(ds, y)
        yv = np.asarray(sub[y].values, dtype=float) * ys
        mesh = ax.pcolormesh(xv, yv, vals * vs, shading="nearest")
        ax.figure.colorbar(mesh, ax=ax, label=vlabel)
        if bad.any():
            iy, ix = np.nonzero(bad)
            ax.plot(xv[ix], yv[iy], "kx", ms=5)
        ax.set_ylabel(yl)
    ax.set_xlabel(xl)
    _title(ax, out + _flag_note(int(bad.sum())), ds, sub)


def plot_histograms(ds: Any, outputs: Sequence[str]) -> Any:
    """Histograms of Monte Carlo outputs (valid cases; the flagged ones excluded, counted in
    each panel's title)."""
    plt = pyplot()
    outs = [OUTPUT_ALIASES.get(o, o) for o in outputs if OUTPUT_ALIASES.get(o, o) in ds]
    n = max(1, len(outs))
    fig, axes = plt.subplots(1, n, figsize=(3.2 * n, 3.0), squeeze=False)
    st = np.asarray(ds["status"].values).ravel()
    bad = _flagged(ds).ravel()
    for ax, o in zip(axes[0], outs, strict=False):
        v = np.asarray(ds[o].values, dtype=float).ravel()
        v = v[(st == 0) & ~bad & np.isfinite(v)]
        s, unit = plot_unit(o, output_spec(o).unit)
        ax.hist(v * s, bins=50)
        ax.set_xlabel(f"{o} [{unit}]" if unit and unit != "1" else o)
        if bad.any():
            ax.set_title(f"{int(bad.sum())} flagged case{'s' if bad.sum() != 1 else ''} excluded",
                         fontsize="small")  # fmt: skip
    fig.tight_layout()
    return fig


def plot_sweep(
    ds: Any,
    outdir: str | Path,
    *,
    outputs: Sequence[str] = ("e", "delta_p", "sliding_length", "duration"),
    sel: Mapping[str, Any] | None = None,
) -> list[Path]:
    """Write every plot the sweep's dimensions allow into ``outdir`` (PNG); returns the files.

    angle x mu with 'regime' -> regime map (with mu_c); angle x a velocity -> output maps;
    angle alone -> output lines; a 'sample' dimension -> histograms. Two further dimensions
    are drawn as facets; maps of a grid+sample study show the sample in ``sel`` (default: the
    first). Dimensions beyond those take the value in ``sel``, else their first: one
    :class:`SliceWarning` per distinct slice says which.
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SliceWarning)
        files = _plot_all(ds, Path(outdir), outputs, sel)
    for note in dict.fromkeys(str(w.message) for w in caught if w.category is SliceWarning):
        warnings.warn(note, SliceWarning, stacklevel=2)
    for w in caught:
        if w.category is not SliceWarning:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return files


def _plot_all(
    ds: Any, out: Path, outputs: Sequence[str], sel: Mapping[str, Any] | None
) -> list[Path]:
    """The plots of :func:`plot_sweep`."""
    plt = pyplot()
    out.mkdir(parents=True, exist_ok=True)
    files: list[Path] = []
    dims = list(ds.dims)
    present = [o for o in (OUTPUT_ALIASES.get(o, o) for o in outputs) if o in ds.data_vars]
    msel = {SAMPLE_DIM: 0, **dict(sel or {})} if SAMPLE_DIM in dims else sel

    def save(axes: Any, name: str) -> None:
        fig = np.ravel(axes)[0].figure
        p = out / name
        fig.savefig(p, dpi=120, bbox_inches="tight")
        plt.close(fig)
        files.append(p)

    if "angle" in dims and "mu" in dims and "regime" in ds.data_vars:
        save(plot_regime_map(ds, sel=msel), "regime_map.png")
    vel = next((d for d in _VELOCITY_DIMS if d in dims), None)
    if "angle" in dims and vel is not None:
        for o in present:
            save(plot_output_map(ds, o, x="angle", y=vel, sel=msel), f"{o}_angle_{vel}.png")
    elif "angle" in dims:
        other = "mu" if "mu" in dims else None
        for o in present:
            name = f"{o}_angle{'_' + other if other else ''}.png"
            save(plot_output_map(ds, o, x="angle", y=other, sel=msel), name)
    if SAMPLE_DIM in dims and present:
        sub = _select(ds, (SAMPLE_DIM,), sel)
        save(plot_histograms(sub, present).axes, "histograms.png")
    return files
