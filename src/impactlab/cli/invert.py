"""``impactlab invert``: impact duration and mean force from a measured dent (paper Eqs. 12, 29).

Inputs merge as case < file < command line. Dimensional values carry their unit ("22 um"); an
angle without a unit is refused (20 could be degrees or radians). A bare ``--sigma-*`` number is
in the unit its value was given in on the command line (``--ls "1400 um" --sigma-ls 50``: 50 um),
and is refused when the value comes from ``--case`` or ``--file``.
"""

from __future__ import annotations

import json
import re
import warnings
from pathlib import Path
from typing import Any

import typer

from impactlab._display import field_row
from impactlab._json import to_json
from impactlab._validation import ImplausibleInputWarning
from impactlab.analytic import InversionResult, invert
from impactlab.bodies import PAPER_ROD, Rod
from impactlab.cli._common import (
    SI_UNITS,
    UserError,
    angle_quantity,
    load_toml,
    parse_rod_table,
    print_rows,
    quantity,
    rod_option,
)
from impactlab.cli.config_values import check_booleans
from impactlab.cli.invert_output import inversion_json, print_inversion

# input name -> (SI unit used for parsing, accepted TOML keys, command-line option)
_FIELDS: dict[str, tuple[str, tuple[str, ...], str]] = {
    "angle": ("degree", ("angle",), "--angle"),
    "v_i": ("m/s", ("vi", "v_i"), "--vi"),
    "e": ("", ("e",), "--e"),
    "mu": ("", ("mu",), "--mu"),
    "delta_p": ("m", ("delta_p", "delta-p"), "--delta-p"),
    "L_s": ("m", ("ls", "L_s", "l_s"), "--ls"),
    "dv_cy": ("m/s", ("dv_cy", "dv-cy"), "--dv-cy"),
}
_ALIAS = {k: name for name, (_, keys, _) in _FIELDS.items() for k in keys}
#: input name -> keyword of impactlab.analytic.invert, where they differ
_ARGUMENTS = {"L_s": "sliding_length"}
#: the other keys of a measurement file
_EXTRA = ("case", "gravity", "samples", "seed")
#: a number and what follows it (its unit) in a command-line value
_NUMBER_AND_UNIT = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\s*(.*)")
#: a unit to show in the example of an error about a bare sigma
_EXAMPLE_UNITS = {"v_i": "m/s", "delta_p": "um", "L_s": "um", "dv_cy": "m/s"}
#: a sigma with its unit, for the help
_EXAMPLE_SIGMAS = {"v_i": "0.01 m/s", "delta_p": "0.5 um", "L_s": "50 um", "dv_cy": "0.005 m/s"}
#: the inputs that T needs (F needs e or dv_cy besides)
_REQUIRED = ("angle", "v_i", "mu", "delta_p", "L_s")


def _parse(value: Any, unit: str, name: str) -> float:
    if unit == "degree":
        return angle_quantity(value, name)
    if unit:
        return quantity(value, unit, name)  # type: ignore[return-value]
    if isinstance(value, str):
        try:
            return float(value)
        except ValueError:
            raise UserError(f"{name} must be a number, got {value!r}") from None
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise UserError(f"{name} must be a number, got {value!r}")
    return float(value)


def _unit_text(value: Any) -> str | None:
    """The unit written after the number of a command-line value ("1400 um" -> "um"); None for
    a bare number (or a value that is not text)."""
    if not isinstance(value, str):
        return None
    m = _NUMBER_AND_UNIT.fullmatch(value.strip())
    unit = m.group(1).strip() if m is not None else ""
    return unit or None


def _is_bare(value: Any) -> bool:
    try:
        float(str(value).strip())
    except ValueError:
        return False
    return True


def _parse_sigma(name: str, sigma: Any, value: Any) -> float:
    """A command-line ``--sigma-*`` in SI: with its unit, or a bare number in the unit its value
    was given in on the command line (SI for a bare value); a bare sigma of a dimensional input
    whose value comes from --case or --file is refused (its unit would be a guess). An angle's
    sigma needs its unit, as the angle."""
    unit, _, flag = _FIELDS[name]
    option = "--sigma-" + flag[2:]
    if not unit or unit == "degree" or not _is_bare(sigma):
        return _parse(sigma, unit, option)
    if value is None:
        raise UserError(
            f"{option} {str(sigma).strip()} has no unit and {flag} comes from --case or --file: "
            f"give its unit, e.g. {option} '{str(sigma).strip()} {_EXAMPLE_UNITS[name]}'"
        )
    given = _unit_text(value)
    return _parse(f"{str(sigma).strip()} {given}" if given else sigma, unit, option)


