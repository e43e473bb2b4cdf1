"""The result of ``explain``: which configuration's predictions meet the measured values of
each drop, as tables (SI), a text table, a notebook table and JSON with units."""

from __future__ import annotations

import html
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import pandas as pd

from impactlab._display import display_unit, format_number
from impactlab._json import jsonable, quantity
from impactlab._version import __version__
from impactlab.explain.configurations import Configuration
from impactlab.explain.correlated import Pairs
from impactlab.explain.modes import MODES_CAVEAT, MODES_UNCHECKED
from impactlab.explain.runs import Outcome
from impactlab.explain.tables import WITHIN
from impactlab.explain.verdict import Verdict, drop_modes, verdict

__all__ = ["NOTHING_TUNED", "Z_DEFINITION", "Explanation"]

#: What every explanation states: no parameter was fitted.
NOTHING_TUNED = (
    "nothing is tuned: every configuration runs each drop with its own body, materials, "
    "incoming state and measured mu (the local Coulomb coefficient), the library's contact law "
    "and constants, gravity on; a rate row raises the flat's yield strength by its rate factor "
    "and, where the raised flat would overtake the rod's, the rod's to 1.5 times the raised "
    "flat's (more where their Poisson's ratios differ), so that a flat that yields first still "
    "does, as the measured dents say (a rod that yields first is left as it is)"
)
#: How z is formed, stated with every explanation.
Z_DEFINITION = (
    "z = (predicted - measured) / sigma with the measurement's sigma alone: a model's own error "
    "(its law beyond the verified range, ...) is a flag, not part of sigma; within 2 sigma: "
    "|z| <= 2; a configuration that did not run, was refused or is flagged invalidating "
    "predicts nothing and agrees with nothing"
)


def _cell(name: str, value: Any, unit: str) -> str:
    """``value`` of field ``name`` [``unit``, SI] as a number in its display unit, as text."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return format_number(float(value) * display_unit(name, unit).scale, 4)


def _head(name: str, unit: str) -> str:
    """A quantity's column head with its display unit: ``delta_p [um]``, ``e``."""
    shown = display_unit(name, unit).unit
    return name if shown in ("1", "", "-") else f"{name} [{shown}]"


def _short(status: str, caveat: str = "") -> str:
    """A status for a table cell: "ok", or its kind ("not run", "refused", "not ok", or "ok"
    with a caveat; "ok, not converged in modes", "ok, not checked in modes") with a pointer to
    the notes, which give the reason whole."""
    if status == "ok" and not caveat:
        return status
    kind = status.partition(":")[0]
    for words in (MODES_CAVEAT, MODES_UNCHECKED):
        if status == "ok" and caveat.startswith(words):
            kind = f"ok, {words}"
    return f"{kind} (see notes)"


def z_text(z: float) -> str:
    """z with three significant digits (``+7.46``), more where those would put it on the
    other side of the 2-sigma line or show a z that is not 2 as 2 (``+2.001``, ``+1.9997``),
    so that the cell agrees with the count within 2 sigma."""
    for digits in range(3, 18):
        text = f"{z:+.{digits}g}"
        shown = abs(float(text))
        if (shown <= WITHIN) == (abs(z) <= WITHIN) and (shown != WITHIN or abs(z) == WITHIN):
            return text
    return f"{z:+.17g}"


def _prediction(name: str, row: Any, unit: str) -> str:
    """A predicted value with its z (``0.7239 (z +7.46)``), or ``-`` where there is none."""
    if math.isnan(row.predicted):
        return "-"
    return f"{_cell(name, row.predicted, unit)} (z {z_text(row.z)})"


def _verdict_cell(v: Verdict, configuration: str) -> str:
    """What the verdict says of a configuration's row: ``best`` (``best, provisional``),
    ``first, inconsistent`` (named, but inconsistent with the measurements), ``least
    disagreeing (none agrees)``, ``undecided``, or ""."""
    mark = ""
    if configuration == v.configuration:
        mark = "best" if v.consistent is not False else "first, inconsistent"
    elif configuration == v.least_disagreeing:
        mark = "least disagreeing (none agrees)"
    elif configuration in v.undecided:
        mark = "undecided"
    return f"{mark}, provisional" if mark and v.provisional else mark


