"""Every plot a study allows, written to a folder, and a named reason for each one it cannot
draw (``plot_sweep``, ``plot_plan``).

The numeric grid dimensions with more than one value choose the maps, in the order angle, mu,
vy, vx, spin, then the study's others: two or more give a regime map (over angle and mu when
both are swept, with mu_c; else over the first two) and one map per output over the angle and
a velocity, the angle and mu, or else the first two; one gives lines; a ``sample`` dimension
gives histograms. Category dimensions (law, friction, ...) and further numeric ones are drawn as
facets or sliced (``impactlab.sweep.plotgrid``). The outputs drawn by default are one impact's
(:data:`DEFAULT_PLOT_OUTPUTS`) and, where the store keeps them, a flexible rod's drop's
(:data:`DROP_PLOT_OUTPUTS`); an output (or the regime) that no case of the store has a value
of, such as the one-contact outputs of a study of flexible rods only, is not drawn. Nothing is
skipped silently: a plot that cannot be drawn is named with its reason in a
:class:`PlotSkipped` warning (and ``plot_plan``).
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._mpl import pyplot
from impactlab.schema import RENAMED_DROP_FIELDS
from impactlab.sweep.dimensions import SAMPLE_DIM
from impactlab.sweep.filewrite import write_atomic
from impactlab.sweep.flexible import MEASURED_AS
from impactlab.sweep.inputs import OUTPUT_ALIASES
from impactlab.sweep.netcdf import as_dataset
from impactlab.sweep.plotgrid import EmptyPanel, SliceWarning, select, where
from impactlab.sweep.plots import (
    CATEGORY_OUTPUTS,
    plot_histograms,
    plot_output_map,
    plot_regime_map,
)
from impactlab.sweep.slabs import slabs, store_chunks

__all__ = [
    "DEFAULT_PLOT_OUTPUTS",
    "DROP_PLOT_OUTPUTS",
    "PlotPlan",
    "PlotSkipped",
    "plot_plan",
    "plot_sweep",
]

#: The outputs ``plot_sweep`` maps unless told otherwise.
DEFAULT_PLOT_OUTPUTS = ("e", "delta_p", "sliding_length", "duration")
#: The outputs of a flexible rod's drop it maps as well unless told otherwise, where the store
#: keeps them: its dent, its slip and the extent of its mark over all its contacts, and the
#: duration of its sequence.
DROP_PLOT_OUTPUTS = ("dent_depth", "sequence_sliding_length", "scar_length", "sequence_duration")
#: A drop's output of the meaning of an impact's (``schema.RENAMED_DROP_FIELDS``,
#: ``flexible.MEASURED_AS``): named where the impact's has no value.
_DROP_COUNTERPART = {**RENAMED_DROP_FIELDS, **MEASURED_AS}
#: At most this many cases of a store are read at a time to find whether an output has a value.
_BLOCK_CASES = 1 << 20
#: The order in which numeric grid dimensions become a map's axes.
_AXIS_ORDER = ("angle", "mu", "vy", "vx", "spin")
_VELOCITY_DIMS = ("vy", "vx", "spin")


class PlotSkipped(UserWarning):
    """A plot of a study that ``plot_sweep`` could not draw; the message says which and why."""


@dataclass
class PlotPlan:
    """The plots of a study: ``(file name, draw)`` pairs and the skipped plots' reasons."""

    plots: list[tuple[str, Callable[[], Any]]] = field(default_factory=list)
    skipped: list[str] = field(default_factory=list)


def _numeric_dims(ds: Any) -> list[str]:
    """The grid dimensions with a numeric coordinate and more than one value, axis order."""
    dims = [
        d
        for d in ds.dims
        if d != SAMPLE_DIM
        and ds.sizes[d] > 1
        and d in ds.coords
        and np.issubdtype(ds[d].dtype, np.number)
    ]
    return sorted(dims, key=lambda d: _AXIS_ORDER.index(d) if d in _AXIS_ORDER else 99)


def _map_axes(dims: list[str]) -> tuple[str, str]:
    """The two dimensions of the output maps: angle x a velocity, angle x mu, else the first
    two in axis order."""
    vel = next((d for d in _VELOCITY_DIMS if d in dims), None)
    if "angle" in dims and vel is not None:
        return "angle", vel
    return dims[0], dims[1]


def has_value(ds: Any, name: str) -> bool:
    """True when some case of ``ds`` has a value of ``name``: not NaN, or >= 0 for an integer
    output (-1: no value); read a block at a time, up to the first value found."""
    var = ds[name]
    integer = np.issubdtype(var.dtype, np.integer)
    for slab in slabs(tuple(var.shape), _BLOCK_CASES, store_chunks(ds)):
        v = np.asarray(var[slab].values)
        if (v >= 0).any() if integer else (~np.isnan(v)).any():
            return True
    return False


def _no_value(ds: Any, name: str) -> str:
    """Why output ``name`` of ``ds`` is not drawn: no case has a value of it."""
    drop = _DROP_COUNTERPART.get(name)
    instead = f"; a flexible rod's drop gives {drop}" if drop in ds.data_vars else ""
    return f"{name}: no case of the store has a value of it{instead}"