def _measured(
    table: dict[str, Any], where: str, prefix: str = "", more: tuple[str, ...] = ()
) -> dict[str, float]:
    """The measured values (or their sigmas) of a TOML table, by input name."""
    out: dict[str, float] = {}
    for key, val in table.items():
        if key not in _ALIAS:
            allowed = ", ".join(sorted([*_ALIAS, *more]))
            raise UserError(f"unknown key {key!r} in {where}; allowed: {allowed}")
        out[_ALIAS[key]] = _parse(val, _FIELDS[_ALIAS[key]][0], prefix + key)
    return out


def _from_file(
    data: dict[str, Any],
) -> tuple[dict[str, float], dict[str, float], dict[str, float], dict[str, Any]]:
    """(values, sigmas, rod, extra: case, gravity, samples, seed) of a measurement file."""
    tables = {k: v for k, v in data.items() if k in ("sigma", "rod")}
    extra = {k: v for k, v in data.items() if k in _EXTRA}
    check_booleans(extra, ("gravity",), "the measurement file")
    values = {k: v for k, v in data.items() if k not in tables and k not in extra}
    for name, table in tables.items():
        if not isinstance(table, dict):
            raise UserError(f"[{name}] must be a table")
    sigmas = _measured(tables.get("sigma", {}), "[sigma]", "sigma.")
    rod = parse_rod_table(tables.get("rod", {}), "rod.")
    file_values = _measured(values, "the measurement file", more=("sigma", "rod", *_EXTRA))
    return file_values, sigmas, rod, extra


def _rod(r: dict[str, float]) -> Rod:
    """The paper's rod with the given properties replaced (without an explicit inertia the
    slender-rod m L^2 / 12 of the new mass and length)."""
    if not r:
        return PAPER_ROD
    return Rod(
        mass=r.get("mass", PAPER_ROD.mass),
        length=r.get("length", PAPER_ROD.length),
        tip_radius=r.get("tip_radius", PAPER_ROD.tip_radius),
        inertia=r.get("inertia"),
    )


def _check_complete(have: set[str], sigmas: set[str]) -> None:
    """Every input T and F need is there (checked before any value is parsed)."""
    missing = [n for n in _REQUIRED if n not in have]
    if missing:
        raise UserError(
            "missing input(s): "
            + ", ".join(_FIELDS[m][2] for m in missing)
            + " (or use --case paper-20|paper-45|paper-70 or --file)"
        )
    if "e" not in have and "dv_cy" not in have:
        raise UserError("missing input: --e (or --dv-cy) is needed for the mean force")
    alone = sorted(sigmas - have)
    if alone:
        raise UserError(f"an uncertainty is given for {', '.join(alone)} but not its value")


def run_invert(
    *,
    case: str | None = None,
    file: Path | None = None,
    values: dict[str, Any] | None = None,
    sigmas: dict[str, Any] | None = None,
    rod: dict[str, Any] | None = None,
    gravity: bool | None = None,
    samples: int | None = None,
    seed: int | None = None,
) -> tuple[InversionResult, dict[str, tuple[float, float]]]:
    """Merge case < file < command line and call :func:`impactlab.analytic.invert` (the paper
    case's negative dent depth and sliding length enter as magnitudes). Returns the result and
    the inputs as given (SI, signs kept: the echo), as ``(value, sigma)`` by keyword."""
    v, s, r, extra = _from_file(load_toml(file, "--file"))
    case = case or extra.get("case")
    if case is not None:
        from impactlab.paper.data import get_case  # lazy: a fast CLI start

        x = get_case(str(case))
        paper = {"angle": x.angle, "v_i": x.v_i, "e": x.e, "mu": x.mu}
        v = {**paper, "delta_p": abs(x.delta_p), "L_s": abs(x.L_s), **v}
    cli_v = {k: val for k, val in (values or {}).items() if val is not None}
    cli_s = {k: val for k, val in (sigmas or {}).items() if val is not None}
    _check_complete(set(v) | set(cli_v), set(s) | set(cli_s))
    v.update({k: _parse(val, _FIELDS[k][0], _FIELDS[k][2]) for k, val in cli_v.items()})
    s.update({k: _parse_sigma(k, val, cli_v.get(k)) for k, val in cli_s.items()})
    r.update(parse_rod_table({k: val for k, val in (rod or {}).items() if val is not None}, "--"))
    kwargs: dict[str, Any] = {_ARGUMENTS.get(k, k): (val, s.get(k, 0.0)) for k, val in v.items()}
    result = invert(
        **kwargs,
        rod=_rod(r),
        gravity=gravity if gravity is not None else bool(extra.get("gravity", False)),
        n_samples=samples if samples is not None else _file_count(extra, "samples", 20_000, 100),
        seed=seed if seed is not None else _file_count(extra, "seed", 0, 0),
    )
    return result, kwargs


