"""The output of ``impactlab invert`` (and of the inversion inside ``impactlab analyze``): the
JSON of docs/json-schema.md and the table in display units."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import typer

from impactlab._display import field_row, field_rows
from impactlab._json import quantity as quantity_json
from impactlab._json import to_json
from impactlab.analytic import InversionResult
from impactlab.analytic.inversion import MC_REJECTED_WARNING
from impactlab.cli._common import SI_UNITS, print_rows

#: SI units of the inversion's inputs, by keyword of ``impactlab.analytic.invert``.
INPUT_UNITS = {
    "angle": "rad",
    "v_i": "m/s",
    "e": "1",
    "mu": "1",
    "delta_p": "m",
    "sliding_length": "m",
    "dv_cy": "m/s",
}
#: The sigma of each output: output -> its field in InversionResult.
_SIGMAS = {
    "duration": "sigma_T_linear",
    "mean_force": "sigma_F_linear",
    "T_mc": "sigma_T_mc",
    "F_mc": "sigma_F_mc",
}


def _per(unit: str, by: str) -> str:
    return unit if by == "1" else f"{unit}/({by})"


def inversion_json(
    res: InversionResult, given: Mapping[str, tuple[float, float]] | None = None
) -> dict[str, Any]:
    """The inversion as JSON (docs/json-schema.md): outputs with their sigma (first order for
    ``duration``/``mean_force``, Monte Carlo for ``T_mc``/``F_mc``), the Monte Carlo's counts
    (``n_samples``, ``mc_used``: integers; ``mc_rejected``: the share discarded), the inputs as
    given (signs kept; ``res.inputs`` without ``given``), the rod and the sensitivities, each
    with its unit."""
    data = {k: v for k, v in res.to_dict().items() if k not in _SIGMAS.values()}
    inputs = given or res.inputs
    sigmas = {k: getattr(res, name) for k, name in _SIGMAS.items()}
    data["inputs"] = {k: quantity_json(float(v), INPUT_UNITS[k], s) for k, (v, s) in inputs.items()}
    for out, unit in (("T", "s"), ("F", "N")):
        sens = data.pop(f"sensitivity_{out}")
        data[f"sensitivity_{out}"] = {
            k: quantity_json(float(d), _per(unit, INPUT_UNITS[k])) for k, d in sens.items()
        }
    return to_json(data, SI_UNITS, sigmas)  # type: ignore[no-any-return]


def print_inversion(res: InversionResult, given: Mapping[str, tuple[float, float]]) -> None:
    """The inputs as given, then T and F (± first order; Monte Carlo rows, with the number of
    samples drawn and used, only when an input has an uncertainty), in display units. A
    discarded share up to ``MC_REJECTED_WARNING`` is noted under the table; above it the
    inversion's warning (stderr) says so."""
    uncertain = any(s > 0 for _v, s in given.values())
    rows = [field_row(k, float(v), INPUT_UNITS[k], s) for k, (v, s) in given.items()]
    outputs: dict[str, Any] = {
        "duration": res.duration,
        "mean_force": res.mean_force,
        "force_method": res.force_method,
    }
    if uncertain:
        outputs.update({"T_mc": res.T_mc, "F_mc": res.F_mc})
        outputs.update({"n_samples": res.n_samples, "mc_used": res.mc_used})
    outputs.update({"alpha": res.alpha, "mu_c": res.mu_c, "K_x": res.K_x, "K_y": res.K_y})
    outputs["gravity"] = "included" if res.gravity else "neglected (paper)"
    sigmas = {k: getattr(res, name) for k, name in _SIGMAS.items()} if uncertain else {}
    rows += field_rows(outputs, SI_UNITS, sigmas)
    title = "impactlab invert (paper Eqs. 12, 29)"
    if uncertain:
        title += ": ± first order; T_mc, F_mc: Monte Carlo mean ± sigma"
    print_rows(rows, title)
    if uncertain and 0 < res.mc_rejected <= MC_REJECTED_WARNING:
        typer.echo(
            f"note: {res.mc_rejected:.2%} of the {res.n_samples} Monte Carlo samples fell in the "
            f"sticking regime or out of range and were discarded ({res.mc_used} used)"
        )
