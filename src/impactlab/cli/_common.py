"""Shared helpers for the command modules: unit-aware options, TOML inputs; the console and the
JSON/table output (``cli.printing``) re-exported."""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import Any

import typer

from impactlab._validation import did_you_mean, read_text_file
from impactlab.cli.printing import (  # noqa: F401  (re-exported: the commands import them here)
    EXTRA_UNITS,
    SI_UNITS,
    console,
    emit,
    print_rows,
)
from impactlab.contact.rate import RATE_CONSTANTS, RATE_LAWS, RateLaw, constants_text, get_rate_law
from impactlab.dynamics.input_checks import past_normal
from impactlab.dynamics.kernels.inputs import angle_allowed, incidence_allowed
from impactlab.materials import Material
from impactlab.units import angle_to_rad, to_si


class UserError(ValueError):
    """An error in the user's input: reported as one line, exit status 2."""


def refuse_empty_paths(command: Any) -> None:
    """Every path argument and option (``Path``, ``list[Path]``) of the click ``command`` and
    of its commands refuses an empty value with a usage error naming it (exit status 2):
    ``Path("")`` is the current folder, and the command would speak of ``'.'``, a path the
    user never gave."""
    for param in command.params:
        kind = getattr(getattr(param, "type_descriptor", None), "annotation", None)
        if kind in (Path, list[Path]) and "process_value" not in vars(param):
            param.process_value = _non_empty(param, param.process_value)
    for sub in getattr(command, "commands", {}).values():
        refuse_empty_paths(sub)


def _non_empty(param: Any, process: Callable[[Any, Any], Any]) -> Callable[[Any, Any], Any]:
    """``param``'s ``process_value``, refusing an empty or blank path first."""

    def process_value(ctx: Any, value: Any) -> Any:
        for given in value if isinstance(value, list | tuple) else (value,):
            if isinstance(given, str) and not given.strip():
                raise typer.BadParameter(
                    f"an empty path ({given!r}): give a file or folder name", ctx, param
                )
        return process(ctx, value)

    return process_value


#: The sources of the library's rate laws, short (``impactlab.contact.rate``).
_RATE_SOURCES = {
    "cowper-symonds-1957": "Cowper & Symonds 1957",
    "jones-1989": "constants as quoted by Jones, Structural Impact 1989",
    "johnson-cook-1983": "Johnson & Cook 1983",
}


def _form(name: str, example: bool = False) -> str:
    """``--rate``'s form of the law ``name``: ``cowper-symonds(D=... 1/s, q=...)``, or with
    ``example`` ``cowper-symonds(D=6500 1/s, q=4)``."""
    values = None if example else dict.fromkeys(RATE_CONSTANTS[name][1], "...")
    return f"{name}({constants_text(name, values, '=')})"


#: A rate law with one's own constants, as ``--rate`` takes it.
RATE_EXAMPLE = _form("cowper-symonds", example=True)


def rate_help() -> str:
    """The help of ``--rate``: each library law's form, constants (with units), what they were
    fitted for and their sources, and how to give one's own constants."""
    laws = "; ".join(
        f"{n}: k = {RATE_CONSTANTS[n][0]}, {constants_text(n, dict(law.parameters))} "
        f"({law.description.split(':')[0]}; "
        f"{', '.join(_RATE_SOURCES.get(k, k) for k in law.reference_keys)})"
        for n, law in RATE_LAWS.items()
    )
    own = " or ".join(f'"{_form(n)}"' for n in RATE_LAWS)
    fitted = {law.fitted_for.name for law in RATE_LAWS.values() if law.fitted_for is not None}
    return (
        "Rate-dependent flat, its yield strength times k(eps_dot), eps_dot its strain rate "
        f"(default none): {laws}; fitted for {' and '.join(sorted(fitted))} (another flat is "
        f"refused). A flat's own constants: {own} (a bare number is in the unit shown), e.g. "
        f'"{RATE_EXAMPLE}"; the form a result prints reads back.'
    )


