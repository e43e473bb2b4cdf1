"""An inversion as JSON (docs/json-schema.md): what ``impactlab invert --json`` prints and the
``inversion`` of an analysis's JSON and of its ``results.json``."""

from __future__ import annotations

import math
from typing import Any

from impactlab._json import quantity as quantity_json
from impactlab._json import to_json
from impactlab._version import __version__
from impactlab.analytic.result import INPUT_UNITS, InversionResult
from impactlab.schema.printed import SI_UNITS

__all__ = ["OUTPUT_UNITS", "SIGMAS", "inversion_json"]

#: The sigma of each output: output -> its field in InversionResult.
SIGMAS = {
    "duration": "sigma_T_linear",
    "mean_force": "sigma_F_linear",
    "T_mc": "sigma_T_mc",
    "F_mc": "sigma_F_mc",
}
#: SI units of the inversion's outputs (``SI_UNITS`` and the Monte Carlo's medians).
OUTPUT_UNITS = {**SI_UNITS, "T_median_mc": "s", "F_median_mc": "N"}


def _per(unit: str, by: str) -> str:
    """The unit of a derivative, ``unit`` per ``by``: ``s/m``, ``s/rad``, ``s/(m/s)``."""
    if by == "1":
        return unit
    return f"{unit}/({by})" if any(c in by for c in "/* ") else f"{unit}/{by}"


def inversion_json(res: InversionResult) -> dict[str, Any]:
    """The inversion as JSON (docs/json-schema.md): outputs with their sigma (first order for
    ``duration``/``mean_force``, Monte Carlo for ``T_mc``/``F_mc``), the Monte Carlo's medians
    and 95 % intervals, its counts (``n_samples``, ``mc_used``: integers; ``mc_rejected``: the
    share discarded), the inputs as the inversion used them (``res.inputs``: SI, magnitudes of
    ``v_i``, ``delta_p`` and ``sliding_length``), the rod and the sensitivities, derivatives
    with respect to those same inputs, each with its unit; a force that does not exist
    (``F_momentum`` without a measured dv_cy) is a quantity of value null; the
    ``impactlab_version``."""
    data = {k: v for k, v in res.to_dict().items() if k not in SIGMAS.values()}
    data |= {k: math.nan for k in ("F_momentum", "F_rigid") if data.get(k, 0.0) is None}
    sigmas = {k: getattr(res, name) for k, name in SIGMAS.items()}
    data["inputs"] = {
        k: quantity_json(float(v), INPUT_UNITS[k], s) for k, (v, s) in res.inputs.items()
    }
    for out, unit in (("T", "s"), ("F", "N")):
        sens = data.pop(f"sensitivity_{out}")
        data[f"sensitivity_{out}"] = {
            k: quantity_json(float(d), _per(unit, INPUT_UNITS[k])) for k, d in sens.items()
        }
    data["impactlab_version"] = __version__
    return to_json(data, OUTPUT_UNITS, sigmas)  # type: ignore[no-any-return]