@dataclass(frozen=True)
class Explanation:
    """Which physics explains measured drops: ``comparison`` (one row per drop, configuration
    and measured quantity: measured, sigma, predicted, z, within_2_sigma, unit (SI), status),
    ``summary`` (per drop and configuration: values within 2 sigma, chi2 = sum of z^2 over
    the measured values, z^T R^-1 z for a drop with correlation coefficients (NaN when one
    has no prediction), the run's number of contacts, mu_apparent beside the measured mu,
    max_delta_ratio, delta_c, law_range, strain_rate, flags, modes_converged, a caveat), the
    ``configurations`` compared, the contact ``law`` and ``friction``, ``notes`` (what was not
    run and why, the caveats, what the runs warned), ``source`` (the measurements file, if any)
    and ``correlation`` (drop -> its correlation coefficients, pair -> coefficient).
    ``result(drop, configuration)`` is the simulation behind a row, ``verdict(drop)`` and
    ``best(drop)`` which configuration explains a drop best, ``references()`` the runs'
    sources."""

    comparison: pd.DataFrame
    summary: pd.DataFrame
    configurations: tuple[Configuration, ...]
    law: str
    friction: str
    notes: tuple[str, ...]
    source: str | None = None
    outcomes: Mapping[tuple[str, str], Outcome] = field(default_factory=dict, repr=False)
    correlation: Mapping[str, Pairs] = field(default_factory=dict, repr=False)

    def result(self, drop: str, configuration: str) -> Any:
        """The ImpactResult or DropResult of ``configuration`` on ``drop`` (None where it did
        not run or was refused); KeyError naming the known drops and configurations."""
        key = (drop, configuration)
        if key not in self.outcomes:
            drops = sorted({k[0] for k in self.outcomes})
            names = [c.name for c in self.configurations]
            raise KeyError(f"no run {key!r}; drops: {drops}; configurations: {names}")
        return self.outcomes[key].result

    def verdict(self, drop: str) -> Verdict:
        """Which configuration explains ``drop`` best, over which measured quantities and why
        (``explain.verdict``: the ok configurations ranked over the quantities all of them
        predict); KeyError naming the known drops for another."""
        return verdict(self.summary, self.comparison, drop, self.correlation.get(drop),
                       drop_modes(self.outcomes, drop))  # fmt: skip

    def best(self, drop: str) -> str | None:
        """The configuration that explains ``drop`` best (``verdict(drop).configuration``): of
        those whose result is ok, the one with the most values within 2 sigma, then the lowest
        chi2, over the measured quantities that all of them predict. None when no configuration
        is ok, they predict no quantity in common, the first agrees with none of the values it
        was ranked over (``verdict(drop).least_disagreeing`` names it), another ok
        configuration agrees with more of the drop's measured values than the first, or the
        verdict is undecided near the 2-sigma line (``verdict(drop).undecided``);
        ``verdict(drop).reason`` says which. Ranking first is not explaining the drop:
        ``verdict(drop).consistent`` is False where the measurements reject the row named
        (its chi2's p-value below 0.01, ``explain.verdict``). KeyError naming the known drops
        for another."""
        return self.verdict(drop).configuration

    def references(self) -> tuple[str, ...]:
        """The sources of the runs behind the rows (contact law, rate law, beam theory,
        integrator, ...), each once, as citations (with DOIs where they have one)."""
        cited = (str(r) for o in self.outcomes.values() if o.result is not None
                 for r in getattr(o.result, "references", ()))  # fmt: skip
        return tuple(dict.fromkeys(cited))

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready (docs/json-schema.md): every number a quantity with its unit (SI)."""
        comparison = [
            {
                "drop": r.drop, "configuration": r.configuration, "quantity": r.quantity,
                "measured": quantity(r.measured, r.unit, r.sigma),
                "predicted": quantity(r.predicted, r.unit), "z": quantity(r.z, "1"),
                "within_2_sigma": bool(r.within_2_sigma), "status": r.status,
            }
            for r in self.comparison.itertuples(index=False)
        ]  # fmt: skip
        summary = [
            {
                "drop": r.drop, "configuration": r.configuration, "status": r.status,
                "ok": bool(r.ok), "within_2_sigma": int(r.within_2_sigma),
                "compared": int(r.compared), "n_measured": int(r.n_measured),
                "chi2": quantity(r.chi2, "1"),
                "n_contacts": None if pd.isna(r.n_contacts) else int(r.n_contacts),
                "mu": quantity(r.mu, "1"), "mu_apparent": quantity(r.mu_apparent, "1"),
                "max_delta_ratio": quantity(r.max_delta_ratio, "1"),
                "fitted_delta_ratio_max": quantity(r.fitted_delta_ratio_max, "1"),
                "delta_c": quantity(r.delta_c, "m"), "law_range": r.law_range,
                "law_extrapolated": r.law_extrapolated, "rate_factor": quantity(r.rate_factor, "1"),
                "strain_rate": quantity(r.strain_rate, "1/s"),
                "flags": None if pd.isna(r.flags) else int(r.flags),
                "flag_names": r.flag_names,
                "modes_converged": None if r.modes_converged is None else bool(r.modes_converged),
                "caveat": r.caveat or None,
            }
            for r in self.summary.itertuples(index=False)
        ]  # fmt: skip
        best = [
            v.to_dict() | {name: quantity(getattr(v, name), "1")
                           for name in ("chi2", "consistency_chi2", "p_value")}
            for v in (self.verdict(d) for d in dict.fromkeys(self.summary["drop"]))
        ]  # fmt: skip
        return jsonable({
            "source": self.source, "law": self.law, "friction": self.friction,
            "nothing_tuned": NOTHING_TUNED, "z": Z_DEFINITION,
            "configurations": [
                {"name": c.name, "flexible": c.flexible,
                 "rate": None if c.rate is None else c.rate.text, "description": c.description}
                for c in self.configurations
            ],
            "comparison": comparison, "summary": summary, "best": best,
            "notes": list(self.notes), "references": list(self.references()),
            "impactlab_version": __version__,
        })  # fmt: skip

    def display_rows(self) -> tuple[tuple[str, ...], list[tuple[str, ...]]]:
        """(header, rows) in display units: per drop its measured row (value +- sigma), then
        one row per configuration: each quantity's prediction with its z, the values within
        2 sigma of those measured, chi2, what the verdict says of the row (``best``, ``first,
        inconsistent``, ``least disagreeing (none agrees)``, ``undecided``), the number of
        contacts, Eq. 28's mu (the measured row: the drop's mu), the flags and the status."""
        c = self.comparison
        quantities = list(dict.fromkeys(c["quantity"]))
        units = dict(zip(c["quantity"], c["unit"], strict=True))
        head = ("drop", "configuration", *(_head(q, units[q]) for q in quantities),
                "within 2 sigma", "chi2", "verdict", "n_contacts", "mu_apparent", "flags",
                "status")  # fmt: skip
        rows: list[tuple[str, ...]] = []
        for drop, part in self.summary.groupby("drop", sort=False):
            v = self.verdict(str(drop))
            mine = c[c["drop"] == drop]
            first = mine[mine["configuration"] == part["configuration"].iloc[0]]
            got = {r.quantity: r for r in first.itertuples(index=False)}
            rows.append((str(drop), "measured (+- sigma)", *(
                f"{_cell(q, got[q].measured, units[q])} +- {_cell(q, got[q].sigma, units[q])}"
                if q in got else "" for q in quantities
            ), "", "", "", "", _cell("mu", part["mu"].iloc[0], "1"), "", ""))  # fmt: skip
            for s in part.itertuples(index=False):
                cfg = mine[mine["configuration"] == s.configuration]
                pred = {r.quantity: r for r in cfg.itertuples(index=False)}
                rows.append(("", str(s.configuration), *(
                    _prediction(q, pred[q], units[q]) if q in pred else "" for q in quantities
                ), f"{s.within_2_sigma}/{s.n_measured}" if s.ok else "-",
                    _cell("chi2", s.chi2, "1"), _verdict_cell(v, str(s.configuration)),
                    "-" if pd.isna(s.n_contacts) else str(s.n_contacts),
                    _cell("mu", s.mu_apparent, "1"), s.flag_names or "-",
                    _short(s.status, s.caveat)))  # fmt: skip
        return head, rows

    def __repr__(self) -> str:
        head, body = self.display_rows()
        rows = [head, *body]
        widths = [max(len(r[i]) for r in rows) for i in range(len(head))]
        lines = [f"Explanation ({self.law}/{self.friction}; {len(self.configurations)} "
                 "configurations)"]  # fmt: skip
        lines += ["  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip()
                  for r in rows]  # fmt: skip
        lines += [f"note: {n}" for n in (NOTHING_TUNED, Z_DEFINITION, *self.notes)]
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        names, rows = self.display_rows()
        head = "".join(f"<th>{html.escape(h)}</th>" for h in names)
        body = "".join(
            "<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in rows
        )
        notes = "".join(
            f"<li>{html.escape(n)}</li>" for n in (NOTHING_TUNED, Z_DEFINITION, *self.notes)
        )
        title = html.escape(f"Explanation ({self.law}/{self.friction})")
        return (
            f"<div><strong>{title}</strong><table><thead><tr>{head}</tr></thead>"
            f"<tbody>{body}</tbody></table><ul>{notes}</ul></div>"
        )
