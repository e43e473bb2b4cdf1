"""The dynamic FE impact beside the quasi-static FE 1-DOF impact and impactlab's contact laws.

Reads the shipped tables (``impactlab.fe.impact_reference``: dynamic FE and the 1-DOF impact
on the quasi-static FE curves of the same bodies, without running CalculiX) and adds one
column per contact law, simulated by impactlab's engine for the same sphere (radius, mass,
speed; frictionless, no gravity). A new law becomes a column with one call:
``add_law(comparison, "tabulated")``, if it shares the case's materials: an elastic-plastic
law only where a body can yield, an elastic one (Hertz) only where both are kept elastic.
Each row also gives delta_max / delta_c and, for a law, the upper end of its range for the
pair (verified against the FE indentations, ``impactlab.contact.ranges``), marked where the
impact went past it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from impactlab._display import format_number
from impactlab._html import grid_html
from impactlab.bodies import Sphere
from impactlab.contact import law_names
from impactlab.dynamics import simulate
from impactlab.fe.impact_reference import IMPACT_CASES, RADIUS, ImpactCase, load_impact_table
from impactlab.fe.impact_result import RenamedKeys
from impactlab.fe.problem import critical_interference
from impactlab.materials import ContactPair

__all__ = [
    "ImpactComparison",
    "add_law",
    "check_law",
    "compare_impacts",
    "comparison_markdown",
    "comparison_rows",
    "law_row",
]

#: The quantities compared (the glossary's names: an FE impact's delta_p is the interference
#: left after it, the flat's dent and the sphere's flattening, as the engine's delta_p is the
#: law's residual depth at separation), with their labels and units.
QUANTITIES: tuple[tuple[str, str], ...] = (
    ("e", "e"),
    ("delta_p", "delta_p [um]"),
    ("delta_max", "delta_max [um]"),
    ("max_force", "F_max [N]"),
    ("duration", "T [us]"),
)
_SCALE = {"delta_p": 1e6, "delta_max": 1e6, "duration": 1e6}
#: Fixed decimals of e, whose deviation from 1 four significant digits would round away
#: (1.0003 shown as 1); a permanent depth: 4 significant digits, at most 4 decimals (its
#: deviation from 0: -0.0091 um); the others: 4 significant digits.
_DECIMALS = {"e": 4}
_NEAR_ZERO = ("delta_p",)
#: The last column: delta_max / delta_c, and a law's range in delta_c.
RANGE_LABEL = "delta_max/delta_c (law's range)"
#: The FE columns (every other column is a law's); speeds and columns a repr names at most.
_FE_COLUMNS = ("dynamic FE", "quasi-static FE 1-DOF")
_SHOWN = 8

#: The elastic-plastic laws.
PLASTIC_LAWS: tuple[str, ...] = (
    "jackson-green",
    "ghaednia",
    "kogut-komvopoulos",
    "brake",
    "thornton",
)
#: The elastic laws (no yield, no permanent dent); every other law is elastic-plastic (a
#: registered law is the tabulated law on its own indentation data).
ELASTIC_LAWS: tuple[str, ...] = ("hertz",)
#: The laws compared by default: Hertz for the elastic case, the elastic-plastic laws for the
#: elastic-plastic flat.
DEFAULT_LAWS: dict[str, tuple[str, ...]] = {
    "elastic-ball-on-aisi1010": ("hertz",),
    "paper-ball-on-aisi1010": PLASTIC_LAWS,
    "rod-mass-on-aisi1010": PLASTIC_LAWS,
}


@dataclass(repr=False)
class ImpactComparison:
    """One case's comparison: per speed, a column name -> quantities mapping (the names of
    :data:`QUANTITIES`; those before 0.3, ``restitution``, ..., read them with a
    DeprecationWarning). The columns are "dynamic FE", "quasi-static FE 1-DOF" and one per law
    added."""

    case: str
    speeds: list[float]
    mass: float
    columns: dict[str, list[dict[str, float]]] = field(default_factory=dict)
    delta_c: float = math.nan  # the pair's critical interference [m]

    def __repr__(self) -> str:
        """One line: the case, speeds, mass, delta_c, the columns, e of the dynamic FE and
        how many law rows went past the law's range."""
        speeds = ", ".join(format_number(v) for v in self.speeds[:_SHOWN])
        names = list(self.columns)
        cols = ", ".join(names[:_SHOWN]) + (", ..." if len(names) > _SHOWN else "")
        parts = [
            f"{len(self.speeds)} speed{'s' * (len(self.speeds) != 1)} {speeds}"
            + (", ..." if len(self.speeds) > _SHOWN else "")
            + " m/s",
            f"mass {format_number(self.mass)} kg",
            f"delta_c {format_number(self.delta_c * 1e6, 4)} um",
        ]
        text = f"ImpactComparison({self.case!r}: {', '.join(parts)}; {len(names)} columns: {cols}"
        fe = self.columns.get("dynamic FE")
        if fe:
            text += "; dynamic FE e " + ", ".join(_shown("e", r["e"]) for r in fe[:_SHOWN])
        laws = [r for n, col in self.columns.items() if n not in _FE_COLUMNS for r in col]
        past = sum(bool(r.get("extrapolated", 0.0)) for r in laws)
        if laws:
            text += f"; {past} of {len(laws)} law rows extrapolated"
        return text + ")"

    def _repr_html_(self) -> str:
        """The table of :func:`comparison_markdown` (escaped)."""
        header, rows = comparison_rows(self)
        return grid_html(f"ImpactComparison {self.case}", header, rows)


