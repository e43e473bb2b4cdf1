"""The measured inputs of ``impactlab invert``: their units, option names and TOML keys, and how
a value or a standard deviation is read (from the command line or a ``--file``).

A bare standard deviation of a dimensional input is in the unit its value is written in, on the
command line (``--ls "1400 um" --sigma-ls 50``: 50 um) as in a measurement file (``ls = "1400
um"`` and ``[sigma] ls = 50``: 50 um); where the value comes from elsewhere (``--case``, or the
file for a command-line sigma) it is refused: its unit would be a guess.
"""

from __future__ import annotations

import math
import re
from typing import Any

from impactlab.analytic._measurements import past_normal_inversion
from impactlab.cli._common import UserError, any_angle, parse_rod_table, quantity
from impactlab.cli.config_values import check_booleans
from impactlab.units import bare_number, read_minus

__all__ = [
    "ALIAS",
    "ARGUMENTS",
    "EXAMPLE_SIGMAS",
    "EXAMPLE_UNITS",
    "EXTRA",
    "FIELDS",
    "IN_FILE",
    "MEASURES",
    "check_measure",
    "correlation_label",
    "file_correlations",
    "from_file",
    "parse_correlations",
    "parse_sigma",
    "parse_value",
]

# input name -> (SI unit used for parsing, accepted TOML keys, command-line option); the keys
# include the keyword of impactlab.analytic.invert (and of the JSON's inputs), so that a
# result's inputs can be written back into a measurement file
FIELDS: dict[str, tuple[str, tuple[str, ...], str]] = {
    "angle": ("degree", ("angle",), "--angle"),
    "v_i": ("m/s", ("vi", "v_i"), "--vi"),
    "e": ("", ("e",), "--e"),
    "mu": ("", ("mu",), "--mu"),
    "delta_p": ("m", ("delta_p", "delta-p"), "--delta-p"),
    "L_s": ("m", ("ls", "L_s", "l_s", "sliding_length", "sliding-length"), "--ls"),
    "dv_cy": ("m/s", ("dv_cy", "dv-cy"), "--dv-cy"),
    "vt_in": ("m/s", ("vt_in", "vt-in"), "--vt-in"),
}
ALIAS = {k: name for name, (_, keys, _) in FIELDS.items() for k in keys}
#: input name -> keyword of impactlab.analytic.invert, where they differ
ARGUMENTS = {"L_s": "sliding_length"}
#: the other keys of a measurement file (``n_samples``: the JSON's and Python's ``samples``)
EXTRA = ("case", "gravity", "measure", "samples", "n_samples", "seed", "correlation")
#: the inputs a correlation may pair, by keyword of impactlab.analytic.invert (in this order)
CORRELATED = tuple(ARGUMENTS.get(k, k) for k in FIELDS)
#: a pair of correlated inputs (keywords of impactlab.analytic.invert, in CORRELATED's order)
Pair = tuple[str, str]
#: what ``measure`` (``--measure``) may be: what the sliding length measures
MEASURES = ("slip", "travel")
#: where a measurement file's value is named in an error
IN_FILE = "in the measurement file"
#: a number and what follows it (its unit) in a command-line value
_NUMBER_AND_UNIT = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\s*(.*)")
#: a unit to show in the example of an error about a bare sigma
EXAMPLE_UNITS = {"v_i": "m/s", "delta_p": "um", "L_s": "um", "dv_cy": "m/s", "vt_in": "m/s"}
#: a sigma with its unit, for the help
EXAMPLE_SIGMAS = {
    "v_i": "0.01 m/s",
    "delta_p": "0.5 um",
    "L_s": "50 um",
    "dv_cy": "0.005 m/s",
    "vt_in": "0.005 m/s",
}


def _inversion_angle(value: Any, name: str) -> float:
    """The rod's angle [rad] of an inversion: with its unit, in (0, 90) deg, open at both ends
    (the range of ``impactlab.analytic.invert``: at 90 deg the tip cannot slide)."""
    th = any_angle(value, name)
    if not 0.0 < th < 0.5 * math.pi:
        why = (
            "at 90 deg it stands vertical and its tip cannot slide"
            if th >= 0.5 * math.pi
            else "at 0 deg it lies on the flat, and below 0 its tip points up"
        )
        hint = past_normal_inversion(th) if 0.5 * math.pi < th < math.pi else ""
        raise UserError(
            f"{name} must lie in (0, 90) deg, open at both ends (the rod tilted: {why}), "
            f"got {str(value).strip()}{hint}"
        )
    return th


