"""``impactlab invert``: impact duration and mean force from a measured dent (paper Eqs. 12, 29).

Inputs merge as case < file < command line. Dimensional values carry their unit ("22 um"); an
angle without a unit is refused (20 could be degrees or radians). A bare ``--sigma-*`` number is
in the unit its value was given in on the command line (``--ls "1400 um" --sigma-ls 50``: 50 um),
and is refused when the value comes from ``--case`` or ``--file``. The same holds in a ``--file``:
a bare number of its ``[sigma]`` table is in the unit its value is written in, in that file, and
is refused when the file does not give the value.
"""

from __future__ import annotations

import json
import warnings
from pathlib import Path
from typing import Any

import typer

from impactlab._display import field_row
from impactlab._json import to_json
from impactlab._validation import ImplausibleInputWarning
from impactlab.analytic import InversionResult, invert
from impactlab.analytic.inversion import MAX_SAMPLES
from impactlab.analytic.result_json import inversion_json
from impactlab.cli._common import (
    SI_UNITS,
    UserError,
    load_toml,
    parse_rod_table,
    print_rows,
    rod_option,
)
from impactlab.cli.invert_checks import (
    check_complete,
    compare_with_engine,
    inversion_rod,
    inversion_warnings,
)
from impactlab.cli.invert_inputs import (
    ARGUMENTS,
    EXAMPLE_SIGMAS,
    EXAMPLE_UNITS,
    FIELDS,
    IN_FILE,
    check_measure,
    correlation_label,
    from_file,
    parse_correlations,
    parse_sigma,
    parse_value,
)
from impactlab.cli.invert_output import inversion_doubts, print_inversion
from impactlab.cli.printing import print_wrapped


def run_invert(
    *,
    case: str | None = None,
    file: Path | None = None,
    values: dict[str, Any] | None = None,
    sigmas: dict[str, Any] | None = None,
    rod: dict[str, Any] | None = None,
    gravity: bool | None = None,
    measure: str | None = None,
    samples: int | None = None,
    seed: int | None = None,
    correlation: list[str] | None = None,
) -> tuple[InversionResult, dict[str, tuple[float, float]]]:
    """Merge case < file < command line and call :func:`impactlab.analytic.invert` (the paper
    case's negative dent depth and sliding length enter as magnitudes; ``correlation``: the
    ``--correlation`` texts, each pair replacing the file's coefficient of that pair). Returns
    the result and the inputs as given (SI, signs kept: the echo), as ``(value, sigma)`` by
    keyword. An error of ``invert`` names each input as the user gave it (``--ls``, ``ls in the
    measurement file``; ``--correlation``)."""
    v, s, r, extra, keys = from_file(load_toml(file, "--file"))
    case = case or extra.get("case")
    labels: dict[str, str] = {}
    if case is not None:
        from impactlab.paper.data import get_case  # lazy: a fast CLI start

        x = get_case(str(case))
        paper = {"angle": x.angle, "v_i": x.v_i, "e": x.e, "mu": x.mu}
        v = {**paper, "delta_p": abs(x.delta_p), "L_s": abs(x.L_s), **v}
        labels |= {k: f"{FIELDS[k][2]} of --case {case}" for k in FIELDS}
    labels |= {k: f"{key} {IN_FILE}" for k, key in keys.items()}
    cli_v = {k: val for k, val in (values or {}).items() if val is not None}
    cli_s = {k: val for k, val in (sigmas or {}).items() if val is not None}
    labels |= {k: FIELDS[k][2] for k in cli_v}
    labels |= {f"sigma.{k}": "--sigma-" + FIELDS[k][2][2:] for k in cli_s}
    cli_c, file_c = parse_correlations(correlation), extra.get("correlation", {})
    labels["correlation:"] = correlation_label(bool(cli_c), bool(file_c))
    check_complete(set(v) | set(cli_v), set(s) | set(cli_s))
    v.update({k: parse_value(val, FIELDS[k][0], FIELDS[k][2]) for k, val in cli_v.items()})
    s.update({k: parse_sigma(k, val, cli_v.get(k)) for k, val in cli_s.items()})
    cli_r = {k: val for k, val in (rod or {}).items() if val is not None}
    r.update(parse_rod_table(cli_r, "--"))
    body = inversion_rod(r, cli_r)
    kwargs: dict[str, Any] = {ARGUMENTS.get(k, k): (val, s.get(k, 0.0)) for k, val in v.items()}
    if measure is not None:
        check_measure(measure, "--measure")
    if seed is not None and seed < 0:
        raise UserError(f"--seed must be an integer >= 0, got {seed}")
    samples_key = "n_samples" if "n_samples" in extra else "samples"
    if samples is None:
        samples = _file_count(extra, samples_key, 20_000, 100)
        samples_label = f"{samples_key} in the measurement file"
    else:
        samples_label = "--samples"
    if samples > MAX_SAMPLES:  # about 125 bytes a sample: refused before any is drawn
        raise UserError(
            f"{samples_label} must be at most {MAX_SAMPLES:,} (about "
            f"{MAX_SAMPLES * 125 / 1e9:.2g} GB of memory), got {samples:,}; the Monte Carlo's "
            "mean and 95 % interval settle long before (default 20,000)"
        )
    try:
        result = invert(
            **kwargs,
            rod=body,
            gravity=gravity if gravity is not None else bool(extra.get("gravity", False)),
            measure=measure or extra.get("measure", "slip"),
            n_samples=samples,
            seed=seed if seed is not None else _file_count(extra, "seed", 0, 0),
            correlation={**file_c, **cli_c} or None,
        )
    except ValueError as exc:  # "mu must be finite": the input as the user gave it
        raise UserError(_as_given(str(exc), labels)) from None
    return result, kwargs


