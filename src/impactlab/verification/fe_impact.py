"""The dynamic FE impact beside the quasi-static FE 1-DOF impact and impactlab's contact laws.

Reads the shipped tables (``impactlab.fe.impact_reference``: dynamic FE and the 1-DOF impact
on the quasi-static FE curves of the same bodies, without running CalculiX) and adds one
column per contact law, simulated by impactlab's engine for the same sphere (radius, mass,
speed; frictionless, no gravity). A new law becomes a column with one call:
``add_law(comparison, "tabulated")``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from impactlab.bodies import Sphere
from impactlab.dynamics import simulate
from impactlab.fe.impact_reference import IMPACT_CASES, RADIUS, load_impact_table

__all__ = ["ImpactComparison", "add_law", "compare_impacts", "comparison_markdown", "law_row"]

#: The quantities compared, with their labels and units.
QUANTITIES: tuple[tuple[str, str], ...] = (
    ("restitution", "e"),
    ("residual_depth", "delta_p [um]"),
    ("max_interference", "delta_max [um]"),
    ("max_force", "F_max [N]"),
    ("contact_duration", "T [us]"),
)
_SCALE = {"residual_depth": 1e6, "max_interference": 1e6, "contact_duration": 1e6}
#: Fixed decimals of the quantities near a bound (e near 1, a residual depth near 0), whose
#: deviation 4 significant digits would round away (1.0003 shown as 1); the others: 4 digits.
_DECIMALS = {"restitution": 4, "residual_depth": 4}

#: The elastic-plastic laws.
PLASTIC_LAWS: tuple[str, ...] = (
    "jackson-green",
    "ghaednia",
    "kogut-komvopoulos",
    "brake",
    "thornton",
)
#: The laws compared by default: Hertz for the elastic case, the elastic-plastic laws for the
#: elastic-plastic flat.
DEFAULT_LAWS: dict[str, tuple[str, ...]] = {
    "elastic-ball-on-aisi1010": ("hertz",),
    "paper-ball-on-aisi1010": PLASTIC_LAWS,
    "rod-mass-on-aisi1010": PLASTIC_LAWS,
}


@dataclass
class ImpactComparison:
    """One case's comparison: per speed, a column name -> quantities mapping. The columns
    are "dynamic FE", "quasi-static FE 1-DOF" and one per law added."""

    case: str
    speeds: list[float]
    mass: float
    columns: dict[str, list[dict[str, float]]] = field(default_factory=dict)


def law_row(case: str, law: str, speed: float, mass: float) -> dict[str, float]:
    """e, delta_p, delta_max, F_max and the duration of ``law``'s impact for the case's
    sphere and flat at ``speed`` [m/s] (frictionless, no gravity; SI units)."""
    c = IMPACT_CASES[case]
    body = Sphere(RADIUS, mass=mass, material=c.sphere_material)
    r = simulate(
        body,
        c.flat,
        law=law,
        friction="coulomb",
        mu=0.0,
        velocity=(0.0, -speed),
        gravity=False,
        history=False,
    )
    return {
        "restitution": float(r.e),
        "residual_depth": float(r.delta_p),
        "max_interference": float(r.delta_max),
        "max_force": float(r.max_force),
        "contact_duration": float(r.duration),
    }


def _fe_column(rows: list[dict[str, Any]], key: str) -> list[dict[str, float]]:
    out = []
    for row in rows:
        src = row[key] or {}  # None: not run (the rod-mass case's dynamic FE)
        out.append({q: math.nan if src.get(q) is None else float(src[q]) for q, _ in QUANTITIES})
    return out


def add_law(comparison: ImpactComparison, law: str) -> ImpactComparison:
    """Add the column of a registered contact law (``impactlab.contact.law_names()``)."""
    comparison.columns[law] = [
        law_row(comparison.case, law, v, comparison.mass) for v in comparison.speeds
    ]
    return comparison


def compare_impacts(case: str, laws: tuple[str, ...] | None = None) -> ImpactComparison:
    """The comparison of a shipped case with its default laws (or ``laws``)."""
    table = load_impact_table(case)
    rows = table["rows"]
    comp = ImpactComparison(
        case=case, speeds=[float(r["speed"]) for r in rows], mass=float(rows[0]["mass"])
    )
    comp.columns["dynamic FE"] = _fe_column(rows, "dynamic")
    comp.columns["quasi-static FE 1-DOF"] = _fe_column(rows, "quasi_static")
    for law in DEFAULT_LAWS.get(case, ()) if laws is None else laws:
        add_law(comp, law)
    return comp


def comparison_markdown(comp: ImpactComparison) -> str:
    """The comparison as a Markdown table: one row per speed and column."""
    head = "| v [m/s] | model | " + " | ".join(label for _, label in QUANTITIES) + " |\n"
    head += "| --- | --- |" + " --- |" * len(QUANTITIES) + "\n"
    lines = []
    for i, v in enumerate(comp.speeds):
        for name, col in comp.columns.items():
            vals = []
            for q, _ in QUANTITIES:
                x = col[i][q] * _SCALE.get(q, 1.0)
                places = _DECIMALS.get(q)
                shown = f"{x:.{places}f}" if places is not None else f"{x:.4g}"
                vals.append("n/a" if not math.isfinite(x) else shown)
            lines.append(f"| {v:g} | {name} | " + " | ".join(vals) + " |")
    return head + "\n".join(lines) + "\n"


def plot_force_histories(case: str) -> Any:
    """F(t) of the dynamic FE impact and of the 1-DOF impact on the quasi-static FE curves,
    one panel per speed (t from the first touch) [us, N]; returns the matplotlib figure."""
    from impactlab._mpl import pyplot

    plt = pyplot()
    table = load_impact_table(case)
    rows = table["rows"]
    fig, axes = plt.subplots(1, len(rows), figsize=(4.2 * len(rows), 3.4), squeeze=False)
    for ax, row in zip(axes[0], rows, strict=True):
        for key, label, style in (
            ("dynamic", "dynamic FE", "-"),
            ("quasi_static", "quasi-static FE 1-DOF", "--"),
        ):
            if row[key] is None:
                continue
            s = row[key]["force"]
            t = [x * 1e6 if x is not None else math.nan for x in s["t"]]
            y = [x if x is not None else math.nan for x in s["y"]]
            ax.plot(t, y, style, label=label)
        ax.set_title(f"v = {row['speed']:g} m/s, m = {row['mass'] * 1e3:.3g} g")
        ax.set_xlabel("time from first touch [us]")
        ax.set_ylabel("contact force [N]")
        ax.set_xlim(left=0.0)
        ax.grid(alpha=0.3)
    axes[0][0].legend(loc="upper right", fontsize=8)
    fig.suptitle(table["description"], fontsize=9)
    fig.tight_layout()
    return fig
