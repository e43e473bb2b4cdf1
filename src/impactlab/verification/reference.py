"""The compiled engine against the independent ``solve_ivp`` implementation
``impactlab.dynamics.reference`` at a tight tolerance (``REFERENCE_RTOL``), for every law and
the friction models ``impulse_ratio``, ``coulomb`` and ``mindlin`` (``partial_slip`` has no
``solve_ivp`` reference: ``verify_partial_slip`` checks it against its converged solution)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from impactlab.bodies import PAPER_ROD, Sphere
from impactlab.contact import builtin_law_names
from impactlab.dynamics import DEFAULT_RTOL, simulate
from impactlab.dynamics.reference import simulate_reference
from impactlab.friction import FRICTION_IDS
from impactlab.verification.table import TOLERANCES, VerificationTable, columns, worst_of

__all__ = ["REFERENCE_RTOL", "case_inputs", "reference_cases", "verify_reference"]

#: The reference's relative tolerance: that of the engine's accuracy contract
#: (tests/dynamics/test_accuracy.py), so that the errors are the engine's, not the reference's.
REFERENCE_RTOL = 1e-11

_REF_QUANTITIES = ("e", "delta_p", "sliding_length", "duration", "max_force")


def reference_cases(
    laws: Sequence[str] | None = None, frictions: Sequence[str] | None = None
) -> list[dict[str, Any]]:
    """The comparison cases: the paper's rod at 20 deg, 1.41 m/s, mu = 0.2, gravity on, for every
    law and friction model, plus the 45 and 70 deg drops (Ghaednia, Coulomb) and an oblique
    sphere (Mindlin)."""
    laws = list(builtin_law_names() if laws is None else laws)
    frictions = list(FRICTION_IDS if frictions is None else frictions)
    cases: list[dict[str, Any]] = [
        {
            "body": "rod",
            "law": law,
            "friction": fr,
            "mu": 0.2,
            "angle": 20.0,
            "vx": 0.0,
            "vy": -1.41,
        }
        for law in laws
        for fr in frictions
    ]
    if laws == list(builtin_law_names()) and frictions == list(FRICTION_IDS):
        cases += [
            {
                "body": "rod",
                "law": "ghaednia",
                "friction": "coulomb",
                "mu": 0.13,
                "angle": 45.0,
                "vx": 0.0,
                "vy": -2.18,
            },
            {
                "body": "rod",
                "law": "ghaednia",
                "friction": "coulomb",
                "mu": 0.10,
                "angle": 70.0,
                "vx": 0.0,
                "vy": -3.45,
            },
            {
                "body": "sphere",
                "law": "ghaednia",
                "friction": "mindlin",
                "mu": 0.3,
                "angle": 90.0,
                "vx": 0.4,
                "vy": -1.0,
            },
        ]
    return cases


_COLUMNS = (
    *columns(
        """
        case       | case
        law        | law
        friction   | friction
        regime     | regime
        regime_ref | regime (ref.)
        """
    ),
    *columns("\n".join(f"err_{q} | error {q} | .1e" for q in _REF_QUANTITIES)),
    *columns("status | status"),
)


def _sci(x: float) -> str:
    """``x`` as 2e-7, 1e-11 (no zero-padded exponent)."""
    mant, exp = f"{x:.0e}".split("e")
    return f"{mant}e{int(exp)}"


_D, _R, _T = _sci(DEFAULT_RTOL), _sci(REFERENCE_RTOL), _sci(TOLERANCES["reference"])
_TEXT = f"""
The compiled engine (`impactlab.dynamics.simulate`, its default tolerance rtol = {_D}) against
`impactlab.dynamics.reference.simulate_reference` at rtol = {_R}: the same physics written
independently in plain Python and integrated with `scipy.integrate.solve_ivp` (RK45), with every
phase change (compression/restitution, reloading, stick/slip, the law's switch point) located by
a terminal event and the integration restarted. Only the contact-law kernels are shared. The
paper's rod (I_C = m L^2/12) on AISI 1010 with gravity, the rod free to turn. Errors are
relative to each quantity's scale: 1 for e, delta_max for delta_p, max(abs(L_s), delta_max) for
L_s, the reference value for T and F_max. The reference changes by less than 1e-9 of these
scales from rtol = {_R} to 1e-12, so the errors are the engine's; the tolerance, {_T}, is the
engine's accuracy contract at its default tolerance (docs/engine/benchmarks.md, asserted by
tests/dynamics/test_accuracy.py). `partial_slip` has no `solve_ivp` reference: it is verified
against its converged solution, Maw-Barber-Fawcett's problem and Kharaz's data below.
"""


def case_inputs(c: Mapping[str, Any]) -> tuple[Any, dict[str, Any]]:
    """The body and the keyword arguments of ``simulate`` for one case of
    :func:`reference_cases`."""
    body = PAPER_ROD if c["body"] == "rod" else Sphere(0.01)
    kw = {
        "law": c["law"],
        "friction": c["friction"],
        "mu": c["mu"],
        "angle": math.radians(c["angle"]) if c["body"] == "rod" else None,
        "velocity": (c["vx"], c["vy"]),
    }
    return body, kw


def _compare(c: Mapping[str, Any]) -> dict[str, Any]:
    """One case (a record of :func:`reference_cases`): the engine against the reference, with
    the scaled errors, the regimes and a status."""
    body, kw = case_inputs(c)
    rec: dict[str, Any] = {
        "case": f"{c['body']} {c['angle']:g} deg, v = "
        f"({c['vx']:g}, {c['vy']:g}) m/s, mu = {c['mu']:g}",
        "law": c["law"],
        "friction": c["friction"],
    }
    r = simulate(body, history=False, **kw)
    try:
        ref = simulate_reference(body, rtol=REFERENCE_RTOL, **kw)
    except (RuntimeError, ValueError) as exc:
        failed = {"regime_ref": "-", "worst": math.nan, "status": f"reference failed: {exc}"}
        return {**rec, "regime": r.regime, **failed}
    scale = {
        "e": 1.0,
        "delta_p": ref["delta_max"],
        "sliding_length": max(abs(ref["sliding_length"]), ref["delta_max"]),
        "duration": abs(ref["duration"]),
        "max_force": abs(ref["max_force"]),
    }
    for q in _REF_QUANTITIES:
        rec[f"err_{q}"] = abs(getattr(r, q) - ref[q]) / scale[q]
    rec["regime"] = r.regime
    rec["regime_ref"] = ref["regime"]
    rec["worst"] = max(rec[f"err_{q}"] for q in _REF_QUANTITIES)
    if r.regime != ref["regime"]:
        rec["status"] = "**regime differs**"
    else:
        rec["status"] = "ok" if rec["worst"] <= TOLERANCES["reference"] else "**exceeds**"
    return rec


def verify_reference(cases: Sequence[Mapping[str, Any]] | None = None) -> VerificationTable:
    """The compiled engine (``simulate``, default tolerance) against
    ``impactlab.dynamics.reference`` (``solve_ivp`` with event location, written independently)
    at rtol = ``REFERENCE_RTOL``: e, delta_p, L_s, T, F_max and the regime. Errors relative to
    each quantity's scale: 1 for e, delta_max for delta_p, max(abs(L_s), delta_max) for L_s, the
    reference value for T and F_max."""
    records = [_compare(c) for c in (reference_cases() if cases is None else cases)]
    compared = [r for r in records if not str(r["status"]).startswith("reference failed")]
    worst = worst_of([r["worst"] for r in compared])
    tol = TOLERANCES["reference"]
    passed = (
        len(compared) == len(records)
        and worst <= tol
        and all(r["regime"] == r["regime_ref"] for r in compared)
    )
    return VerificationTable(
        "reference",
        "Engine vs the solve_ivp reference",
        _TEXT,
        _COLUMNS,
        tuple(records),
        "largest scaled error of e, delta_p, L_s, T, F_max "
        "per case; regimes equal; every reference run succeeds",
        worst,
        tol,
        passed,
    )