def plot_plan(
    ds: Any,
    outputs: Sequence[str] | None = None,
    sel: Mapping[str, Any] | None = None,
) -> PlotPlan:
    """What :func:`plot_sweep` draws for ``ds`` and what it cannot, with the reasons.

    outputs : the outputs to map; default :data:`DEFAULT_PLOT_OUTPUTS` and those of
        :data:`DROP_PLOT_OUTPUTS` the store keeps. An output no case has a value of is named
        in ``skipped``, not drawn.
    """
    plan = PlotPlan()
    if outputs is None:
        outputs = (*DEFAULT_PLOT_OUTPUTS, *(o for o in DROP_PLOT_OUTPUTS if o in ds.data_vars))
    wanted = list(dict.fromkeys(OUTPUT_ALIASES.get(o, o) for o in outputs))
    kept = [o for o in wanted if o in ds.data_vars]
    plan.skipped += [f"{o}: the study did not keep this output" for o in wanted if o not in kept]
    present = [o for o in kept if has_value(ds, o)]
    plan.skipped += [_no_value(ds, o) for o in kept if o not in present]
    nums = _numeric_dims(ds)
    has_sample = SAMPLE_DIM in ds.dims
    msel = {SAMPLE_DIM: 0, **dict(sel or {})} if has_sample else sel
    if len(nums) >= 2:
        if "regime" not in ds.data_vars:
            plan.skipped.append("regime map: the study did not keep the output 'regime'")
        elif not has_value(ds, "regime"):
            plan.skipped.append(
                "regime map: no case of the store has a regime (a flexible rod's drop has none)"
            )
        else:
            rx, ry = ("angle", "mu") if "angle" in nums and "mu" in nums else (nums[0], nums[1])
            plan.plots.append(
                ("regime_map.png", partial(plot_regime_map, ds, x=rx, y=ry, sel=msel))
            )
        x, y = _map_axes(nums)
        plan.plots += [
            (f"{o}_{x}_{y}.png", partial(plot_output_map, ds, o, x=x, y=y, sel=msel))
            for o in present
        ]
    elif len(nums) == 1:
        (x,) = nums
        plan.skipped.append(
            f"regime map and output maps: they need two swept numeric inputs, the study "
            f"sweeps one ({x}); drawn as lines over {x}"
        )
        plan.plots += [
            (f"{o}_{x}.png", partial(plot_output_map, ds, o, x=x, sel=msel)) for o in present
        ]
    elif not has_sample:
        swept = [d for d in ds.dims if ds.sizes[d] > 1]
        what = f"it sweeps only categories ({', '.join(swept)})" if swept else "nothing is swept"
        plan.skipped.append(f"maps: they need a swept numeric input (angle, mu, vy, ...); {what}")
    if has_sample:
        numbers = [o for o in present if o not in CATEGORY_OUTPUTS]
        plan.skipped += [f"{o}: a category, no histogram" for o in present if o not in numbers]
        if numbers:
            sub = select(ds, (SAMPLE_DIM,), sel)
            plan.plots.append(("histograms.png", partial(_histograms, ds, sub, numbers)))
    return plan


def _histograms(ds: Any, sub: Any, outputs: Sequence[str]) -> Any:
    """The histograms of the sample ``sub`` of ``ds``, titled with its grid point (if any)."""
    fig = plot_histograms(sub, outputs)
    at = where(ds, sub)
    if at:
        fig.suptitle(at, fontsize="small", y=1.02)
    return fig.axes


def plot_sweep(
    ds: Any,
    outdir: str | Path,
    *,
    outputs: Sequence[str] | None = None,
    sel: Mapping[str, Any] | None = None,
) -> list[Path]:
    """Write every plot the sweep's dimensions allow into ``outdir`` (PNG); returns the files.

    The maps and lines follow the swept numeric inputs (module docstring), of ``outputs``
    (default: :func:`plot_plan`'s, a flexible rod's drop's included where the store keeps
    them; an output no case has a value of is not drawn); a 'sample'
    dimension adds histograms (of a grid+sample study: of one grid point, the first or the one
    in ``sel``, named in the title). Two further dimensions are drawn as facets; maps of a
    grid+sample study show the sample index in ``sel`` (``{"sample": 3}``; default: the
    first). Dimensions beyond those take the value in ``sel``, else their first: one
    :class:`SliceWarning` per distinct slice says which. Each plot it cannot draw is named, with
    the reason, in a :class:`PlotSkipped` warning. ``ds``: the Dataset, a store's path or
    ``run_sweep``'s result.
    """
    ds = as_dataset(ds)
    plan = plot_plan(ds, outputs, sel)
    plt = pyplot()
    out = Path(outdir)
    out.mkdir(parents=True, exist_ok=True)
    files: list[Path] = []
    empty: list[str] = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SliceWarning)
        warnings.simplefilter("always", EmptyPanel)
        for name, draw in plan.plots:
            before = len(caught)
            fig = np.ravel(draw())[0].figure
            path = out / name
            save = partial(fig.savefig, dpi=120, bbox_inches="tight", format="png")
            try:  # under a temporary name, then renamed: no half-written PNG on a full disk
                write_atomic(path, save)
            finally:
                plt.close(fig)
            files.append(path)
            empty += _empty_notes(name, [w for w in caught[before:] if w.category is EmptyPanel])
    for note in dict.fromkeys(str(w.message) for w in caught if w.category is SliceWarning):
        warnings.warn(note, SliceWarning, stacklevel=2)
    for w in caught:
        if w.category not in (SliceWarning, EmptyPanel):
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    for reason in [*plan.skipped, *empty]:
        warnings.warn(f"not plotted: {reason}", PlotSkipped, stacklevel=2)
    return files


def _empty_notes(name: str, caught: Sequence[Any]) -> list[str]:
    """One note per reason for the empty panels of the plot file ``name`` (their
    :class:`EmptyPanel` warnings): ``"e_angle.png: empty panel(s) body = sphere; ...: why"``."""
    by_reason: dict[str, list[str]] = {}
    for w in caught:
        head, _, why = str(w.message).partition("): ")
        by_reason.setdefault(why, []).append(head.partition(": empty panel (")[2])
    return [f"{name}: empty panel(s) {'; '.join(at)}: {why}" for why, at in by_reason.items()]