def _as_given(message: str, labels: dict[str, str]) -> str:
    """An error of ``invert`` whose leading keyword (``sliding_length must ...``, ``the sigma of
    e = ...``) is spelled as the user gave it (``labels``: input name or ``sigma.`` + name ->
    its option or file key; ``correlation:``: where the correlations came from)."""
    if message.startswith("correlation: "):
        return labels["correlation:"] + message.removeprefix("correlation")
    for k, text in labels.items():
        name = k.removeprefix("sigma.")
        head = ARGUMENTS.get(name, name) + " "
        head = "the sigma of " + head if k.startswith("sigma.") else head
        if message.startswith(head) and len(message) > len(head):
            return _spelled(text, message.removeprefix(head))
    return message


def _spelled(label: str, rest: str) -> str:
    """``label rest``; a file's key before a value as ``key (in the measurement file) = ...``."""
    if label.endswith(IN_FILE) and rest.startswith("= "):
        return f"{label.removesuffix(IN_FILE)}({IN_FILE}) {rest}"
    return f"{label} {rest}"


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
    "v_i": "Drop velocity of the tip ('-1.41 m/s'; bare number: m/s; its sign is ignored: T and "
    "F use, and the output shows, its magnitude |v_i|, but a --correlation naming vi is of the "
    "value as given: a negative v_i flips its sign; required unless --case or --file gives it).",
    "e": "Coefficient of restitution (tip, normal), for the mean force F; it or --dv-cy is "
    "required (without either the command is refused, T too) unless --case or --file gives it.",
    "mu": "Friction coefficient (paper Eq. 28); required unless --case or --file gives it.",
    "delta_p": "Permanent dent depth, a magnitude ('22 um'; bare number: m; the paper prints "
    "-22 um; required unless --case or --file gives it).",
    "L_s": "Sliding length L_s, a magnitude ('1400 um'; bare number: m; the paper prints "
    "-1400 um; required unless --case or --file gives it).",
    "dv_cy": "Change of the centre-of-mass vertical velocity ('0.62 m/s'; bare number: m/s; "
    "optional): F from Eq. 29.",
    "vt_in": "Tangential velocity of the tip before the impact, along +x towards the centre of "
    "mass, spin included ('-0.3 m/s'; bare number: m/s; default 0, the paper's assumption; the "
    "sign matters).",
}


def _sigma_help(name: str) -> str:
    """The help of ``--sigma-*``: how its unit is read (``parse_sigma``)."""
    unit, _, flag = FIELDS[name]
    if not unit:
        return f"Std. dev. of {flag} (default 0)."
    if unit == "degree":
        return f"Std. dev. of {flag} with its unit ('0.5 deg'; a bare number is refused)."
    ex = EXAMPLE_UNITS[name]
    return (
        f"Std. dev. of {flag}, e.g. '{EXAMPLE_SIGMAS[name]}' (default 0). A bare number is in "
        "the unit of "
        f"{flag} as given on the command line ('... {ex}': {ex}; a bare {flag}: {unit}); with "
        f"{flag} from --case or --file it needs its unit."
    )


