"""The reproduction's figures: Fig. 5 (alpha vs angle), Fig. 4 (the simulated dent), force-time
and force-penetration per angle, and the inertia sensitivity of the experimental T. Each function
writes one PNG and returns its path.
"""

from __future__ import annotations

import io
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

import impactlab.analytic as an
from impactlab._files import write_bytes_atomic
from impactlab._mpl import pyplot
from impactlab.paper import data as D
from impactlab.paper.analytic_rows import invert_case, rod_with_inertia_ratio
from impactlab.paper.quantities import Simulations, extrapolation_label


def figure_alpha(path: Path, mus: Iterable[float] = (0.0, 0.1, 0.13, 0.2, 0.3, 0.5)) -> Path:
    """Fig. 5: alpha vs angle for several mu (corrected Eq. 13), the sign change at mu = mu_c
    marked, the sticking part dashed, and the three experiments."""
    plt = pyplot()
    th = np.radians(np.linspace(0.5, 89.5, 400))
    mu_c = an.critical_friction(th)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for mu in mus:
        al = an.alpha(th, mu)
        slide = mu < mu_c
        stick = ~slide
        stick_ext = stick.copy()  # one more point each side closes the gaps at mu = mu_c
        stick_ext[1:] |= stick[:-1]
        stick_ext[:-1] |= stick[1:]
        (ln,) = ax.plot(np.degrees(th), np.where(slide, al, np.nan), label=f"mu = {mu:g}")
        ax.plot(np.degrees(th), np.where(stick_ext, al, np.nan), ls="--", color=ln.get_color())
        # angles where mu = mu_c (alpha = 0); mu_c(theta) rises from (L/2) R / (k^2 + R^2) at
        # theta = 0 to its maximum near 24 deg and falls to 0 at 90 deg: up to two crossings
        idx = np.flatnonzero(np.diff(np.sign(al)) != 0)
        for i in idx:
            t0 = np.degrees(th[i] - al[i] * (th[i + 1] - th[i]) / (al[i + 1] - al[i]))
            ax.plot([t0], [0.0], "o", color=ln.get_color(), mfc="white")
    for ang, x in D.EXPERIMENTS.items():
        ax.plot([ang], [an.alpha(x.angle, x.mu)], "k*", ms=10)
        ax.annotate(
            f"exp. {ang} deg (mu={x.mu:g})",
            (ang, an.alpha(x.angle, x.mu)),
            textcoords="offset points",
            xytext=(5, -12),
            fontsize=8,
        )
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("impact angle theta [deg]")
    ax.set_ylabel("alpha = K_x / K_y")
    ax.set_title("Fig. 5 (corrected Eq. 13): open circles mu = mu_c; dashed: sticking")
    ax.legend(fontsize=8)
    ax.set_ylim(-1.2, 1.0)
    return _save(plt, fig, path)


def figure_inertia(path: Path, table: pd.DataFrame) -> Path:
    """The experimental T relative to the published one vs I_C / (m L^2)."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6, 4))
    q = np.linspace(0.04, 0.16, 61)
    for ang, x in D.EXPERIMENTS.items():
        pub = D.published_row(ang, "experiment")
        T = [invert_case(x, rod=rod_with_inertia_ratio(v)).duration for v in q]
        ref = pub.T if pub and pub.T else T[np.argmin(abs(q - 1 / 12))]
        ax.plot(
            q,
            np.array(T) / ref,
            label=f"{ang} deg" + (" (/ published T)" if pub else " (/ T at 1/12)"),
        )
    ax.axvline(1 / 12, color="0.5", ls=":", label="slender rod 1/12")
    ax.axhspan(0.95, 1.05, color="0.9")
    ax.set_xlabel("I_C / (m L^2)")
    ax.set_ylabel("T / reference")
    ax.legend(fontsize=8)
    ax.set_title("Experimental T vs the rod's moment of inertia")
    return _save(plt, fig, path)


def figure_forces(
    path: Path, sims: Simulations, angle: int, friction: str = "impulse_ratio"
) -> Path:
    """Force-time and force-penetration for the three laws at one angle; a curve whose impact
    left its law's verified range is marked in the legend (``extrapolation_label``), which
    lies below each panel, clear of the curves."""
    plt = pyplot()
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 5))
    for law in D.PAPER_LAWS:
        res = sims.get((angle, law, friction))
        if res is None or res.history is None:
            continue
        h = res.history
        t, pen, fn = h.t, h.penetration, h.normal_force
        a1.plot(t * 1e3, fn, label=law + extrapolation_label(res))
        a2.plot(pen * 1e6, fn, label=law + extrapolation_label(res))
    a1.set_xlabel("t [ms]")
    a1.set_ylabel("normal force [N]")
    a2.set_xlabel("penetration [um]")
    a2.set_ylabel("normal force [N]")
    for ax in (a1, a2):  # below the axes: inside, it hid the peaks of the curves
        ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.16), frameon=False)
    fig.suptitle(
        f"{angle} deg, v_i = {D.EXPERIMENTS[angle].v_i} m/s, "
        f"mu = {D.EXPERIMENTS[angle].mu}, friction: {friction}"
    )
    return _save(plt, fig, path)


def figure_dent(path: Path, res: Any) -> Path:
    """Fig. 4: the simulated dent (20 deg, 1.41 m/s, Ghaednia) from ``result.dent()``; the
    title says, on a line of its own (the figure is narrow beside its colorbar), when the
    impact left the law's verified range (``extrapolation_label``)."""
    plt = pyplot()
    dent = res.dent()
    x, y, z = np.asarray(dent.x), np.asarray(dent.y), np.asarray(dent.height)  # z[y, x]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ext = [x.min() * 1e6, x.max() * 1e6, y.min() * 1e6, y.max() * 1e6]
    im = ax.imshow(z * 1e6, extent=ext, origin="lower", aspect="equal", cmap="viridis")
    fig.colorbar(im, ax=ax, label="height [um]")
    ax.set_xlabel("x [um]")
    ax.set_ylabel("y, across the impact plane [um]")
    mark = extrapolation_label(res)
    ax.set_title(
        "Fig. 4: simulated dent, 20 deg, 1.41 m/s, Ghaednia et al."
        + (f"\nbeyond the law's verified range{mark}" if mark else "")
    )
    return _save(plt, fig, path)


def _save(plt: Any, fig: Any, path: Path) -> Path:
    """Write ``fig`` to ``path`` as PNG, whole or not at all, and close it."""
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110)
    plt.close(fig)
    write_bytes_atomic(path, buf.getvalue())
    return path
