"""A command's ``--config`` file (``impactlab simulate``, ``impactlab drop``): a TOML file of the
command's option keys, checked (unknown keys with the nearest known one, a material given
whole, switches that are TOML booleans) and merged under the options of the command line, which
win (a velocity given there, either form, replaces the file's, either form); a material file it
names is read relative to the file's folder; each value's errors name it as the user gave it,
``--mass`` or ``mass (in case.toml)``, the API's refusals of a velocity or a rod's mass too
(``approach_worded``)."""

from __future__ import annotations

import re
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from impactlab._validation import did_you_mean
from impactlab.cli._common import UserError, positive, velocity_input
from impactlab.cli.config_values import check_booleans
from impactlab.materials import Material, get_material

__all__ = [
    "RENAMED_KEYS",
    "ConfigOptions",
    "command_table",
    "merge_config",
    "option_material",
    "refuse_given",
    "renamed_options",
]

#: Keys that say one thing in two forms: given on the command line in one form, the file's
#: keys of the other form are not read (the velocity: ``vx``/``vy`` or ``speed``/``incidence``).
ALTERNATIVES: tuple[tuple[str, ...], ...] = (("vx", "vy"), ("speed", "incidence"))
#: Keys that may name a file (a material's TOML file): in a config file, relative to its folder.
FILE_KEYS = ("material", "flat")
#: Other names of a key, read as it (their names elsewhere: study files, [rod] tables,
#: ``FlexibleRod``'s keywords): an alias by the key it gives.
KEY_ALIASES = {"tip_radius": "radius", "n_axial": "modes_axial", "n_bending": "modes_bending"}
#: Keys renamed in 0.3, read under their old name until 0.4 with a deprecation line on stderr
#: (a config file's ``t_max``, the option ``--t-max``): old key -> key.
RENAMED_KEYS = {"t_max": "time_limit"}


@dataclass(frozen=True)
class ConfigOptions:
    """The merged options (config file < command line) and where each came from.

    values: by key, SI or as written (quantities are parsed where they are used); from_cli:
    the keys given on the command line; config: the file, as given; flags: the command-line
    switches of the keys whose option is not ``--<key>``, the one that leaves the default first
    (``gravity``: ``--no-gravity/--gravity``; a label names that one); spelt: the file's
    name of a key given under an alias (``modes_axial``: ``n_axial``, ``KEY_ALIASES``)."""

    values: dict[str, Any]
    from_cli: frozenset[str]
    config: str
    flags: Mapping[str, str] = field(default_factory=dict)
    spelt: Mapping[str, str] = field(default_factory=dict)

    def label(self, key: str, like: str | None = None) -> str:
        """How the user wrote ``key``: "--mass" or "mass (in case.toml)". A key not given is
        spelt where ``like`` (the given key the error is about) was given: the option, or
        the file's key, ``mass (in case.toml)``, ``rigid = true (in case.toml)`` for a switch."""
        # a switch: the half that leaves the default (errors say "leave out" or "give" it)
        flag = self.flags.get(key, "--" + key.replace("_", "-")).partition("/")[0]
        if key in self.from_cli:
            return flag
        if key not in self.values:  # not given: where the value it goes with was
            if like is None or like in self.from_cli or like not in self.values:
                return flag
            if key in self.flags:
                return f"{key} = {str(not flag.startswith('--no-')).lower()} (in {self.config})"
        return f"{self.spelt.get(key, key)} (in {self.config})"

    def velocity(self) -> tuple[float, float]:
        """The velocity (vx, vy) [m/s] (``velocity_input``); a missing speed or incidence is
        spelt where the other was given."""
        v, partner = self.values, {"speed": "incidence", "incidence": "speed"}
        return velocity_input(v.get("vx"), v.get("vy"), v.get("speed"), v.get("incidence"),
                              lambda key: self.label(key, partner.get(key)))  # fmt: skip

    def given(self, key: str) -> bool:
        return self.values.get(key) not in (None, False)

    def size(self, key: str, unit: str) -> float | None:
        """The given positive quantity (None: not given)."""
        return positive(self.values.get(key), unit, self.label(key))

    def size_or(self, key: str, unit: str, default: float) -> float:
        """The given positive quantity, else ``default``."""
        value = self.size(key, unit)
        return default if value is None else value