def _file_count(extra: dict[str, Any], key: str, default: int, least: int) -> int:
    """The integer ``key`` of a measurement file (``samples``, ``seed``), ``default`` when it
    is absent; UserError naming the key for a value that is not an integer >= ``least`` (a
    float such as 200.7 or 1.5 is refused, not rounded)."""
    value = extra.get(key, default)
    if isinstance(value, bool) or not isinstance(value, int) or value < least:
        raise UserError(
            f"{key} in the measurement file must be an integer >= {least}, got {value!r}"
        )
    return value


#: Help of the measured inputs' options.
_HELP = {
    "angle": "Rod-to-flat angle with its unit: '20 deg' or '0.35 rad' (a bare number is "
    "refused; required unless --case or --file gives it).",
    "v_i": "Drop velocity of the tip ('-1.41 m/s'; bare number: m/s; the sign is ignored; "
    "required unless --case or --file gives it).",
    "e": "Coefficient of restitution (tip, normal); required for F unless --dv-cy is given.",
    "mu": "Friction coefficient (paper Eq. 28); required unless --case or --file gives it.",
    "delta_p": "Permanent dent depth, a magnitude ('22 um'; bare number: m; the paper prints "
    "-22 um; required unless --case or --file gives it).",
    "L_s": "Sliding length L_s, a magnitude ('1400 um'; bare number: m; the paper prints "
    "-1400 um; required unless --case or --file gives it).",
    "dv_cy": "Change of the centre-of-mass vertical velocity ('0.62 m/s'; bare number: m/s; "
    "optional): F from Eq. 29.",
}


def _sigma_help(name: str) -> str:
    """The help of ``--sigma-*``: how its unit is read (``_parse_sigma``)."""
    unit, _, flag = _FIELDS[name]
    if not unit:
        return f"Std. dev. of {flag} (default 0)."
    if unit == "degree":
        return f"Std. dev. of {flag} with its unit ('0.5 deg'; a bare number is refused)."
    ex = _EXAMPLE_UNITS[name]
    return (
        f"Std. dev. of {flag}, e.g. '{_EXAMPLE_SIGMAS[name]}' (default 0). A bare number is in "
        "the unit of "
        f"{flag} as given on the command line ('... {ex}': {ex}; a bare {flag}: {unit}); with "
        f"{flag} from --case or --file it needs its unit."
    )


def _measured_option(name: str, *, sigma: bool = False) -> Any:
    """The option of a measured input (``--vi``), or of its standard deviation (``--sigma-vi``)."""
    flag = _FIELDS[name][2]
    if sigma:
        return typer.Option(None, "--sigma-" + flag[2:], help=_sigma_help(name))
    return typer.Option(None, flag, help=_HELP[name])


