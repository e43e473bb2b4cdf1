"""The output of ``impactlab invert`` (and of the inversion inside ``impactlab analyze``): the
JSON of docs/json-schema.md and the table in display units."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import typer

from impactlab._display import field_row, field_rows
from impactlab.analytic import InversionResult
from impactlab.analytic.inversion import MC_REJECTED_WARNING
from impactlab.analytic.result import INPUT_UNITS, MC_INTERVAL, doubting
from impactlab.analytic.result_json import OUTPUT_UNITS, SIGMAS
from impactlab.cli._common import print_rows
from impactlab.cli.invert_inputs import CORRELATED

#: The inputs whose sign ``invert`` ignores, shown in the table as the magnitudes it uses (and
#: the JSON's ``inputs`` holds): labelled ``|v_i|``, ``|sliding_length|``.
_MAGNITUDES = ("v_i", "sliding_length")


def inversion_doubts(inverted: list[str], compared: list[str]) -> list[str]:
    """What makes the inversion not ok (``ok`` false in ``invert --json``): the inversion's
    warnings (``inverted``) that doubt it, as its ``InversionResult.doubts`` (by the rule of
    ``impactlab analyze``: a velocity change no impact gives, a duration no rigid-body impact
    has, a Monte Carlo spread to such durations, a rod whose mass and inertia do not fit;
    ``analytic.result.DOUBT_PHRASES``), and every warning of the comparison with the simulated
    impact (``compared``: a T or F more than 3 times off)."""
    return [*doubting(inverted), *compared]


def _label(name: str) -> str:
    """An input's label in the table: ``|v_i|`` for an input whose magnitude is used."""
    return f"|{name}|" if name in _MAGNITUDES else name


def _correlation_row(res: InversionResult) -> list[tuple[str, str, str]]:
    """The row of the inputs' correlations (none when independent): the coefficients of the
    inputs as used, as the JSON's ``correlation`` (those of the magnitudes: ``--vi "-1.41
    m/s" --correlation vi,ls=0.5`` shows ``(|v_i|, |sliding_length|) -0.5``); each pair in the
    order of the command's inputs (``CORRELATED``: angle, v_i, e, mu, delta_p, sliding_length,
    dv_cy, vt_in, the rows above it), as ``--correlation e,mu=-0.3`` or ``mu,e=-0.3`` reads
    it: ``(e, mu) -0.3`` (``InversionResult.correlation`` and the JSON hold a pair in the
    order of ``invert``'s keywords)."""
    texts = []
    for (a, b), rho in res.correlation.items():
        first, second = sorted((a, b), key=CORRELATED.index)
        texts.append(f"({_label(first)}, {_label(second)}) {rho:.4g}")
    return [("correlation", ", ".join(texts), "")] if texts else []


def print_inversion(res: InversionResult, doubts: Sequence[str] = ()) -> None:
    """The inputs as the inversion used them, as the JSON's ``inputs`` (SI values in display
    units; the magnitudes of v_i and sliding_length, labelled ``|v_i|``, ``|sliding_length|``:
    ``--vi "-1.41 m/s"`` and ``--vi "1.41 m/s"`` show 1.41) and their correlations, then T and
    F (± first order; Monte Carlo rows, with their medians, 95 % intervals and the number of
    samples drawn and used, only when an input has an uncertainty), in display units, and
    ``ok`` no with each of the ``doubts`` where there is one (as the JSON's ``ok`` and
    ``doubts``). A discarded share up to ``MC_REJECTED_WARNING`` is noted under the table;
    above it the inversion's warning (stderr) says so."""
    uncertain = any(s > 0 for _v, s in res.inputs.values())
    rows = [
        (_label(k), *field_row(k, float(v), INPUT_UNITS[k], s)[1:])
        for k, (v, s) in res.inputs.items()
    ]
    rows += _correlation_row(res)
    outputs: dict[str, Any] = {
        "duration": res.duration,
        "mean_force": res.mean_force,
        "force_method": res.force_method,
    }
    if uncertain:
        outputs.update({"T_mc": res.T_mc, "T_median_mc": res.T_median_mc})
        outputs["T_interval_mc"] = res.T_interval_mc
        outputs.update({"F_mc": res.F_mc, "F_median_mc": res.F_median_mc})
        outputs["F_interval_mc"] = res.F_interval_mc
        outputs.update({"n_samples": res.n_samples, "mc_used": res.mc_used})
    outputs.update({"alpha": res.alpha, "mu_c": res.mu_c, "K_x": res.K_x, "K_y": res.K_y})
    outputs["gravity"] = "included" if res.gravity else "neglected (paper)"
    outputs["measure"] = res.measure
    sigmas = {k: getattr(res, name) for k, name in SIGMAS.items()} if uncertain else {}
    rows += field_rows(outputs, OUTPUT_UNITS, sigmas)
    rows += [("ok", "no", ""), *(("doubt", d, "") for d in doubts)] if doubts else []
    title = "impactlab invert (paper Eqs. 12, 29)"
    if uncertain:
        lo, hi = MC_INTERVAL
        title += (
            ": ± first order; Monte Carlo: T_mc, F_mc mean ± sigma, *_median_mc median, "
            f"*_interval_mc 95 % ({lo:g}-{hi:g} percentiles)"
        )
    print_rows(rows, title)
    if uncertain and 0 < res.mc_rejected <= MC_REJECTED_WARNING:
        typer.echo(
            f"note: {res.mc_rejected:.2%} of the {res.n_samples} Monte Carlo samples fell in the "
            "sticking regime or out of range (e.g. e outside [0, 1]) and were discarded "
            f"({res.mc_used} used)"
        )