def _yields(c: ImpactCase) -> bool:
    """True when a body of the case can yield (not both kept elastic)."""
    return not (c.sphere == "elastic" and c.flat_hardening == "elastic")


def check_law(case: str, law: str) -> None:
    """ValueError (one line) unless ``law`` is a registered law whose materials the case
    shares: elastic-plastic where a body can yield, elastic where both are kept elastic."""
    if case not in IMPACT_CASES:
        raise ValueError(f"case must be one of {', '.join(IMPACT_CASES)}, got {case!r}")
    known = law_names()
    if law not in known:
        raise ValueError(f"law must be a registered contact law ({', '.join(known)}), got {law!r}")
    yields, plastic_law = _yields(IMPACT_CASES[case]), law not in ELASTIC_LAWS
    if plastic_law == yields:
        return
    fitting = " or ".join(n for n, c in IMPACT_CASES.items() if _yields(c) == plastic_law)
    if yields:
        raise ValueError(
            f"law {law!r} is elastic but case {case!r} has bodies that yield: compare it on "
            f"{fitting}, or use an elastic-plastic law here "
            f"({', '.join(n for n in known if n not in ELASTIC_LAWS)})"
        )
    raise ValueError(
        f"law {law!r} is elastic-plastic but case {case!r} keeps both bodies elastic (nothing "
        f"can yield): compare it on {fitting}, or use an elastic law here "
        f"({', '.join(ELASTIC_LAWS)})"
    )


def law_row(case: str, law: str, speed: float, mass: float) -> dict[str, float]:
    """e, delta_p, delta_max, F_max and the duration of ``law``'s impact for the case's
    sphere and flat at ``speed`` [m/s] (frictionless, no gravity; SI units), with
    ``range_limit``, the upper end of the law's range for the pair in delta_c (verified
    against FE, else its stand-in; inf: none, as the tabulated law's, refused beyond its data;
    nan where both bodies are kept elastic: Hertz holds at any interference there) and
    ``extrapolated`` (1.0 where delta_max passed it, the engine's LAW_EXTRAPOLATED, else 0.0).
    ValueError for a law the case's materials do not fit (:func:`check_law`)."""
    check_law(case, law)
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
    limit, extrapolated = math.nan, False
    if _yields(c):  # the law's own reference interference, then in the pair's delta_c
        delta_c = critical_interference(ContactPair(c.sphere_material, c.flat), RADIUS)
        delta_ref = float(r.delta_max) / float(r.max_delta_ratio)
        limit = float(r.fitted_delta_ratio_max) * delta_ref / delta_c
        extrapolated = bool(r.extrapolated)
    return RenamedKeys(
        e=float(r.e),
        delta_p=float(r.delta_p),
        delta_max=float(r.delta_max),
        max_force=float(r.max_force),
        duration=float(r.duration),
        range_limit=limit,
        extrapolated=float(extrapolated),
    )