def command_table(config: Mapping[str, Any], name: str, other: str, where: str) -> dict[str, Any]:
    """The keys of the command ``name`` in a config file ``where``: its ``[name]`` table, else
    the top level. A file may hold both commands' tables (``[drop]`` and ``[simulate]``), each
    read by its own command; beside its table, other top-level keys are refused (never
    silently left out), and the ``other`` command's table alone is refused, pointing to
    ``[name]``: its keys describe that command's body."""
    if name in config:
        table = config[name]
        if not isinstance(table, dict):
            raise UserError(f"{name} in {where} must be a table, [{name}], got {table!r}")
        rest = sorted(set(config) - {name, other})
        if rest:
            them = "it" if len(rest) == 1 else "them"
            raise UserError(
                f"{', '.join(rest)} in {where}: beside a [{name}] table the top level is not "
                f"read; move {them} into [{name}]"
            )
        return table
    if other in config:
        raise UserError(
            f"[{other}] in {where} is impactlab {other}'s table; give impactlab {name}'s keys "
            f"in a [{name}] table (a file may hold both) or at the top level"
        )
    return dict(config)


def merge_config(
    section: Mapping[str, Any],
    cli: Mapping[str, Any],
    config_path: Path | None,
    keys: tuple[str, ...],
    flags: Mapping[str, str],
    notes: Mapping[str, str] | None = None,
) -> ConfigOptions:
    """The options of the command line (``cli``: by key, None when not given) over the keys of
    the config file's ``section``. Refused: a material in parts (``flat_E``), an unknown key
    (with the nearest of ``keys``, or its ``notes``: why a key of another command is none of
    this one's), a switch of ``flags`` that is no TOML boolean; an alias (``KEY_ALIASES``:
    ``tip_radius``, ``n_axial``, ``n_bending``) is read as its key, as is a key's name before
    0.3 (``RENAMED_KEYS``: ``t_max``, with a line on stderr). A velocity given on the
    command line in one form leaves out the file's other form (``ALTERNATIVES``); a relative
    material file's path (``FILE_KEYS``: text ending in .toml) is read from the file's folder."""
    section, spelt = _unaliased(section, keys, config_path)
    unknown = sorted(set(section) - set(keys))
    props = [k for k in unknown if k.startswith(("flat_", "material_", "body_"))]
    if props:
        raise UserError(
            f"{props[0]} in the config file: give a material whole, as a table, e.g. "
            'flat = { E = "69 GPa", nu = 0.33, Sy = "276 MPa", rho = "2700 kg/m^3" }, or a '
            "library name, flat = \"al-6061-t6\" (see 'impactlab materials')"
        )
    if unknown:
        why = notes or {}
        hints = ", ".join(f"{k} ({why[k]})" if k in why else k + did_you_mean(k, keys)
                          for k in unknown)  # fmt: skip
        raise UserError(f"unknown key(s) in the config file: {hints}; known: {', '.join(keys)}")
    check_booleans(section, flags, str(config_path))
    given = {k: v for k, v in cli.items() if v is not None}
    for form in ALTERNATIVES:  # the command line's form replaces the file's other forms
        if any(k in given for k in form):
            others = {k for f in ALTERNATIVES if f != form for k in f}
            section = {k: v for k, v in section.items() if k not in others}
    if config_path is not None:
        section = {k: _beside(v, config_path) if k in FILE_KEYS else v for k, v in section.items()}
    return ConfigOptions({**section, **given}, frozenset(given), str(config_path), flags, spelt)