def invert_cmd(
    angle: str | None = _measured_option("angle"),
    vi: str | None = _measured_option("v_i"),
    e: str | None = _measured_option("e"),
    mu: str | None = _measured_option("mu"),
    delta_p: str | None = _measured_option("delta_p"),
    ls: str | None = _measured_option("L_s"),
    dv_cy: str | None = _measured_option("dv_cy"),
    sigma_angle: str | None = _measured_option("angle", sigma=True),
    sigma_vi: str | None = _measured_option("v_i", sigma=True),
    sigma_e: str | None = _measured_option("e", sigma=True),
    sigma_mu: str | None = _measured_option("mu", sigma=True),
    sigma_delta_p: str | None = _measured_option("delta_p", sigma=True),
    sigma_ls: str | None = _measured_option("L_s", sigma=True),
    sigma_dv_cy: str | None = _measured_option("dv_cy", sigma=True),
    mass: str | None = rod_option("mass"),
    length: str | None = rod_option("length"),
    tip_radius: str | None = rod_option("tip_radius"),
    inertia: str | None = rod_option("inertia"),
    case: str | None = typer.Option(
        None, "--case", help="Start from the paper's measurements: paper-20, paper-45 or paper-70."
    ),
    file: Path | None = typer.Option(
        None, "--file", help="TOML file of measurements (keys as the options; [sigma], [rod])."
    ),
    gravity: bool | None = typer.Option(
        None,
        "--gravity/--no-gravity",
        help="Gravity during the contact (default: no, as in the paper).",
    ),
    samples: int | None = typer.Option(
        None, "--samples", min=100, help="Monte Carlo samples (default 20000; at least 100)."
    ),
    seed: int | None = typer.Option(None, "--seed", help="Monte Carlo seed (default 0)."),
    flat: str | None = typer.Option(
        None,
        "--flat",
        help="Flat material preset (e.g. aisi-1010; with --case the paper's flat): also "
        "simulate the impact (ghaednia law, the measured angle, v_i and mu) and warn when T "
        "or F is more than 3 times off.",
    ),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output (SI)."),
) -> None:
    """Impact duration T and mean normal force F from a measured oblique impact of the rod.

    Inverts the paper's Eq. 12 (corrected) for T and Eq. 29 (or the rigid-body identity
    F T = (1 + e)|v_i| / K_y) for F, with first-order and Monte Carlo uncertainties.

    Example: impactlab invert --angle "20 deg" --vi "-1.41 m/s" --e 0.5 --mu 0.2
    --delta-p "22 um" --ls "1400 um" --sigma-ls "50 um"
    """
    inputs = (angle, vi, e, mu, delta_p, ls, dv_cy)
    sigmas = (sigma_angle, sigma_vi, sigma_e, sigma_mu, sigma_delta_p, sigma_ls, sigma_dv_cy)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ImplausibleInputWarning)
        res, given = run_invert(
            case=case,
            file=file,
            values=dict(zip(_FIELDS, inputs, strict=True)),
            sigmas=dict(zip(_FIELDS, sigmas, strict=True)),
            rod={"mass": mass, "length": length, "tip_radius": tip_radius, "inertia": inertia},
            gravity=gravity,
            samples=samples,
            seed=seed,
        )
    found = _inversion_warnings(caught)
    if flat is None and case is not None:
        flat = "aisi-1010"  # the paper's flat
    model, compared = _compare_with_engine(res, flat) if flat is not None else ({}, [])
    found += compared
    if as_json:
        data = inversion_json(res, given)
        if model:
            data["model"] = to_json(model, SI_UNITS)
        print(json.dumps({**data, "warnings": found}, indent=2))
    else:
        print_inversion(res, given)
        if model:
            rows = [(f"model {k} ({model['law']})", *field_row(k, v, SI_UNITS[k])[1:])
                    for k, v in model.items() if isinstance(v, float)]  # fmt: skip
            print_rows(rows, f"simulated impact on {model['flat']}")
    for text in found:
        typer.echo(f"warning: {text}", err=True)


def _inversion_warnings(caught: list[warnings.WarningMessage]) -> list[str]:
    """The texts of the inversion's ImplausibleInputWarnings (for the JSON's ``warnings`` and
    stderr); any other warning is shown again as Python shows it."""
    texts = []
    for w in caught:
        if issubclass(w.category, ImplausibleInputWarning):
            texts.append(str(w.message))
        else:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
    return texts


def _compare_with_engine(res: InversionResult, flat: str) -> tuple[dict[str, Any], list[str]]:
    """The impact simulated with the measured angle, tip velocity v_i (no spin) and mu on
    ``flat``, and the warnings of ``experiment.consistency`` on the inferred T and F."""
    from impactlab.dynamics import simulate  # lazy: a fast CLI start
    from impactlab.experiment.consistency import check_against_model
    from impactlab.materials import get_material

    try:
        material = get_material(flat.strip().lower())
    except ValueError as exc:
        raise UserError(f"--flat: {exc}") from None
    rod = res.rod
    body = Rod(length=rod["length"], tip_radius=rod["tip_radius"], mass=rod["mass"],
               inertia=rod.get("inertia"))  # fmt: skip
    law = "ghaednia"
    try:
        r = simulate(body, material, law=law, mu=res.inputs["mu"][0],
                     angle=res.inputs["angle"][0], velocity=(0.0, -abs(res.inputs["v_i"][0])),
                     history=False)  # fmt: skip
    except ValueError as exc:
        raise UserError(f"--flat: the simulated impact failed: {exc}") from None
    model: dict[str, Any] = {"law": law, "flat": material.name}
    model |= {"duration": r.duration, "mean_force": r.mean_force, "e": r.e, "delta_p": r.delta_p}
    warnings = check_against_model(
        res.duration, res.mean_force, model_duration=r.duration, model_force=r.mean_force,
        law=law, sigma_duration=res.sigma_T_linear,
    )  # fmt: skip
    return model, warnings


def register(app: typer.Typer) -> None:
    """Add ``impactlab invert`` to ``app``."""
    app.command("invert")(invert_cmd)
