"""An analysis as JSON (docs/json-schema.md): what ``impactlab analyze --json`` prints and
what ``results.json`` (``ExperimentResult.save``, ``analyze(out_dir=...)``, ``--out``) holds:
every quantity a ``{"value", "sigma", "unit"}`` object."""

from __future__ import annotations

from typing import Any

from impactlab._json import quantity as quantity_json
from impactlab._json import to_json
from impactlab._version import __version__
from impactlab.analytic.result_json import inversion_json
from impactlab.schema.printed import SI_UNITS

__all__ = ["analysis_json"]

#: SI units of the fields of the analysis' details (``kinematics``, ``dent``) by name; a key
#: ending in ``_m`` is in m, ``_deg`` in deg (docs/json-schema.md).
_DETAIL_UNITS = {
    **SI_UNITS,
    "deepest_fraction": "1",
    "dropout_fraction": "1",
    "sliding_axis": "1",
    "slope_x": "1",
    "slope_y": "1",
    "start": "m",
    "end": "m",
    "fitted_gravity": "m/s^2",
    "filled_in_dent": "1",
}


def _details(node: Any) -> Any:
    """The analysis' details in the JSON shape: an estimate ``{"value", "sigma", "unit"}`` as a
    quantity (sigma only when > 0, unit "1" when dimensionless), a float under a known key or
    a ``_m``/``_deg`` key as a quantity; the rest as it is."""
    if isinstance(node, dict):
        if "plane" in node:  # z = c0 + c1 x + c2 y of the scan's levelling
            c0, c1, c2 = node["plane"]
            node = {**node, "plane": {"offset_m": c0, "slope_x": c1, "slope_y": c2}}
        if set(node) == {"value", "sigma", "unit"}:
            return quantity_json(node["value"], node["unit"] or "1", node["sigma"])  # "": older
        units = {k: u for k in node if (u := _suffix_unit(str(k))) is not None}
        return to_json({k: _details(v) for k, v in node.items()}, units)
    if isinstance(node, list):
        return [_details(v) for v in node]
    return node


def _suffix_unit(key: str) -> str | None:
    if key in _DETAIL_UNITS:
        return _DETAIL_UNITS[key]
    for suffix, unit in (("_m", "m"), ("_deg", "deg"), ("_rad", "rad"), ("_s", "s")):
        if key.endswith(suffix):
            return unit
    return None


def analysis_json(res: Any, options: dict[str, Any] | None = None) -> dict[str, Any]:
    """The analysis ``res`` (an ``ExperimentResult``) as JSON (docs/json-schema.md): ``summary``
    of quantities with their sigma,
    the inversion as ``impactlab invert --json`` writes it, the details (kinematics, dent,
    engine comparison) with the unit of every quantity, the command's ``options`` as given
    (what repeats the analysis; None and the default are written too) and the
    ``impactlab_version``."""
    data = res.to_dict()
    if options is not None:  # the command's words where they differ (a rod by name)
        data["options"] = {**data.get("options", {}), **options}
    data["impactlab_version"] = __version__
    data["summary"] = {
        k: quantity_json(est.value, est.unit, est.sigma) for k, est in res.summary().items()
    }
    if res.inversion is not None:
        data["inversion"] = inversion_json(res.inversion)
    for key in ("rod", "model", "kinematics", "dent"):
        if data.get(key) is not None:
            data[key] = _details(data[key])
    return data
