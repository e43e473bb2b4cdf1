"""Figures of one impact: force-time, force-penetration (loading and unloading branches) and the
contact-point path with the predicted dent. Matplotlib only (through ``impactlab._mpl``, the
package's backend policy); nothing here changes a result.

Each ``plot_*`` draws into ``ax`` when given and returns its Figure. Without ``ax`` it makes a
new Figure that pyplot does not keep open: a notebook shows it once (as the cell's value), and
``fig.savefig(...)`` writes it; ``plt.show()`` does not list it (draw into ``ax`` of your own
``plt.subplots()`` for that). ``save_figures`` writes all four.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from impactlab._mpl import pyplot
from impactlab.dynamics.drop_result import DropResult
from impactlab.dynamics.results import History, ImpactResult


class NotPlottableError(TypeError, ValueError):
    """A result these figures do not draw: a TypeError (a ValueError too, as the refusal of a
    drop's ``DropResult`` was before)."""


def _what_it_is(result: Any) -> str:
    """``"a BatchResult of 3 cases: ..."``: what was passed, and what to do instead."""
    name = type(result).__name__
    if name in ("BatchResult", "DropBatchResult"):  # a batch keeps no history
        drop = name == "DropBatchResult"
        return (
            f"a {name} of {len(result)} cases (a batch keeps no history and no dent): simulate "
            f"one case with history to plot it, impactlab.{'simulate_drop' if drop else 'simulate'}"
            f"(body, flat, law={result.law!r}, friction={result.friction!r}, mu=batch.mu[i], "
            "angle=batch.angle[i], velocity=(batch.vx[i], batch.vy[i]), spin=batch.spin[i])"
            + ("; of its DropResult plot_dent draws the dent" if drop else "")
        )
    if name == "InversionResult":
        return (
            "an InversionResult (T and F inverted from a measured dent: no history to draw; "
            "the measured dent's map: "
            "impactlab.experiment.plot_dent(measure_dent(read_scan(path))))"
        )
    if name == "DropResult":
        return (
            "a DropResult: plot_dent(result) draws its dent; its forces per end are columns "
            "of result.history (t, normal_force_0, penetration_0, ...)"
        )
    return f"a {name}"


def _impact(result: Any, what: str) -> ImpactResult:
    """``result`` if it is an ImpactResult; else a one-line :class:`NotPlottableError` naming
    what it is and what to do instead (a drop's ``DropResult`` has its contacts' forces per
    end, not one contact's; a batch has no history)."""
    if not isinstance(result, ImpactResult):
        raise NotPlottableError(
            f"{what} takes an ImpactResult (simulate of a Rod or Sphere), got {_what_it_is(result)}"
        )
    return result


def _history(result: ImpactResult) -> History:
    if result.history is None:
        raise ValueError("plots need the history: run simulate(..., history=True)")
    return result.history


def _axes(ax: Any) -> tuple[Any, Any]:
    if ax is not None:
        return ax.figure, ax
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.0, 4.0), layout="constrained")
    plt.close(fig)  # not kept by pyplot: a notebook shows the returned figure once
    return fig, ax


def _title(result: ImpactResult) -> str:
    return f"{result.law}, {result.friction} (mu = {result.mu:g}), {result.regime}"


def plot_force_time(result: ImpactResult, ax: Any = None) -> Any:
    """Normal and tangential contact force [N] against time [ms]."""
    h = _history(_impact(result, "plot_force_time"))
    fig, ax = _axes(ax)
    t = h.t * 1e3
    ax.plot(t, h.normal_force, label="normal force $F_n$")
    ax.plot(t, h.tangential_force, label="tangential force $F_t$")
    ax.axvline(result.t_max * 1e3, color="0.6", lw=0.8, ls=":", label="max penetration")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("force [N]")
    ax.set_title(_title(result))
    ax.legend()
    return fig


def plot_force_penetration(result: ImpactResult, ax: Any = None) -> Any:
    """Normal force [N] against penetration [um], loading and unloading branches marked."""
    h = _history(_impact(result, "plot_force_penetration"))
    fig, ax = _axes(ax)
    d = h.penetration * 1e6
    load = h.phase == 0.0
    ax.plot(d[load], h.normal_force[load], "-", label="loading curve")
    ax.plot(d[~load], h.normal_force[~load], "-", label="unloading / reloading (Hertzian)")
    ax.axvline(
        result.delta_p * 1e6,
        color="0.6",
        lw=0.8,
        ls=":",
        label=f"residual depth {result.delta_p * 1e6:.3g} um",
    )
    ax.set_xlabel("penetration $\\delta$ [um]")
    ax.set_ylabel("normal force $F_n$ [N]")
    ax.set_title(_title(result))
    ax.legend()
    return fig


