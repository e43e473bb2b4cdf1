"""The figure of "Can physics explain the experiment?": the contact-force history and the tip
trajectory of a flexible drop over its whole contact sequence. Writes one PNG, returns its path.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from impactlab._mpl import pyplot
from impactlab.paper.figures import _save
from impactlab.paper.quantities import extrapolation_label

__all__ = ["figure_drop"]


def figure_drop(path: Path, result: Any, title: str = "") -> Path:
    """Three panels of a DropResult with history: the normal and tangential force on the tip
    against time [N, ms], the tip's height above the undeformed flat against time [um, ms] and
    the tip's trajectory (height against x) [um]. The title (default: the contacts and e) ends
    with the mark of a drop that left its law's verified range (``extrapolation_label``)."""
    h = result.history
    if h is None:
        raise ValueError("figure_drop needs a DropResult with history (history=True)")
    plt = pyplot()
    fig, (a1, a2, a3) = plt.subplots(3, 1, figsize=(7, 8.5))
    t_ms = h.t * 1e3
    a1.plot(t_ms, h.normal_force, label="normal F_n")
    a1.plot(t_ms, h.tangential_force, label="tangential F_t")
    for c in result.contacts:
        a1.axvspan(c.start * 1e3, (c.start + c.duration) * 1e3, color="0.9", zorder=0)
    a1.set_xlabel("time from the first touch [ms]")
    a1.set_ylabel("force on the tip [N]")
    a1.legend(fontsize=8)
    a2.plot(t_ms, h.tip_height * 1e6)
    a2.axhline(0.0, color="0.5", lw=0.8)
    a2.set_xlabel("time from the first touch [ms]")
    a2.set_ylabel("tip height [um]")
    x0 = h.tip_x[0]
    a3.plot((h.tip_x - x0) * 1e6, h.tip_height * 1e6)
    a3.axhline(0.0, color="0.5", lw=0.8)
    a3.set_xlabel("tip x from the first touch [um]")
    a3.set_ylabel("tip height [um]")
    a1.set_title(
        (title or f"{result.n_contacts} contacts, e = {result.e:.3f}") + extrapolation_label(result)
    )
    return _save(plt, fig, path)