def rate_name(rate: str, name: str = "--rate") -> str | RateLaw | None:
    """The rate law of ``--rate`` (``contact.rate.get_rate_law``): None for "none", a library
    law's name, or a law with one's own constants, ``"cowper-symonds(D=6500 1/s, q=4)"`` (or as
    a result prints it, ``"cowper-symonds (D = 6500 1/s, q = 4)"``); UserError naming ``name``."""
    try:
        law = get_rate_law(rate, name)
    except ValueError as exc:  # an unknown name: the nearest law's ('_' for '-' too)
        head, known = rate.partition("(")[0].strip().lower(), ("none", *RATE_LAWS)
        near = "" if head in known else did_you_mean(head, known)
        raise UserError(f"{exc}{near}") from None
    return law.name if law is not None and RATE_LAWS.get(law.name) is law else law


def check_rate_flat(rate: str | RateLaw | None, flat: Material, name: str = "--rate") -> None:
    """UserError when the library rate law ``rate`` (``name``: how the user gave it) was not
    fitted for ``flat``'s material (``contact.rate.check_rate_flat``; a law with one's own
    constants is not checked), saying how to give the flat's own constants with ``--rate``."""
    law = RATE_LAWS.get(rate) if isinstance(rate, str) else None
    why = None if law is None or law.fitted_for is None else law.fitted_for.mismatch(flat)
    if law is not None and law.fitted_for is not None and why is not None:
        raise UserError(
            f"{name} {law.name}: its constants are fitted for {law.fitted_for.name}, but the flat "
            f"{flat.name!r} has {why}; give the flat's own constants, --rate "
            f'"{_form(law.name)}" (e.g. "{_form(law.name, example=True)}"; --help '
            "lists them)"
        )


def check_rate_law(rate: str | RateLaw | None, law: object, name: str, law_name: str) -> None:
    """UserError when a rate law ``rate`` comes with an elastic contact ``law`` (no yield
    strength to raise), naming each as the user gave it: ``name`` "--rate" or "the recorded
    rate", ``law_name`` "--law" or "the recorded law"."""
    from impactlab.dynamics.drop import ELASTIC_LAWS  # lazy: a fast CLI start

    if rate is None or not isinstance(law, str) or law.strip().lower() not in ELASTIC_LAWS:
        return
    fix = "add --rate none" if name.startswith("the recorded") else f"leave out {name}"
    shown = rate.label if isinstance(rate, RateLaw) else rate
    raise UserError(f"{name} {shown}: {law_name} {law.strip()} is elastic (no yield strength for "
                    f"the rate to raise); {fix}, or give an elastic-plastic --law")  # fmt: skip


def as_option(message: str, keys: Iterable[str], label: Callable[[str], str]) -> str:
    """``message`` with its leading parameter name among ``keys`` (``"mu must be >= 0"``, an API
    message) spelled as the user gave it, ``label(key)`` (``"--mu must be >= 0"``)."""
    head, _, rest = message.partition(" ")
    if head not in keys or not rest or message.startswith(label(head)):
        return message  # not a parameter's, or labelled already ("mass (in c.toml) must ...")
    return f"{label(head)} {rest}"


def quantity(value: str | float | None, unit: str, name: str) -> float | None:
    """Parse a CLI quantity ("8.8 mm"; a bare number is in ``unit``) to SI; None passes through."""
    if value is None:
        return None
    if isinstance(value, bool):  # a config file's `vx = true`: no quantity
        raise UserError(f"{name} must be a quantity in {unit}, got {value!r}")
    return to_si(value, unit, name=name)


def positive(value: str | float | None, unit: str, name: str) -> float | None:
    """:func:`quantity`, and > 0: a given value is always used (None passes through)."""
    x = quantity(value, unit, name)
    if x is not None and not x > 0:
        raise UserError(f"{name} must be > 0, got {value!r}")
    return x