def _flattened(result: ImpactResult) -> bool:
    """True where the impacting body yields first and left a permanent interference
    (``body_yields_first``, delta_p > 0): the body's flattening, no dent in the flat."""
    return bool(result.delta_p > 0.0 and result.body_yields_first)


def plot_contact_path(result: ImpactResult, ax: Any = None, *, dent: bool = True) -> Any:
    """Contact point path on the flat: position along x [um] against penetration [um], with the
    centre-line profile of the predicted dent (``dent``; left out by itself where the impacting
    body yields first, ``body_yields_first``: the flat has no dent, the legend says so)."""
    h = _history(_impact(result, "plot_contact_path"))
    fig, ax = _axes(ax)
    ax.plot(h.contact_x * 1e6, -h.penetration * 1e6, "-", label="tip bottom (contact point)")
    stick = h.stick > 0.5
    if np.any(stick):
        ax.plot(
            h.contact_x[stick] * 1e6,
            -h.penetration[stick] * 1e6,
            ".",
            ms=3,
            label="stick / no gross slip",
        )
    if dent and _flattened(result):
        ax.plot([], [], " ", label="no dent in the flat: the body yields first")
    elif dent:
        dm = result.dent(ny=41)
        x, z = dm.profile()
        ax.plot(x * 1e6, z * 1e6, "k-", lw=1.0, label="predicted dent (y = 0)")
    ax.axhline(0.0, color="0.5", lw=0.6)
    ax.set_xlabel("x along the flat [um]")
    ax.set_ylabel("height [um]")
    ax.set_title(
        f"sliding length {result.sliding_length * 1e6:.3g} um, "
        f"contact travel {result.contact_travel * 1e6:.3g} um"
    )
    ax.legend(fontsize="small")
    return fig


def plot_dent(result: ImpactResult | DropResult, ax: Any = None) -> Any:
    """The predicted dent as a filled contour map [um], of an ImpactResult or a DropResult
    (:class:`NotPlottableError`, a TypeError, for anything else); the title names the caps
    drawn at the contact radius (``DentMap.caps_at_contact_radius``). An impact that leaves no
    permanent dent (an elastic law) gets axes that say so, no map."""
    if not isinstance(result, ImpactResult | DropResult):
        raise NotPlottableError(
            f"plot_dent takes an ImpactResult or a DropResult (simulate or simulate_drop, "
            f"history kept), got {_what_it_is(result)}"
        )
    dm = result.dent()
    fig, ax = _axes(ax)
    if dm.max_depth <= 0.0:
        ax.text(0.5, 0.5, "no permanent dent", ha="center", va="center", transform=ax.transAxes)
        ax.set_axis_off()
        ax.set_title("dent: none (the impact leaves no permanent interference)")
        return fig
    cs = ax.contourf(dm.x * 1e3, dm.y * 1e3, dm.height * 1e6, levels=20, cmap="viridis")
    fig.colorbar(cs, ax=ax, label="height [um]")
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y, across the impact plane [mm]")
    title = f"dent: depth {dm.max_depth * 1e6:.3g} um, length {dm.length * 1e3:.3g} mm"
    bounded = []
    if dm.caps_at_contact_radius:
        bounded.append(
            f"{dm.caps_at_contact_radius} cap(s) at the contact radius: width an upper bound"
        )
    ax.set_title("\n".join([title, *bounded]), **({"fontsize": "medium"} if bounded else {}))
    return fig


def save_figures(
    result: ImpactResult,
    out_dir: str | Path,
    *,
    stem: str = "impact",
    formats: tuple[str, ...] = ("png", "pdf"),
) -> list[Path]:
    """Save the force-time, force-penetration, contact-path and dent figures; returns paths.
    :class:`NotPlottableError` (a TypeError and a ValueError) for a result other than an
    ImpactResult (a drop: ``plot_dent`` draws its dent), before anything is written. No dent
    figure where the impacting body yields first (``body_yields_first``: no dent in the flat)
    or the impact leaves no permanent dent (``delta_p`` = 0: an elastic law)."""
    _impact(result, "save_figures")
    plt = pyplot()
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, fn in (
        ("force_time", plot_force_time),
        ("force_penetration", plot_force_penetration),
        ("contact_path", plot_contact_path),
        ("dent", plot_dent),
    ):
        if name == "dent" and (_flattened(result) or not result.delta_p > 0.0):
            continue
        fig = fn(result)
        for ext in formats:
            p = out / f"{stem}_{name}.{ext}"
            fig.savefig(p, dpi=150)
            paths.append(p)
        plt.close(fig)
    return paths
