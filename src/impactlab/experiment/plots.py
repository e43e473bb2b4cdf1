"""Figures of an analysed experiment (matplotlib through ``impactlab._mpl.pyplot``, the package's
one backend policy; the figures are returned open: close them with ``pyplot.close(fig)``).

* :func:`plot_dent`: the levelled height map with the dent's outline, deepest point and sliding
  direction, the centre-line profile along the sliding axis and the cross profile at the deepest
  point (like the paper's Figs. 6-8).
* :func:`plot_kinematics`: the centre of mass's height and horizontal position and the rod angle
  against time, with the two ballistic fits extrapolated to the impact instant.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from impactlab._mpl import pyplot
from impactlab.experiment.checks import check_instance
from impactlab.experiment.kinematics import ImpactKinematics
from impactlab.experiment.profilometry import DentMetrics

if TYPE_CHECKING:  # pragma: no cover - annotations only
    from matplotlib.figure import Figure

__all__ = ["plot_dent", "plot_kinematics"]


def _figure(width: float, height: float) -> Figure:
    fig: Figure = pyplot().figure(figsize=(width, height), layout="constrained")
    return fig


def plot_dent(
    dent: DentMetrics, path: str | Path | None = None, *, title: str = "", dpi: int = 130
) -> Figure:
    """Height map (colour, um) with outline, deepest point and sliding direction; centre-line and
    cross profiles of ``dent`` (a :class:`DentMetrics`: TypeError naming ``dent`` otherwise).
    Saves a PNG to ``path`` when given; returns the figure."""
    check_instance(dent, DentMetrics, "dent", "measure one with measure_dent(read_scan(path))")
    fig = _figure(12.0, 4.6)
    gs = fig.add_gridspec(2, 2, width_ratios=[1.25, 1.0])
    ax_map = fig.add_subplot(gs[:, 0])
    ax_pr = fig.add_subplot(gs[0, 1])
    ax_cr = fig.add_subplot(gs[1, 1])
    hm = dent.levelled
    um, mm = 1e6, 1e3
    if hm is not None:
        ny, nx = hm.shape
        ext = (
            -0.5 * hm.dx * mm,
            (nx - 0.5) * hm.dx * mm,
            -0.5 * hm.dy * mm,
            (ny - 0.5) * hm.dy * mm,
        )
        zz = np.asarray(hm.z) * um
        lo = -dent.delta_p.value * um
        hi = max(dent.pileup * um, 0.15 * dent.delta_p.value * um)
        im = ax_map.imshow(
            zz,
            origin="lower",
            extent=ext,
            cmap="viridis",
            vmin=lo,
            vmax=hi,
            interpolation="nearest",
        )
        fig.colorbar(im, ax=ax_map, label="height [µm]", shrink=0.85)
    ol = dent.outline
    ax_map.plot(ol[:, 0] * mm, ol[:, 1] * mm, color="w", lw=1.0, label="outline")
    xd, yd = dent.deepest
    ax_map.plot([xd * mm], [yd * mm], "rx", ms=8, mew=2, label="deepest point")
    ax = np.asarray(dent.axis)
    proj = (ol - np.asarray(dent.deepest)) @ ax
    p0 = np.asarray(dent.deepest) + proj.min() * ax
    p1 = np.asarray(dent.deepest) + proj.max() * ax
    ax_map.annotate(
        "",
        xy=(p1[0] * mm, p1[1] * mm),
        xytext=(p0[0] * mm, p0[1] * mm),
        arrowprops={"arrowstyle": "->", "color": "r", "lw": 1.5},
    )
    ax_map.set_xlabel("x [mm]")
    ax_map.set_ylabel("y [mm]")
    amb = " (ambiguous)" if dent.direction_ambiguous else ""
    ax_map.set_title(
        title
        or f"δp = {dent.delta_p.value * um:.3g} µm, "
        f"Ls = {dent.sliding_length.value * um:.4g} µm; "
        f"sliding {math.degrees(dent.sliding_angle):.0f}°{amb}",
        fontsize=10,
    )
    ax_map.legend(loc="upper right", fontsize=8, framealpha=0.6)
    # profiles
    s, z = dent.profile
    ax_pr.plot((s - proj.min()) * mm, z * um, color="C0")
    ax_pr.axhline(0.0, color="0.6", lw=0.8)
    ax_pr.axhline(-dent.edge_threshold * um, color="0.6", lw=0.8, ls=":")
    ax_pr.plot([(-proj.min()) * mm], [-dent.delta_p.value * um], "rx")
    ax_pr.set_xlabel("distance along the sliding direction [mm]")
    ax_pr.set_ylabel("height [µm]")
    ax_pr.set_title(f"centre line: length {dent.length.value * mm:.3f} mm", fontsize=9)
    sc, zc = dent.cross_profile
    ax_cr.plot(sc * mm, zc * um, color="C1")
    ax_cr.axhline(0.0, color="0.6", lw=0.8)
    w = dent.width.value
    ax_cr.axvline(-0.5 * w * mm, color="0.6", lw=0.8, ls="--")
    ax_cr.axvline(0.5 * w * mm, color="0.6", lw=0.8, ls="--")
    ax_cr.set_xlabel("distance across, at the deepest point [mm]")
    ax_cr.set_ylabel("height [µm]")
    ax_cr.set_title(f"cross section: width {w * mm:.3f} mm", fontsize=9)
    if path is not None:
        fig.savefig(str(path), dpi=dpi)
    return fig


def plot_kinematics(
    kin: ImpactKinematics, path: str | Path | None = None, *, dpi: int = 130
) -> Figure:
    """Centre-of-mass height, horizontal position and rod angle against time with the ballistic
    fits before and after the impact, of ``kin`` (an :class:`ImpactKinematics`: TypeError naming
    ``kin`` otherwise). Saves a PNG to ``path`` when given; returns the figure."""
    check_instance(kin, ImpactKinematics, "kin", "measure one with measure_impact(tracks, rod)")
    fig = _figure(11.0, 3.8)
    axs = fig.subplots(1, 3)
    t_all, d_all = kin.series()
    t0 = kin.t_impact.value
    g = kin.gravity
    labels = ("horizontal x of C [mm]", "height y of C [mm]", "", "rod angle [deg]")
    for ax, c in zip(axs, (1, 0, 3), strict=True):
        scale = 180.0 / math.pi if c == 3 else 1e3
        ax.plot((t_all - t0) * 1e3, d_all[:, c] * scale, ".", color="0.7", ms=3, label="all frames")
        for seg, col, name in ((kin.pre, "C0", "before"), (kin.post, "C3", "after")):
            tt = kin.poses.time[seg.frames] if kin.poses is not None else seg.tau + kin.t_ref
            ax.plot(
                (tt - t0) * 1e3,
                seg.data[:, c] * scale,
                ".",
                color=col,
                ms=4,
                label=f"fit data {name}",
            )
            tau = np.linspace(
                min(seg.tau.min(), t0 - kin.t_ref), max(seg.tau.max(), t0 - kin.t_ref), 100
            )
            fit = seg.coef[0, c] + seg.coef[1, c] * tau
            if c == 1:
                fit = fit - 0.5 * g * tau * tau
            ax.plot((tau + kin.t_ref - t0) * 1e3, fit * scale, "-", color=col, lw=1)
        ax.axvline(0.0, color="k", lw=0.8, ls=":")
        ax.set_xlabel("time from impact [ms]")
        ax.set_ylabel(labels[c])
    axs[0].legend(fontsize=7)
    fig.suptitle(
        f"e = {kin.e.value:.3f} ± {kin.e.sigma:.2g}, μ = {kin.mu.value:.3f} ± "
        f"{kin.mu.sigma:.2g}, θ = {math.degrees(kin.angle_in.value):.2f}°, "
        f"v_i = {kin.v_i.value:.3f} m/s",
        fontsize=10,
    )
    if path is not None:
        fig.savefig(str(path), dpi=dpi)
    return fig
