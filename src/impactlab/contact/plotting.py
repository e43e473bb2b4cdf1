"""Plots of the contact laws: loading and unloading curves of every registered law."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from impactlab._validation import check_positive
from impactlab.contact._common import jg_critical
from impactlab.contact.base import ContactModel
from impactlab.contact.registry import get_law, law_names
from impactlab.materials import ContactPair

_SWITCHED = ("ghaednia", "jackson-green", "kogut-komvopoulos")


def plot_laws(
    pair: ContactPair,
    radius: float,
    delta_max: float,
    *,
    laws: Sequence[str] | None = None,
    unload_fractions: Sequence[float] = (1.0 / 3.0, 2.0 / 3.0, 1.0),
    params: Mapping[str, Mapping[str, float]] | None = None,
    n_points: int = 400,
) -> Figure:
    """Figure with the loading curves F(delta) of ``laws`` (default: all registered) and their
    unloading branches from delta_m = ``unload_fractions`` * ``delta_max``.

    Left: the whole range up to ``delta_max`` [m]. Right: the yield region, force over the Hertz
    force against delta/delta_c (Jackson-Green delta_c), with each law's switch point (dot) and,
    dotted, the published switches of the laws that have one (their force jumps).
    ``params`` maps a law name to the parameters for its ``build``.
    """
    R = check_positive("radius", radius, "m")
    dmax = check_positive("delta_max", delta_max, "m")
    names = list(law_names() if laws is None else laws)
    for name in names:
        get_law(name)  # ValueError for unknown names
    fracs = [float(f) for f in unload_fractions]
    if any(not 0.0 < f <= 1.0 for f in fracs):
        raise ValueError(f"unload_fractions must lie in (0, 1], got {list(unload_fractions)!r}")
    params = params or {}
    models: dict[str, ContactModel] = {
        name: get_law(name).build(pair, R, **params.get(name, {})) for name in names
    }
    dc, _ = jg_critical(pair.E_star, R, pair.yield_strength, pair.nu)

    fig = Figure(figsize=(12.0, 5.2), layout="constrained")
    ax_all, ax_y = fig.subplots(1, 2)
    colors = {name: f"C{i}" for i, name in enumerate(law_names())}
    for name, model in models.items():
        c = colors.get(name, "k")
        top = min(dmax, model.max_interference)
        d = np.linspace(0.0, top, n_points)
        ax_all.plot(d * 1e6, model.force(d) * 1e-3, color=c, lw=1.8, label=name)
        for f in fracs:
            dm = f * dmax
            if dm > model.max_interference:
                continue
            br = model.unload(dm)
            du = np.linspace(br.delta_r, dm, max(n_points // 4, 20))
            ax_all.plot(du * 1e6, br.force(du) * 1e-3, color=c, lw=1.0, ls="--")
        # yield region: force relative to Hertz
        dz = np.geomspace(0.05 * dc, min(50.0 * dc, model.max_interference), 4 * n_points)
        hz = 4.0 / 3.0 * pair.E_star * np.sqrt(R) * dz**1.5
        ax_y.semilogx(dz / dc, model.force(dz) / hz, color=c, lw=1.6, label=name)
        dsw = model.switch_interference
        if np.isfinite(dsw) and dsw < 50.0 * dc:
            hsw = 4.0 / 3.0 * pair.E_star * np.sqrt(R) * dsw**1.5
            ax_y.plot([dsw / dc], [float(model.force(dsw)) / hsw], "o", color=c, ms=5)
        if name in _SWITCHED:
            pub = get_law(name).build(pair, R, **{**params.get(name, {}), "published_switch": 1})
            ax_y.semilogx(dz / dc, pub.force(dz) / hz, color=c, lw=1.2, ls=":")
    ax_all.set_xlabel(r"interference $\delta$ [$\mu$m]")
    ax_all.set_ylabel("normal force F [kN]")
    ax_all.set_title(f"loading (solid) and unloading (dashed), R = {R * 1e3:g} mm")
    ax_all.set_xlim(0.0, dmax * 1e6)
    ax_all.set_ylim(bottom=0.0)
    ax_all.legend(loc="upper left", fontsize=9)
    ax_all.grid(alpha=0.3)
    ax_y.set_xlabel(
        r"$\delta/\delta_c$ (Jackson-Green $\delta_c$ = " + f"{dc * 1e6:.3g}" + r" $\mu$m)"
    )
    ax_y.set_ylabel(r"$F / F_{Hertz}$")
    ax_y.set_title("yield region: switch points (dots), published switches (dotted)")
    ax_y.grid(alpha=0.3, which="both")
    ax_y.legend(loc="lower left", fontsize=9)
    info: Any = f"E* = {pair.E_star / 1e9:.4g} GPa, S_y = {pair.yield_strength / 1e6:.4g} MPa"
    fig.suptitle(f"Contact laws: {pair.body.name} on {pair.flat.name}\n{info}", fontsize=10)
    return fig
