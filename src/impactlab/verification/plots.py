"""The figures of the verification page (PNG): Thornton's e(V/V_y), the critical friction and
the Hertz convergence. Plotting goes through ``impactlab._mpl.pyplot`` (the package's one
matplotlib policy)."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._mpl import pyplot
from impactlab.analytic import critical_friction
from impactlab.bodies import PAPER_ROD
from impactlab.contact import thornton_restitution
from impactlab.dynamics import simulate_batch
from impactlab.verification.rigid import regime_codes
from impactlab.verification.table import VerificationTable

__all__ = ["plot_critical_friction", "plot_hertz_convergence", "plot_thornton"]


def _engine_points(plot: Any, x: Any, y: Any, marker: str, label: str) -> None:
    """The engine's results as red markers (``plot``: an Axes plotting method)."""
    plot(x, y, marker, color="#c44e52", ms=5, label=label)


def _save(plt: Any, fig: Any, path: str | Path) -> Path:
    """Write ``fig`` to ``path`` (110 dpi), close it, return the path."""
    p = Path(path)
    fig.savefig(p, dpi=110)
    plt.close(fig)
    return p


def plot_thornton(table: VerificationTable, path: str | Path) -> Path:
    """e(V/V_y): Thornton's closed form (line) and the engine (dots)."""
    plt = pyplot()
    x = np.logspace(-0.5, 3.0, 400)
    fig, ax = plt.subplots(figsize=(6.0, 4.0), constrained_layout=True)
    ax.semilogx(
        x,
        np.asarray(thornton_restitution(x)),
        color="0.3",
        lw=1.5,
        label="Thornton (1997), closed form",
    )
    _engine_points(ax.semilogx, table.extra["ratios"], table.extra["e"], "o", "impactlab engine")
    ax.set_xlabel("V / V_y")
    ax.set_ylabel("coefficient of restitution e")
    ax.set_ylim(0.0, 1.05)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    return _save(plt, fig, path)


def plot_critical_friction(
    table: VerificationTable, path: str | Path, *, grid: tuple[int, int] = (44, 37)
) -> Path:
    """mu_c(theta) (line), the engine's bisection points, and the engine's regimes on a grid."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.0, 4.2), constrained_layout=True)
    if grid[0] > 0 and grid[1] > 0:
        th = np.radians(np.linspace(2.0, 88.0, grid[0]))
        mu = np.linspace(0.0, 0.9, grid[1])
        T, M = np.meshgrid(th, mu)
        b = simulate_batch(
            PAPER_ROD,
            law="hertz",
            friction="coulomb",
            mu=M.ravel(),
            angle=T.ravel(),
            vy=-1.0,
            gravity=False,
            constant_angle=True,
        )
        codes = regime_codes()
        reg = np.asarray(b["regime"])
        for name, color in (("slip", "#4c72b0"), ("stick", "#dd8452")):
            sel = reg == codes[name]
            ax.scatter(
                np.degrees(T.ravel()[sel]),
                M.ravel()[sel],
                s=6,
                color=color,
                alpha=0.5,
                label=f"engine: {name}",
            )
    th_line = np.radians(np.linspace(0.0, 90.0, 361))
    ax.plot(
        np.degrees(th_line),
        np.asarray(critical_friction(th_line, PAPER_ROD)),
        color="k",
        lw=1.5,
        label="mu_c = a b / (k^2 + b^2)",
    )
    _engine_points(
        ax.plot,
        np.degrees(table.extra["angles"]),
        table.extra["engine"],
        "D",
        "engine boundary (bisection)",
    )
    ax.set_xlabel("angle of the rod to the flat [deg]")
    ax.set_ylabel("friction coefficient mu")
    ax.set_xlim(0, 90)
    ax.set_ylim(0, 0.9)
    ax.legend(loc="upper right", fontsize=8)
    return _save(plt, fig, path)


def plot_hertz_convergence(data: Mapping[str, np.ndarray], path: str | Path) -> Path:
    """Relative errors of the Hertz closed forms against the engine's rtol."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.0, 4.0), constrained_layout=True)
    floor = 1e-16
    for key, label in (
        ("T", "duration T"),
        ("F", "peak force F_max"),
        ("delta", "peak penetration delta_max"),
    ):
        ax.loglog(data["rtol"], np.maximum(data[key], floor), "o-", label=label)
    ax.loglog(data["rtol"], data["rtol"], "k--", lw=1, label="error = rtol")
    ax.set_xlabel("engine tolerance rtol")
    ax.set_ylabel("relative error vs closed form")
    ax.invert_xaxis()
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return _save(plt, fig, path)
