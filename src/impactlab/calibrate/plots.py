"""Figures of a calibration: the corner plot of each model's posterior (``corner``) and the
posterior predictive check, predicted against measured with 90 % bands (the band with the noise
drawn within the quantity's possible range: ``quantities.MEASURABLE``)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab._display import display_unit
from impactlab._mpl import pyplot
from impactlab.calibrate.quantities import MEASURABLE
from impactlab.calibrate.result import ModelPosterior

__all__ = ["corner_figure", "in_range", "interval_title", "ppc_figure"]


def corner_figure(post: ModelPosterior) -> Any:
    """The corner plot of ``post`` in display units, the best fit marked."""
    import corner

    scales = [display_unit(p.name, p.unit) for p in post.params]
    x = np.column_stack([post.samples[:, j] * s.scale for j, s in enumerate(scales)])
    labels = [
        f"{p.name} [{s.unit}]" if s.unit not in ("", "1") else p.name
        for p, s in zip(post.params, scales, strict=True)
    ]
    best = [post.best[p.name] * s.scale for p, s in zip(post.params, scales, strict=True)]
    plt = pyplot()  # the one matplotlib backend policy
    if x.shape[1] == 1:  # corner's marks fail on a single axis: the histogram by hand
        fig, ax = plt.subplots(figsize=(4, 3))
        ax.hist(x[:, 0], bins=40, histtype="step", color="k")
        for q in np.quantile(x[:, 0], [0.05, 0.5, 0.95]):
            ax.axvline(q, color="k", ls="--", lw=0.8)
        ax.axvline(best[0], color="#4682b4")
        ax.set_xlabel(labels[0])
        ax.set_title(post.model)
        return fig
    fig = corner.corner(  # quiet: corner's "too few points" goes to the root logger
        x, labels=labels, truths=best, quantiles=[0.05, 0.5, 0.95], quiet=True
    )
    axes = np.asarray(fig.axes).reshape(x.shape[1], x.shape[1])
    for j, label in enumerate(labels):  # corner's titles have one format for all (".2f")
        axes[j, j].set_title(f"{label} = {interval_title(x[:, j])}")
    fig.suptitle(post.model, y=1.02)
    return fig


def interval_title(x: np.ndarray) -> str:
    """The median of the draws ``x`` with the distances to the ends of its 90 % interval, as
    mathtext (``$0.2004_{-0.0043}^{+0.0047}$``), to the decimal that gives the shorter distance
    two significant digits (the same number of decimals for all three; 4 significant digits
    when the draws do not spread)."""
    lo, mid, hi = np.quantile(x, [0.05, 0.5, 0.95])
    minus, plus = mid - lo, hi - mid
    widths = [d for d in (minus, plus) if 0 < d < math.inf]
    spec = f".{min(max(1 - math.floor(math.log10(min(widths))), 0), 12)}f" if widths else ".4g"
    f = f"{{:{spec}}}".format
    return rf"${f(mid)}_{{-{f(minus)}}}^{{+{f(plus)}}}$"


def in_range(
    quantity: str, lo: np.ndarray, hi: np.ndarray, model_lo: np.ndarray, model_hi: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The band [``lo``, ``hi``] of a new measurement of ``quantity`` (SI) as a measurement reads
    it: within the quantity's possible range (``MEASURABLE``: a length, a duration, a force or e
    at least 0, e at most 1, e_t in [-1, 1]), so that the Gaussian noise does not draw a length
    below 0. The
    model's own band [``model_lo``, ``model_hi``] is never cut (a model's e above 1: gravity's
    impulse removed, ``MEASURABLE["e"]``)."""
    m = MEASURABLE.get(quantity)
    if m is None:
        return lo, hi
    low = -math.inf if m.low is None else m.low
    high = math.inf if m.high is None else m.high
    with np.errstate(invalid="ignore"):  # NaN: a value not predicted stays NaN
        lo = np.where(lo < low, np.fmin(low, model_lo), lo)
        hi = np.where(hi > high, np.fmax(high, model_hi), hi)
    return lo, hi


def ppc_figure(posteriors: dict[str, ModelPosterior]) -> Any:
    """Per measured quantity: the measured values (+- sigma) by drop and each model's
    predicted median with its 90 % band (model only) and the band with the measurement
    noise, within the quantity's possible range (:func:`in_range`)."""
    plt = pyplot()
    first = next(iter(posteriors.values()))
    quantities = list(dict.fromkeys(r["quantity"] for r in first.ppc))
    fig, axes = plt.subplots(len(quantities), 1, figsize=(7, 2.6 * len(quantities)), squeeze=False)
    n_models = len(posteriors)
    for ax, q in zip(axes[:, 0], quantities, strict=True):
        rows = [r for r in first.ppc if r["quantity"] == q]
        d = display_unit(q, rows[0]["unit"])
        xs = np.arange(len(rows))
        y = np.array([r["observed"] for r in rows]) * d.scale
        s = np.array([r["sigma"] for r in rows]) * d.scale
        ax.errorbar(xs, y, yerr=s, fmt="ko", label="measured", zorder=5)
        for i, (name, post) in enumerate(posteriors.items()):
            mine = [r for r in post.ppc if r["quantity"] == q]
            off = xs + 0.15 * (i + 1 - (n_models + 1) / 2)
            med, lo, hi, plo, phi = (
                np.array([r[k] for r in mine], dtype=float)
                for k in ("median", "q05", "q95", "pred_q05", "pred_q95")
            )
            plo, phi = in_range(q, plo, phi, lo, hi)
            med, lo, hi, plo, phi = (x * d.scale for x in (med, lo, hi, plo, phi))
            (line,) = ax.plot(off, med, "s", label=name)
            ax.vlines(off, plo, phi, color=line.get_color(), alpha=0.35, lw=6)
            ax.vlines(off, lo, hi, color=line.get_color(), lw=2)
        ax.set_xticks(xs, [r["drop"] for r in rows])
        ax.set_ylabel(f"{q} [{d.unit}]" if d.unit not in ("", "1") else q)
    axes[0, 0].legend(fontsize=8)
    axes[0, 0].set_title("measured and predicted (model 90 % band; wide: with the noise, in range)")
    fig.tight_layout()
    return fig