def _angle_sigma(value: Any, name: str) -> float:
    """The standard deviation of the rod's angle [rad]: with its unit, finite and >= 0 (0: the
    angle taken as exact, as any other zero sigma)."""
    sigma = any_angle(value, name)
    if not (math.isfinite(sigma) and sigma >= 0.0):
        raise UserError(
            f"{name} must be a standard deviation >= 0 deg (0: the angle taken as exact), got "
            f"{str(value).strip()}"
        )
    return sigma


def parse_value(value: Any, unit: str, name: str) -> float:
    if unit == "degree":
        if name.endswith(IN_FILE) and _is_bare(value):  # "angle = 20": as the file writes it
            raise UserError(
                f"{name.removesuffix(IN_FILE).strip()} = {value!r} {IN_FILE} has no unit: give a "
                "unit, e.g. '20 deg' or '0.35 rad'"
            )
        if name.startswith(("--sigma-", "sigma.")):  # a standard deviation, not the angle
            return _angle_sigma(value, name)
        return _inversion_angle(value, name)
    if unit:
        return quantity(value, unit, name)  # type: ignore[return-value]
    if isinstance(value, str):
        if (number := bare_number(value)) is None:
            raise UserError(f"{name} must be a number, got {value!r}")
        return number
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise UserError(f"{name} must be a number, got {value!r}")
    return float(value)


def _unit_text(value: Any) -> str | None:
    """The unit written after the number of a command-line value ("1400 um" -> "um"); None for
    a bare number (or a value that is not text)."""
    if not isinstance(value, str):
        return None
    m = _NUMBER_AND_UNIT.fullmatch(read_minus(value).strip())  # "\u2212141 cm/s": cm/s
    unit = m.group(1).strip() if m is not None else ""
    return unit or None


def _is_bare(value: Any) -> bool:
    """True for a number, or text that is only a number (``"50"``, ``"\u22120.5"``)."""
    return bare_number(str(value)) is not None


def parse_sigma(name: str, sigma: Any, value: Any) -> float:
    """A command-line ``--sigma-*`` in SI: with its unit, or a bare number in the unit its value
    was given in on the command line (SI for a bare value); a bare sigma of a dimensional input
    whose value comes from --case or --file is refused (its unit would be a guess). An angle's
    sigma needs its unit, as the angle."""
    unit, _, flag = FIELDS[name]
    option = "--sigma-" + flag[2:]
    if not unit or unit == "degree" or not _is_bare(sigma):
        return parse_value(sigma, unit, option)
    if value is None:
        raise UserError(
            f"{option} {str(sigma).strip()} has no unit and {flag} comes from --case or --file: "
            f"give its unit, e.g. {option} '{str(sigma).strip()} {EXAMPLE_UNITS[name]}'"
        )
    given = _unit_text(value)
    return parse_value(f"{str(sigma).strip()} {given}" if given else sigma, unit, option)


def _measured(
    table: dict[str, Any], where: str, prefix: str = "", more: tuple[str, ...] = ()
) -> dict[str, float]:
    """The measured values (or their sigmas) of a measurement file's table, by input name."""
    out: dict[str, float] = {}
    seen: dict[str, str] = {}
    for key, val in table.items():
        if key not in ALIAS:
            allowed = ", ".join(sorted([*ALIAS, *more]))
            raise UserError(f"unknown key {key!r} in {where}; allowed: {allowed}")
        _once(ALIAS[key], key, seen, where)
        out[ALIAS[key]] = parse_value(val, FIELDS[ALIAS[key]][0], f"{prefix}{key} {IN_FILE}")
    return out


def _once(name: str, key: str, seen: dict[str, str], where: str) -> None:
    """UserError when two keys of one table (``ls`` and ``sliding_length``) give the same
    input; else ``key`` is recorded in ``seen`` (input name -> key)."""
    if name in seen:
        raise UserError(
            f"{seen[name]!r} and {key!r} in {where} give the same input ({FIELDS[name][2]}); "
            "give it once"
        )
    seen[name] = key


def check_measure(value: Any, name: str) -> str:
    """``value`` as a measure (``"slip"`` or ``"travel"``); UserError naming ``name``."""
    if value not in MEASURES:
        raise UserError(f"{name} must be 'slip' or 'travel', got {value!r}")
    return str(value)


