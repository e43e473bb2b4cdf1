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
    gravity = true                      # or a value in m/s^2; rtol = 1e-7;
                                        # partial_slip_cells = 32 (friction partial_slip)
                                        # (or results.json's { value = 9.81, unit = "m/s^2" })

``models`` may be one text (``models = "ghaednia/coulomb"``). ``[[model]]`` tables (``law``,
``friction``, ``body``, ``rate``, ``name``, ``fixed``, ``law_params``; one ``[model]`` table
is one model) may replace ``models`` where a model needs more than its law and friction; a
misspelt key, or a ``fixed`` input that is unknown or out of range, is refused naming it.
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from impactlab._validation import read_text_file
from impactlab.calibrate.api import parse_model
from impactlab.calibrate.input_checks import ENGINE_OPTIONS, engine_options
from impactlab.calibrate.priors import parse_parameter

__all__ = ["load_config"]

_TOP = {"measurements", "models", "model", "parameters", "sampler", "engine"}
_SAMPLER = {"walkers", "steps", "burn", "seed"}
_ENGINE = set(ENGINE_OPTIONS)


def load_config(path: str | Path) -> dict[str, Any]:
    """The keyword arguments of ``calibrate`` from a calibration file: measurements (a path),
    parameters, models and the sampler's and engine's settings. ValueError naming the file and
    an unknown key, a sampler setting that is not an integer, models that are neither a list,
    a text nor a table, a bad model table, or the file when it is not UTF-8 text or not
    TOML."""
    p = Path(path)
    if p.is_dir():
        raise IsADirectoryError(f"calibration file {str(p)!r} is a directory; give the file")
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
    models = _listed(p, doc, "models", 'a list of model texts, e.g. ["ghaednia/coulomb"]')
    models += _listed(p, doc, "model", '[[model]] tables (law = "ghaednia", friction = ...)')
    if models:
        try:
            out["models"] = [parse_model(m) for m in models]
        except ValueError as exc:
            raise ValueError(f"{p}: {exc}") from None
    out.update(_sampler(p, _table(p, doc, "sampler", _SAMPLER)))
    engine = _table(p, doc, "engine", _ENGINE)
    if engine:
        try:
            out["engine"] = engine_options(engine)[0]
        except ValueError as exc:
            raise ValueError(f"{p}: [engine] {exc}") from None
    return out


def _listed(p: Path, doc: dict[str, Any], key: str, allowed: str) -> list[Any]:
    """The models under ``key`` as a list: a list as it is, one model text or table alone
    (``models = "ghaednia/coulomb"``, a single ``[model]`` table) as a list of it; ValueError
    naming the key, its value and what is ``allowed`` for anything else."""
    given = doc.get(key, [])
    if isinstance(given, str | dict):
        return [given]
    if not isinstance(given, list):
        raise ValueError(f"{p}: {key} must be {allowed}, got {given!r}")
    return given


def _table(p: Path, doc: dict[str, Any], name: str, keys: set[str]) -> dict[str, Any]:
    """The table ``name`` of the file (empty if absent); ValueError for an unknown key."""
    t = doc.get(name, {})
    if not isinstance(t, dict):
        raise ValueError(f"{p}: [{name}] must be a table of key = value")
    bad = set(t) - keys
    if bad:
        raise ValueError(f"{p}: unknown key(s) {sorted(bad)} in [{name}]; known: {sorted(keys)}")
    return dict(t)


def _sampler(p: Path, t: dict[str, Any]) -> dict[str, int]:
    """The [sampler] settings, each an integer (``steps = 12.7`` or ``"ten"`` is refused)."""
    for k, v in t.items():
        if isinstance(v, bool) or not isinstance(v, int):
            raise ValueError(f"{p}: [sampler] {k} must be an integer, got {v!r}")
    return t
