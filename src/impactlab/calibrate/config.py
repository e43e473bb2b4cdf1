"""A calibration file (TOML): what ``impactlab calibrate --config`` reads.

    measurements = "drops.csv"          # relative to this file
    models = ["ghaednia/coulomb", "jackson-green/coulomb"]
    [parameters]
    mu = "uniform(0, 0.6)"
    flat_yield_strength = "loguniform(100 MPa, 2 GPa)"
    [sampler]
    walkers = 16
    steps = 2000
    burn = 1000
    seed = 0
    [engine]
    gravity = true                      # or a value in m/s^2; rtol = 1e-7

``[[model]]`` tables (``law``, ``friction``, ``body``, ``name``, ``fixed``, ``law_params``)
may replace ``models`` where a model needs more than its law and friction.
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from impactlab._validation import read_text_file
from impactlab.calibrate.api import parse_model
from impactlab.calibrate.priors import parse_parameter

__all__ = ["load_config"]

_TOP = {"measurements", "models", "model", "parameters", "sampler", "engine"}
_SAMPLER = {"walkers", "steps", "burn", "seed"}
_ENGINE = {"gravity", "rtol"}


def load_config(path: str | Path) -> dict[str, Any]:
    """The keyword arguments of ``calibrate`` from a calibration file: measurements (a path),
    parameters, models and the sampler's and engine's settings. ValueError naming an unknown
    key, or the file when it is not UTF-8 text or not TOML."""
    p = Path(path)
    if not p.is_file():
        raise FileNotFoundError(f"calibration file not found: {p}")
    try:
        doc = tomllib.loads(read_text_file(p, "TOML", f"calibration file {str(p)!r}"))
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{p}: not valid TOML ({exc})") from None
    unknown = set(doc) - _TOP
    if unknown:
        raise ValueError(f"{p}: unknown key(s) {sorted(unknown)}; known: {sorted(_TOP)}")
    out: dict[str, Any] = {}
    if "measurements" in doc:
        m = Path(str(doc["measurements"]))
        out["measurements"] = m if m.is_absolute() else p.parent / m
    params = doc.get("parameters", {})
    if not isinstance(params, dict):
        raise ValueError(f"{p}: [parameters] must be a table of name = prior")
    out["parameters"] = [parse_parameter(k, v) for k, v in params.items()]
    models: list[Any] = list(doc.get("models", [])) + list(doc.get("model", []))
    if models:
        out["models"] = [parse_model(m) for m in models]
    for table, keys in (("sampler", _SAMPLER), ("engine", _ENGINE)):
        t = doc.get(table, {})
        bad = set(t) - keys
        if bad:
            raise ValueError(
                f"{p}: unknown key(s) {sorted(bad)} in [{table}]; known: {sorted(keys)}"
            )
        if table == "sampler":
            out.update({k: int(v) for k, v in t.items()})
        elif t:
            out["engine"] = dict(t)
    return out