def _file_sigmas(table: dict[str, Any], values: dict[str, Any]) -> dict[str, float]:
    """The ``[sigma]`` table of a measurement file in SI, read as ``--sigma-*`` are: a bare
    number of a dimensional input is in the unit its value is written in, in the same file
    (``ls = "1400 um"`` and ``[sigma] ls = 50``: 50 um; a bare value: SI), and is refused when
    the file does not give that value (its unit would be a guess)."""
    raw = {ALIAS.get(k, k): v for k, v in values.items()}
    out = _measured({k: v for k, v in table.items() if k not in ALIAS}, "[sigma]", "sigma.")
    seen: dict[str, str] = {}
    for key, sigma in table.items():
        if key not in ALIAS:
            continue
        name = ALIAS[key]
        _once(name, key, seen, "[sigma]")
        unit = FIELDS[name][0]
        if not unit or unit == "degree" or not _is_bare(sigma):
            out[name] = parse_value(sigma, unit, f"sigma.{key} {IN_FILE}")
            continue
        if name not in raw:
            value_keys = " or ".join(repr(k) for k in FIELDS[name][1][:2])
            raise UserError(
                f"sigma.{key} = {sigma!r} in the measurement file has no unit and the file gives "
                f"no {value_keys} to take it from: give its unit, e.g. "
                f"{key} = '{str(sigma).strip()} {EXAMPLE_UNITS[name]}' in [sigma]"
            )
        given = _unit_text(raw[name])
        text = f"{str(sigma).strip()} {given}" if given else sigma
        out[name] = parse_value(text, unit, f"sigma.{key} {IN_FILE}")
    return out


def _quantity_tables(values: dict[str, Any], tables: dict[str, Any]) -> dict[str, Any]:
    """``values`` with each ``{value, unit, sigma}`` table (the JSON output's form of an input,
    ``inputs``) written as the quantity text ``"0.349 rad"``; its ``sigma``, in the same unit,
    moves into ``tables["sigma"]`` (given there too: refused)."""
    out = dict(values)
    for key, val in values.items():
        if not isinstance(val, dict):
            continue
        if "value" not in val or set(val) - {"value", "unit", "sigma"}:
            raise UserError(
                f"{key} {IN_FILE} is a table with {sorted(val)}: a quantity's table holds "
                "value, unit and sigma (as the JSON output writes it), e.g. "
                f'{key} = {{ value = 0.35, unit = "rad" }}'
            )
        unit = str(val.get("unit", "1")).strip()
        bare = unit in ("", "1", "-")
        out[key] = val["value"] if bare else f"{val['value']!r} {unit}"
        if "sigma" in val:
            sigmas = tables.setdefault("sigma", {})
            if key in sigmas:
                raise UserError(f"{key}'s sigma {IN_FILE} is given twice, in its table and in "
                                "[sigma]; give it once")  # fmt: skip
            sigmas[key] = val["sigma"] if bare else f"{val['sigma']!r} {unit}"
    return out


def from_file(
    data: dict[str, Any],
) -> tuple[dict[str, float], dict[str, float], dict[str, float], dict[str, Any], dict[str, str]]:
    """(values, sigmas, rod, extra: case, gravity, measure, samples, seed, correlation (as
    :func:`file_correlations` reads it), keys) of a measurement file; ``keys``: each given
    value's key as written (input name -> key, and ``"sigma." + name`` -> ``"sigma." + key``),
    to name it in errors."""
    tables = {k: v for k, v in data.items() if k in ("sigma", "rod")}
    extra = {k: v for k, v in data.items() if k in EXTRA}
    check_booleans(extra, ("gravity",), "the measurement file")
    if "measure" in extra:
        check_measure(extra["measure"], f"measure {IN_FILE}")
    if "samples" in extra and "n_samples" in extra:
        raise UserError(f"'samples' and 'n_samples' {IN_FILE} are the same count; give one")
    if "correlation" in extra:
        extra["correlation"] = file_correlations(extra["correlation"])
    values = {k: v for k, v in data.items() if k not in tables and k not in extra}
    for name, table in tables.items():
        if not isinstance(table, dict):
            raise UserError(f"[{name}] must be a table")
    values = _quantity_tables(values, tables)
    file_values = _measured(values, "the measurement file", more=("sigma", "rod", *EXTRA))
    sigmas = _file_sigmas(tables.get("sigma", {}), values)
    rod = parse_rod_table(tables.get("rod", {}), "rod.")
    keys = {ALIAS[k]: k for k in values}
    keys |= {f"sigma.{ALIAS[k]}": f"sigma.{k}" for k in tables.get("sigma", {}) if k in ALIAS}
    return file_values, sigmas, rod, extra, keys