def _measured_option(name: str, *, sigma: bool = False) -> Any:
    """The option of a measured input (``--vi``), or of its standard deviation (``--sigma-vi``)."""
    flag = FIELDS[name][2]
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
    vt_in: str | None = _measured_option("vt_in"),
    sigma_angle: str | None = _measured_option("angle", sigma=True),
    sigma_vi: str | None = _measured_option("v_i", sigma=True),
    sigma_e: str | None = _measured_option("e", sigma=True),
    sigma_mu: str | None = _measured_option("mu", sigma=True),
    sigma_delta_p: str | None = _measured_option("delta_p", sigma=True),
    sigma_ls: str | None = _measured_option("L_s", sigma=True),
    sigma_dv_cy: str | None = _measured_option("dv_cy", sigma=True),
    sigma_vt_in: str | None = _measured_option("vt_in", sigma=True),
    correlation: list[str] | None = typer.Option(
        None,
        "--correlation",
        metavar="PAIR",
        help="Correlation of two inputs measured together, NAME,NAME=COEFFICIENT (e.g. "
        "e,dv_cy=0.94; repeatable, one pair each; names as Python's invert or the options: "
        "v_i or vi, sliding_length or ls); each input needs its sigma; a pair replaces a "
        "--file correlation of the same pair. Default: independent.",
    ),
    mass: str | None = rod_option("mass"),
    length: str | None = rod_option("length"),
    tip_radius: str | None = rod_option("tip_radius"),
    inertia: str | None = rod_option("inertia"),
    case: str | None = typer.Option(
        None, "--case", help="Start from the paper's measurements: paper-20, paper-45 or paper-70."
    ),
    file: Path | None = typer.Option(
        None,
        "--file",
        help="TOML file of measurements (keys as the options or as Python's invert: ls or "
        "sliding_length; [sigma], [rod], [correlation]; measure, gravity, samples, seed). A "
        "bare number in [sigma] is in the unit of its value in the file (ls = '1400 um' and "
        "[sigma] ls = 50: 50 um); without that value in the file it needs its unit.",
    ),
    gravity: bool | None = typer.Option(
        None,
        "--gravity/--no-gravity",
        help="Gravity during the contact (default: no, as in the paper).",
    ),
    measure: str | None = typer.Option(
        None,
        "--measure",
        help="What --ls measures: 'slip' (default, the paper: the rod's material point at the "
        "contact) or 'travel' (the contact patch, which a dent's length records).",
    ),
    samples: int | None = typer.Option(
        None,
        "--samples",
        min=100,
        metavar="N",
        help=f"Monte Carlo samples (default 20000; at least 100, at most {MAX_SAMPLES:,}).",
    ),
    seed: int | None = typer.Option(None, "--seed", help="Monte Carlo seed (default 0)."),
    flat: str | None = typer.Option(
        None,
        "--flat",
        help="Flat material: a library name (see 'impactlab materials'), properties "
        "'E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3' (HB=, n=, brittle=yes optional) or a "
        "TOML file (with --case: the paper's, aisi-1010): also simulate the impact (ghaednia "
        "law, the measured angle, v_i, vt_in and mu; no spin) and warn when T or F is more "
        "than 3 times off.",
    ),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output (SI)."),
) -> None:
    """Impact duration T and mean normal force F from a measured oblique impact of the rod.

    Inverts the paper's Eq. 12 (corrected) for T and Eq. 29 (or the rigid-body identity
    F T = (1 + e)|v_i| / K_y) for F, with first-order and Monte Carlo uncertainties.

    Example:

    \b
      impactlab invert --angle "20 deg" --vi "-1.41 m/s" --e 0.5 --mu 0.2 \\
        --delta-p "22 um" --ls "1400 um" --sigma-ls "50 um"
    """
    inputs = (angle, vi, e, mu, delta_p, ls, dv_cy, vt_in)
    sigmas = (sigma_angle, sigma_vi, sigma_e, sigma_mu, sigma_delta_p, sigma_ls, sigma_dv_cy,
              sigma_vt_in)  # fmt: skip
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ImplausibleInputWarning)
        res, _given = run_invert(
            case=case,
            file=file,
            values=dict(zip(FIELDS, inputs, strict=True)),
            sigmas=dict(zip(FIELDS, sigmas, strict=True)),
            rod={"mass": mass, "length": length, "tip_radius": tip_radius, "inertia": inertia},
            gravity=gravity,
            measure=measure,
            samples=samples,
            seed=seed,
            correlation=correlation,
        )
    found = inversion_warnings(caught)
    if flat is None and case is not None:
        flat = "aisi-1010"  # the paper's flat
    model, compared = compare_with_engine(res, flat) if flat is not None else ({}, [])
    doubts = inversion_doubts(found, compared)
    found += compared
    if as_json:
        data = inversion_json(res)
        if model:
            data["model"] = to_json(model, SI_UNITS)
        data |= {"ok": not doubts, "doubts": doubts}
        print(json.dumps({**data, "warnings": found}, indent=2))
    else:
        print_inversion(res, doubts)
        if model:
            rows = [(f"model {k} ({model['law']})", *field_row(k, v, SI_UNITS[k])[1:])
                    for k, v in model.items() if isinstance(v, float)]  # fmt: skip
            print_rows(rows, f"simulated impact on {model['flat']}")
    for text in found:
        print_wrapped(f"warning: {text}")


def register(app: typer.Typer) -> None:
    """Add ``impactlab invert`` to ``app``."""
    app.command("invert")(invert_cmd)
