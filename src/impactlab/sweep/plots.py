"""Plots of a sweep: regime maps with the analytic mu_c boundary, output maps, histograms.

- ``plot_regime_map``: the friction regime (engine codes, e.g. slip / stick / reversal) over
  two swept inputs (by default the angle and mu) on a categorical colour scale with a legend,
  with the rigid-body boundary mu_c(theta) = a b / (k^2 + b^2)
  (``impactlab.analytic.critical_friction``; physics notes Sec. 1) drawn on an angle x mu map.
- ``plot_output_map``: one output over two swept inputs (e.g. angle and vy), or a line over one;
  a categorical output (``regime``) is drawn as the regime map, never on a continuous scale.
- ``plot_histograms``: the distributions of a Monte Carlo study's outputs.

``impactlab.sweep.plotsweep.plot_sweep`` writes every plot a study allows and names the ones it
cannot draw. The slices and facets of a map: ``impactlab.sweep.plotgrid``. Values are shown in
the display layer's units (``impactlab._display``: angles in deg, dent-scale lengths in um,
other lengths in mm, durations in ms); they stay SI in the Dataset.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from impactlab._mpl import pyplot
from impactlab.analytic import critical_friction
from impactlab.bodies import PAPER_ROD, Rod
from impactlab.flags import ADVISORY_FLAGS
from impactlab.sweep.display import plot_unit
from impactlab.sweep.inputs import OUTPUT_ALIASES, output_spec
from impactlab.sweep.netcdf import as_dataset
from impactlab.sweep.plotgrid import (
    MAX_FACETS,
    MAX_FACETS_SIDE,
    SliceWarning,
    empty_panel,
    facets,
    label,
    select,
    title,
)

__all__ = [
    "CATEGORY_OUTPUTS",
    "MAX_FACETS",
    "MAX_FACETS_SIDE",
    "SliceWarning",
    "critical_friction_curve",
    "plot_histograms",
    "plot_output_map",
    "plot_regime_map",
]

#: Outputs whose values are category codes (drawn on a categorical scale, never histogrammed).
CATEGORY_OUTPUTS = ("regime",)


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
    """Friction regime over ``x`` and ``y`` (default angle and mu; any two grid dimensions) on a
    categorical colour scale (one colour and legend entry per regime), with mu_c(theta) drawn
    on an angle x mu map.

    Other dimensions: ``sel`` picks their values; without ``ax``, a free third dimension is
    drawn as facets (one panel per value). Titles name the slice. Returns the Axes (an array of
    Axes for facets). ``ds``: the Dataset, a store's path or ``run_sweep``'s result."""
    ds = as_dataset(ds)
    if "regime" not in ds.data_vars:
        raise ValueError("the sweep did not keep the output 'regime'")
    for d in (x, y):
        if d not in ds.dims:
            raise ValueError(f"a regime map needs {d!r} as a grid dimension; dims: {list(ds.dims)}")
    return facets(ds, (x, y), sel, lambda s, a: _regime_panel(ds, x, y, s, a, show_mu_c), ax)


def _regime_panel(
    ds: Any, x: str, y: str, sel: Mapping[str, Any], ax: Any, show_mu_c: bool
) -> None:
    pyplot()
    # matplotlib modules load after pyplot() has settled the backend (see impactlab._mpl)
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.patches import Patch

    sub = select(ds[_variables(ds, "regime")], (x, y), sel).transpose(y, x)
    bad = _flagged(sub)  # computed, but not plain success: blank, marked x, as in output maps
    reg = np.asarray(sub["regime"].values, dtype=float)
    reg[(np.asarray(sub["status"].values) != 0) | bad] = np.nan
    names = {int(k): v for k, v in ds["regime"].attrs.get("regimes", {}).items()}
    codes = sorted(names) or sorted({int(v) for v in reg[np.isfinite(reg)].ravel()})
    xs, xl = label(ds, x)
    ys, yl = label(ds, y)
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
    if show_mu_c and x == "angle" and y == "mu":
        th = np.linspace(float(np.min(sub[x])), float(np.max(sub[x])), 200)
        mu_c = critical_friction_curve(sub, th)
        if mu_c is not None:
            (line,) = ax.plot(
                th * xs, mu_c * ys, "k-", lw=2, label=r"$\mu_c = ab/(k^2+b^2)$ (rigid body)"
            )
            handles.append(line)
    if bad.any():
        iy, ix = np.nonzero(bad)
        ax.plot(xv[ix], yv[iy], "kx", ms=5, clip_on=False)  # whole on the grid's edge
    data_limits(ax, xv, yv)
    ax.set_xlabel(xl)
    ax.set_ylabel(yl)
    title(ax, "friction regime" + _flag_note(int(bad.sum())), ds, sub)
    empty_panel(ax, ds, sub, "regime", np.where(reg >= 0, reg, np.nan))
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
    gravity-dominated, the other end, beyond the tip), marked x and counted in the title. Other
    dimensions as in ``plot_regime_map`` (facets without ``ax``, the slice in the titles);
    returns the Axes (an array of Axes for facets). ``ds`` as in ``plot_regime_map``."""
    ds = as_dataset(ds)
    out = OUTPUT_ALIASES.get(output, output)
    if out not in ds.data_vars:
        raise ValueError(f"the sweep has no output {output!r}")
    keep = (x,) if y is None else (x, y)
    for d in keep:
        if d not in ds.dims:
            raise ValueError(f"{d!r} is not a grid dimension; dims: {list(ds.dims)}")
    if out in CATEGORY_OUTPUTS:
        if y is None:
            return facets(ds, keep, sel, lambda s, a: _category_line(ds, out, x, s, a), ax)
        return plot_regime_map(ds, x=x, y=y, sel=sel, ax=ax)
    return facets(ds, keep, sel, lambda s, a: _output_panel(ds, out, x, y, s, a), ax)