def any_angle(value: Any, name: str) -> float:
    """An angle with its unit ("20 deg", "-0.35 rad") in radians, any value. A bare number is
    refused: 0.35 could be degrees or radians (the angle rule, docs/glossary.md)."""
    text = str(value).strip()
    try:
        x = float(text)
    except ValueError:
        return angle_to_rad(text, name=name)
    if not math.isfinite(x):
        raise UserError(f"{name} must be finite, got {text!r}")
    raise UserError(f"{name} {text} has no unit: give a unit, e.g. '20 deg' or '0.35 rad'")


def angle_quantity(value: Any, name: str) -> float:
    """An angle with its unit ("20 deg", "0.35 rad") in radians, in (0, 90] deg (answered in
    degrees otherwise). A bare number is refused: 0.35 could be degrees or radians."""
    th = any_angle(value, name)
    if not angle_allowed(th):
        hint = past_normal(th, True) if 0.5 * math.pi < th < math.pi else ""
        raise UserError(f"{name} must be in (0, 90] deg, got {str(value).strip()}{hint}")
    return th


def velocity_input(
    vx: Any, vy: Any, speed: Any, incidence: Any, label: Any = None
) -> tuple[float, float]:
    """(vx, vy) [m/s] from --vx/--vy, or from --speed and --incidence (the incidence to the
    flat's normal with its unit; positive: vx > 0); UserError when both pairs or neither are
    given. ``label(key)`` spells an option in errors (default ``--key``)."""
    name = label or (lambda key: "--" + key)
    by_components = vx is not None or vy is not None
    by_speed = speed is not None or incidence is not None
    if by_components and by_speed:
        given = {"vx": vx, "vy": vy, "speed": speed, "incidence": incidence}

        def pair(keys: tuple[str, str]) -> str:  # the given keys of a form, as given
            return "/".join(name(k) for k in keys if given[k] is not None)

        raise UserError(
            f"{pair(('vx', 'vy'))} and {pair(('speed', 'incidence'))} both given: they say the "
            "same thing; give one pair"
        )
    if by_speed:
        if speed is None or incidence is None:
            missing = name("speed") if speed is None else name("incidence")
            raise UserError(f"{name('speed')} and {name('incidence')} go together: {missing} "
                            "is missing")  # fmt: skip
        v = positive(speed, "m/s", name("speed"))
        th = any_angle(incidence, name("incidence"))
        if not incidence_allowed(th):
            raise UserError(
                f"{name('incidence')} must lie in (-90, 90) deg from the flat's normal, got "
                f"{str(incidence).strip()}"
            )
        return (v * math.sin(th), -v * math.cos(th))  # type: ignore[operator]
    if vy is None:
        raise UserError(
            f'{name("vy")} is required, e.g. {name("vy")} "-1.41 m/s" (or {name("speed")} '
            f'"1.5 m/s" {name("incidence")} "30 deg")'
        )
    return (quantity(vx, "m/s", name("vx")) or 0.0, quantity(vy, "m/s", name("vy")) or 0.0)


#: Help of the initial state's options, shared by ``simulate`` and ``drop``.
KINEMATIC_HELP = {
    "angle": 'Rod angle to the flat with its unit, "20 deg" or "0.35 rad" (required for a rod; '
    "a bare number is refused).",
    "vy": 'Vertical velocity of the centre of mass, e.g. "-1.41 m/s" (required unless --speed '
    "and --incidence; a bare number is in m/s).",
    "vx": "Horizontal velocity, e.g. '0.1 m/s' (bare number: m/s; default 0 m/s).",
    "speed": "Instead of --vx/--vy: the speed of the centre of mass, e.g. '1.5 m/s' (with "
    "--incidence).",
    "incidence": "Instead of --vx/--vy: the velocity's angle to the flat's normal with its unit, "
    "in (-90, 90) deg, e.g. '30 deg'; vx = speed sin(incidence) (positive: towards +x), "
    "vy = -speed cos(incidence).",
    "spin": 'Angular velocity, e.g. "5 rad/s" (bare number: rad/s; counter-clockwise positive; '
    "default 0 rad/s).",
}