def _unaliased(
    section: Mapping[str, Any], keys: tuple[str, ...], config_path: Path | None
) -> tuple[dict[str, Any], dict[str, str]]:
    """``section`` with each alias of a key among ``keys`` (``KEY_ALIASES``: ``n_axial``,
    ``tip_radius``) or its name before 0.3 (``RENAMED_KEYS``: ``t_max``, said on stderr) read
    as that key, and the file's name of each key so given; UserError for a key given under
    both names."""
    out, spelt = dict(section), {}
    where = config_path or "the config file"
    for old, key in RENAMED_KEYS.items():
        if old not in out or key not in keys:
            continue
        if key in out:
            raise UserError(
                f"{key} and {old} in {where}: {old} is the name of {key} before impactlab 0.3; "
                f"give {key} only"
            )
        _say_renamed(f"{old} (in {where})", key)
        out[key] = out.pop(old)
        spelt[key] = old
    for alias, key in KEY_ALIASES.items():
        if alias not in out or key not in keys:
            continue
        if key in out:
            raise UserError(
                f"{key} and {alias} in {config_path or 'the config file'}: they are one "
                f"({alias} is the other name of {key}); give one"
            )
        out[key] = out.pop(alias)
        spelt[key] = alias
    return out, spelt


def _say_renamed(old: str, new: str) -> None:
    """The one line on stderr of an option or key given under its name before 0.3."""
    print(
        f"warning: {old} is renamed {new} (impactlab 0.3); the old name goes in 0.4",
        file=sys.stderr,
    )


def renamed_options(cli: Mapping[str, Any], former: Mapping[str, Any]) -> dict[str, Any]:
    """The command line's options ``cli`` (by key, None: not given) with each option given
    under its name before 0.3 (``former``: by old key of ``RENAMED_KEYS``, None: not given;
    ``--t-max``) as its key (``time_limit``), said on stderr in one line; UserError when both
    are given."""
    out = dict(cli)
    for old, value in former.items():
        if value is None:
            continue
        key = RENAMED_KEYS[old]
        flag, old_flag = (f"--{k.replace('_', '-')}" for k in (key, old))
        if out.get(key) is not None:
            raise UserError(
                f"{flag} and {old_flag}: {old_flag} is the name of {flag} before impactlab 0.3; "
                f"give {flag} only"
            )
        _say_renamed(old_flag, flag)
        out[key] = value
    return out


def _beside(value: Any, config_path: Path) -> Any:
    """A material file's relative path (text ending in .toml, no ``=``) as the path of the
    file beside the config file ``config_path``; any other value as it is."""
    if not isinstance(value, str) or "=" in value or not value.strip().lower().endswith(".toml"):
        return value
    path = Path(value.strip())
    return value if path.is_absolute() else str(config_path.parent / path)


def refuse_given(opt: ConfigOptions, keys: tuple[str, ...], why: str) -> None:
    """A UserError naming the given options among ``keys`` (they do not apply: ``why``)."""
    extra = [opt.label(k) for k in keys if opt.given(k)]
    if extra:
        them = "it" if len(extra) == 1 else "them"
        raise UserError(f"{', '.join(extra)}: {why}; leave {them} out")


def option_material(opt: ConfigOptions, key: str, default: Material) -> Material:
    """The material of ``key`` (a library name, properties, a TOML file or a config file's
    table; ``default`` if not given), its errors naming the option or the key."""
    value = opt.values.get(key)
    if value is None:
        return default
    try:
        return get_material(value, opt.label(key))
    except ValueError as exc:
        raise UserError(str(exc)) from None


#: The API's refusal of a rod that does not approach the flat (``dynamics.checks``, ``.drop``).
_APPROACH = re.compile(
    r"velocity: the (?P<what>contact point|tip) does not approach the flat \(its normal "
    r"velocity vy(?: - spin \* \(L/2\) cos\(angle\))? = (?P<vn>\S+) m/s must be < 0\)"
)