def _category_line(ds: Any, out: str, x: str, sel: Mapping[str, Any], ax: Any) -> None:
    """A category output over one dimension: points at the category's row, named on the axis."""
    sub = select(ds[[out, "status"]], (x,), sel)
    codes = np.asarray(sub[out].values, dtype=float)
    codes[np.asarray(sub["status"].values) != 0] = np.nan
    names = {int(k): v for k, v in ds[out].attrs.get("regimes", {}).items()}
    shown = sorted(names) or sorted({int(c) for c in codes[np.isfinite(codes)]})
    xs, xl = label(ds, x)
    ax.plot(np.asarray(sub[x].values, dtype=float) * xs, codes, "o", ms=4)
    ax.set_yticks(shown, [names.get(c, str(c)) for c in shown])
    ax.set_xlabel(xl)
    title(ax, out, ds, sub)
    empty_panel(ax, ds, sub, out, np.where(codes >= 0, codes, np.nan))


def data_limits(ax: Any, xv: np.ndarray, yv: np.ndarray) -> None:
    """The map's axes end at the grid's first and last values (an axis of one value keeps
    matplotlib's limits)."""
    if xv.min() < xv.max():
        ax.set_xlim(xv.min(), xv.max())
    if yv.min() < yv.max():
        ax.set_ylim(yv.min(), yv.max())


def _flagged(sub: Any) -> np.ndarray:
    """True where a computed case carries a flag that says it is not plain success (energy
    gain, gravity-dominated, the other end, beyond the tip; the advisory LAW_EXTRAPOLATED
    aside)."""
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
    sub = select(ds[_variables(ds, out)], keep, sel)
    if y is not None:
        sub = sub.transpose(y, x)
    bad = _flagged(sub)
    vals = np.asarray(sub[out].values, dtype=float)
    vals = np.where((np.asarray(sub["status"].values) == 0) & ~bad, vals, np.nan)
    unit = output_spec(out).unit
    vs, vunit = plot_unit(out, unit)
    vlabel = f"{out} [{vunit}]" if vunit and vunit != "1" else out
    xs, xl = label(ds, x)
    xv = np.asarray(sub[x].values, dtype=float) * xs
    if y is None:
        ax.plot(xv, vals * vs, "o-", ms=3)
        if bad.any():
            raw = np.asarray(sub[out].values, dtype=float)[bad] * vs
            low = np.nanmin(vals * vs) if np.isfinite(vals).any() else 0.0  # none unflagged
            ax.plot(xv[bad], np.where(np.isfinite(raw), raw, low), "rx", ms=5)
        ax.set_ylabel(vlabel)
    else:
        ys, yl = label(ds, y)
        yv = np.asarray(sub[y].values, dtype=float) * ys
        mesh = ax.pcolormesh(xv, yv, vals * vs, shading="nearest")
        ax.figure.colorbar(mesh, ax=ax, label=vlabel)
        data_limits(ax, xv, yv)  # "nearest" cells reach half a step beyond: not past 90 deg
        if bad.any():
            iy, ix = np.nonzero(bad)
            ax.plot(xv[ix], yv[iy], "kx", ms=5, clip_on=False)
        ax.set_ylabel(yl)
    ax.set_xlabel(xl)
    title(ax, out + _flag_note(int(bad.sum())), ds, sub)
    empty_panel(ax, ds, sub, out, vals)


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