#: What a drop follows (``simulate_drop(stop=...)``), for ``drop`` and ``simulate --flexible``.
STOP_HELP = (
    "what the drop follows: 'sequence' (default: the tip's impact, its contacts until the tip "
    "leaves the flat for good or the other end lands) or 'flight' (on through the other end's "
    "impacts until the rod flies off)."
)


#: The rod's properties in a [rod] table or as options, with their SI units.
ROD_FIELDS: dict[str, str] = {"mass": "kg", "length": "m", "tip_radius": "m", "inertia": "kg*m^2"}


def length_help(default: str) -> str:
    """The rod length option's help: the length convention, said in every rod option's help,
    and the ``default``."""
    return (
        "Rod length L between the centres of the end spheres (the overall length is L + 2R), "
        f"e.g. '304.8 mm' (bare number: m; default {default})."
    )


#: The rod options' help (the defaults are the paper's rod).
_ROD_HELP = {
    "mass": "Rod mass, e.g. '0.46 kg' (bare number: kg; default 0.4607 kg).",
    "length": length_help("0.3048 m"),
    "tip_radius": "Tip radius (--radius too), e.g. '8.8 mm' (bare number: m; default 8.8 mm).",
    "inertia": "I_C about the centre of mass, e.g. '3.6e-3 kg*m^2' (default m L^2/12).",
}


#: Other spellings of a rod option: the tip radius is ``--radius`` in simulate, drop and laws.
_ROD_ALIASES = {"tip_radius": ("--radius",)}


def rod_option(key: str) -> Any:
    """The command-line option of the rod property ``key`` (``--tip-radius``, ``--radius``)."""
    flags = ("--" + key.replace("_", "-"), *_ROD_ALIASES.get(key, ()))
    return typer.Option(None, *flags, help=_ROD_HELP[key])


def parse_rod_table(table: Mapping[str, Any], prefix: str) -> dict[str, float]:
    """The rod's properties in SI from a [rod] table (``prefix`` "rod."; quantity text or the
    JSON's ``{value, unit}``) or the options (``prefix`` "--"); an unknown key is an error."""
    out: dict[str, float] = {}
    for key, value in table.items():
        if key not in ROD_FIELDS:
            raise UserError(f"unknown key {key!r} in [rod]; allowed: {', '.join(ROD_FIELDS)}")
        name = prefix + (key.replace("_", "-") if prefix == "--" else key)
        if isinstance(value, Mapping) and set(value) != {"value", "unit"}:
            raise UserError(f"{name} is a table of {sorted(value)}: give quantity text or "
                            'a table of value and unit: { value = 0.46, unit = "kg" }')  # fmt: skip
        if isinstance(value, Mapping):  # the JSON output's rod
            value = f"{value['value']!r} {value['unit']}"
        out[key] = positive(value, ROD_FIELDS[key], name)  # type: ignore[assignment]
    return out


def load_toml(path: Path | None, option: str = "input file") -> dict[str, Any]:
    """Read a TOML input file (empty dict for None); a UserError naming ``option`` (``--file``)
    and the path when it is missing, a folder, unreadable, not UTF-8 text or not valid TOML."""
    if path is None:
        return {}
    shown = f"{option} {str(path)!r}"
    if path.is_dir():
        raise UserError(f"{shown} is a folder: give a TOML file")
    if not path.is_file():
        raise UserError(f"{shown} does not exist")
    try:
        return tomllib.loads(read_text_file(path, "TOML", shown))
    except tomllib.TOMLDecodeError as exc:
        raise UserError(f"{shown} is not valid TOML: {exc}") from None
    except ValueError as exc:  # not UTF-8 text
        raise UserError(str(exc)) from None
    except OSError as exc:
        raise UserError(f"{shown} cannot be read ({exc.strerror or exc})") from None


def gravity_option() -> Any:
    """The ``--gravity/--no-gravity`` switch of simulate and drop (None: not given)."""
    return typer.Option(
        None,
        "--gravity/--no-gravity",
        show_default=False,
        help="Gravity on (default) or off; either replaces the --config file's gravity.",
    )