def _input_name(name: Any, where: str) -> str:
    """``name`` (an option's name or a key of a measurement file: ``ls``, ``sliding_length``)
    as the keyword of ``impactlab.analytic.invert``; UserError naming ``where`` otherwise."""
    key = name.strip() if isinstance(name, str) else name
    if not isinstance(key, str) or key not in ALIAS:
        raise UserError(
            f"{where}: unknown input {name!r}; allowed: {', '.join(CORRELATED)} (or their "
            "option names: vi, ls, delta-p, ...)"
        )
    return ARGUMENTS.get(ALIAS[key], ALIAS[key])


def _coefficient(rho: Any, where: str) -> float:
    """``rho`` (a number or its text) as a correlation coefficient in [-1, 1]."""
    if isinstance(rho, str):
        number = bare_number(rho)
    elif isinstance(rho, int | float) and not isinstance(rho, bool):
        number = float(rho)
    else:
        number = None
    if number is None or not -1.0 <= number <= 1.0:  # NaN is refused too
        raise UserError(f"{where}: the coefficient must be a number in [-1, 1], got {rho!r}")
    return number


def _add_pair(out: dict[Pair, float], names: Any, rho: Any, where: str) -> None:
    """Add the pair ``names`` (two input names) with the coefficient ``rho`` to ``out``; a pair
    of one input with itself, or a pair already in ``out`` (either order), is refused."""
    if not isinstance(names, list | tuple) or len(names) != 2:
        raise UserError(f"{where}: a correlation pairs two inputs, got {names!r}")
    a, b = (_input_name(n, where) for n in names)
    if a == b:
        raise UserError(f"{where} pairs {a} with itself (its coefficient is always 1): give two "
                        "different inputs")  # fmt: skip
    pair = (a, b) if CORRELATED.index(a) < CORRELATED.index(b) else (b, a)
    if pair in out:
        raise UserError(f"{where}: the pair ({a}, {b}) is given twice; give it once")
    out[pair] = _coefficient(rho, where)


def parse_correlations(items: list[str] | None) -> dict[Pair, float]:
    """The ``--correlation NAME,NAME=COEFFICIENT`` options (``e,mu=-0.3``), by pair of keywords
    of ``impactlab.analytic.invert``: the coefficients of the inputs as given."""
    out: dict[Pair, float] = {}
    for item in items or []:
        names, eq, rho = str(item).partition("=")
        if not eq or names.count(",") != 1:
            raise UserError(
                f"--correlation must be NAME,NAME=COEFFICIENT (e.g. --correlation e,mu=-0.3), "
                f"got {item!r}"
            )
        _add_pair(out, names.split(","), rho.strip(), f"--correlation {item!r}")
    return out


def file_correlations(value: Any) -> dict[Pair, float]:
    """A measurement file's ``correlation``: a table of ``"NAME,NAME" = COEFFICIENT``
    (``[correlation]`` with ``"e,dv_cy" = 0.94``) or the JSON's list of ``{inputs = [a, b],
    coefficient = {value, unit = "1"}}`` (the coefficient also a plain number), by pair of
    keywords of ``impactlab.analytic.invert``."""
    where = f"correlation {IN_FILE}"
    out: dict[Pair, float] = {}
    if isinstance(value, dict):
        for key, rho in value.items():
            _add_pair(out, str(key).split(","), rho, f"correlation {key!r} {IN_FILE}")
        return out
    if not isinstance(value, list):
        raise UserError(
            f"{where} must be a table ('\"e,dv_cy\" = 0.94' under [correlation]) or the JSON's "
            f"list of {{inputs, coefficient}}, got {value!r}"
        )
    for i, entry in enumerate(value):
        at = f"correlation[{i}] {IN_FILE}"
        if not isinstance(entry, dict) or set(entry) != {"inputs", "coefficient"}:
            raise UserError(f"{at} must hold inputs and coefficient (as the JSON writes "
                            f"them), got {entry!r}")  # fmt: skip
        rho = entry["coefficient"]
        if isinstance(rho, dict):
            if "value" not in rho or set(rho) - {"value", "unit"} or rho.get("unit", "1") != "1":
                raise UserError(f"{at}: the coefficient's table holds value and unit \"1\", "
                                f"got {rho!r}")  # fmt: skip
            rho = rho["value"]
        _add_pair(out, entry["inputs"], rho, at)
    return out


def correlation_label(cli: bool, file: bool) -> str:
    """Where the correlations came from, to name them in an error of ``invert``."""
    given = ["--correlation"] * cli + [f"correlation {IN_FILE}"] * file
    return " and ".join(given) or "correlation"