#: The API's refusal of a velocity component beyond its range (``dynamics.input_checks``).
_RANGE = re.compile(
    r"velocity\[\d\] \((?P<comp>vx|vy)\) = (?P<v>\S+) m/s (?P<rest>exceeds .*)", re.DOTALL
)


def _range_worded(found: re.Match[str], opt: ConfigOptions) -> str:
    """A velocity component beyond its range named as typed: ``--vx "2e4 m/s" exceeds ...``,
    or the options that gave it (``--speed "2e4 m/s", --incidence "10 deg" give vy = -1.97e4
    m/s, which exceeds ...``)."""
    comp, rest = found["comp"], found["rest"]
    if opt.given(comp):
        return f'{opt.label(comp)} "{opt.values[comp]}" {rest}'
    keys = [k for k in ("speed", "incidence") if opt.given(k)]
    typed = ", ".join(f'{opt.label(k)} "{opt.values[k]}"' for k in keys)
    return f"{typed} give {comp} = {float(found['v']):.4g} m/s, which {rest}"


#: The API's refusal of a rod's mass and diameter that do not fit its material (``bodies``;
#: its head "mass" may be named already: "--mass", "mass (in case.toml)").
_DENSITY = re.compile(
    r"(?:.*? )?\((?P<mass>[^)]*) kg\), diameter \((?P<diameter>[^)]*) m\) and length "
    r"\((?P<length>[^)]*) m\) (?P<rest>imply .*)",
    re.DOTALL,
)


def _density_worded(found: re.Match[str], opt: ConfigOptions) -> str:
    """The rod's mass, diameter and length that imply another density, each named as typed
    (``--diameter "12 mm"``), or with its value rounded where it was not given (``length
    304.8 mm``)."""
    units = {"mass": ("kg", 1.0), "diameter": ("mm", 1e3), "length": ("mm", 1e3)}
    parts = []
    for key, (unit, scale) in units.items():
        if opt.given(key):
            parts.append(f'{opt.label(key)} "{opt.values[key]}"')
        else:
            parts.append(f"{key} {float(found[key]) * scale:.4g} {unit}")
    return f"{parts[0]}, {parts[1]} and {parts[2]} {found['rest']}"


#: The start of a drop's refusal of an approach too slow to integrate (``dynamics.drop``).
_SLOW = "velocity: the tip's normal approach speed"


def approach_worded(message: str, opt: ConfigOptions) -> str:
    """The API's refusal of a rod that does not approach the flat naming the velocity options
    as typed (``--vy "1.41 m/s"``; a rod's ``--spin`` where given, with its term of the normal
    velocity), of a velocity component beyond its range (``_range_worded``) and of a mass and
    diameter that do not fit the rod's material (``_density_worded``); any other
    message as it is (``simulate`` and ``drop`` alike)."""
    ranged = _RANGE.fullmatch(message)
    if ranged is not None:
        return _range_worded(ranged, opt)
    density = _DENSITY.fullmatch(message)
    if density is not None:
        return _density_worded(density, opt)
    spin = opt.given("spin") and opt.given("angle")  # a rod's: a sphere's spins in place
    keys = [k for k in ("vy", "speed", "incidence") if opt.given(k)] + ["spin"] * spin
    typed = ", ".join(f'{opt.label(k)} "{opt.values[k]}"' for k in keys)
    if message.startswith(_SLOW) and typed:  # a drop's approach too slow to integrate
        return f"{typed}: {message.removeprefix('velocity: ')}"
    found = _APPROACH.fullmatch(message)
    if found is None:
        return message
    formula = "vy - spin * (L/2) cos(angle)" if spin else "vy"
    return (
        f"{typed}: the {found['what']} does not approach the flat (its normal velocity "
        f"{formula} = {float(found['vn']):.4g} m/s must be < 0, towards the flat)"
    )