def _fe_column(rows: list[dict[str, Any]], key: str) -> list[dict[str, float]]:
    out: list[dict[str, float]] = []
    for row in rows:
        src = row[key] or {}  # None: not run (the rod-mass case's dynamic FE)
        values = {q: math.nan if src.get(q) is None else float(src[q]) for q, _ in QUANTITIES}
        out.append(RenamedKeys(values))
    return out


def add_law(comparison: ImpactComparison, law: str) -> ImpactComparison:
    """Add the column of a registered contact law (``impactlab.contact.law_names()``) whose
    materials the case shares; ValueError (one line) otherwise (:func:`check_law`)."""
    check_law(comparison.case, law)
    comparison.columns[law] = [
        law_row(comparison.case, law, v, comparison.mass) for v in comparison.speeds
    ]
    return comparison


def compare_impacts(case: str, laws: tuple[str, ...] | None = None) -> ImpactComparison:
    """The comparison of a shipped case with its default laws (or ``laws``)."""
    table = load_impact_table(case)
    rows = table["rows"]
    comp = ImpactComparison(
        case=case,
        speeds=[float(r["speed"]) for r in rows],
        mass=float(rows[0]["mass"]),
        delta_c=float(table["delta_c"]),
    )
    comp.columns["dynamic FE"] = _fe_column(rows, "dynamic")
    comp.columns["quasi-static FE 1-DOF"] = _fe_column(rows, "quasi_static")
    for law in DEFAULT_LAWS.get(case, ()) if laws is None else laws:
        add_law(comp, law)
    return comp


def _shown(q: str, x: float) -> str:
    """One quantity's cell (``x`` in the table's unit)."""
    if not math.isfinite(x):
        return "n/a"
    if q in _DECIMALS:
        return f"{x:.{_DECIMALS[q]}f}"
    if q in _NEAR_ZERO:
        digits = 3 - math.floor(math.log10(abs(x))) if x != 0.0 else 4
        return f"{x:.{min(4, max(0, digits))}f}"
    return f"{x:.4g}"


def _range_cell(row: dict[str, float], delta_c: float) -> str:
    """``7.98 > 1: extrapolated``, ``0.8 <= 1``, or delta_max / delta_c alone (the FE rows, a
    law without a range, an elastic case)."""
    ratio = row["delta_max"] / delta_c
    if not math.isfinite(ratio):
        return "n/a"
    limit = row.get("range_limit", math.nan)
    if not math.isfinite(limit):
        return f"{ratio:.3g}"
    if row.get("extrapolated", 0.0):
        return f"{ratio:.3g} > {limit:.3g}: extrapolated"
    return f"{ratio:.3g} <= {limit:.3g}"


def comparison_rows(comp: ImpactComparison) -> tuple[list[str], list[list[str]]]:
    """(header, rows) of the comparison: one row per speed and column; the last column is
    delta_max / delta_c and, for a law on a case where a body yields, the upper end of the
    law's range for the pair (``> ...: extrapolated`` where the impact went past it)."""
    header = ["v [m/s]", "model", *(label for _, label in QUANTITIES), RANGE_LABEL]
    rows = []
    for i, v in enumerate(comp.speeds):
        for name, col in comp.columns.items():
            vals = [_shown(q, col[i][q] * _SCALE.get(q, 1.0)) for q, _ in QUANTITIES]
            rows.append([f"{v:g}", name, *vals, _range_cell(col[i], comp.delta_c)])
    return header, rows


def comparison_markdown(comp: ImpactComparison) -> str:
    """The comparison as a Markdown table (:func:`comparison_rows`)."""
    header, rows = comparison_rows(comp)
    head = "| " + " | ".join(header) + " |\n"
    head += "|" + " --- |" * len(header) + "\n"
    return head + "\n".join("| " + " | ".join(r) + " |" for r in rows) + "\n"


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
