"""A material from what a user writes: a library name, a definition by values or a TOML file.

One reader for every input (the Python API's :func:`get_material`, every command's
``--material``/``--flat``, ``--config`` files, study files):

- a name of the library (``"al-6061-t6"``, case and ``_``/``-`` free; aliases such as
  ``"6061-t6"``; ``impactlab materials`` lists them);
- a definition by values, ``"E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"`` (a mapping with
  the same keys works too): E, nu, the yield strength and the density are **required**,
  the Brinell hardness (``HB``), the Meyer index (``n``), ``name`` and ``condition`` optional.
  Quantities carry units (``HB=95 HB``; ``{"value": 69, "unit": "GPa"}`` in a mapping, as
  ``impactlab materials NAME --json`` writes them, whose descriptive keys are read past); a
  bare number is in SI (Pa, kg/m^3; HB in kgf/mm^2);
- the path of a TOML file holding such a table (top level or under ``[material]``).

A definition by values is complete or refused: it never borrows a library entry's other
values (an aluminium flat never keeps a steel's hardness), and its name never names a library
entry (its key, an alias or its display name) unless every value, the unset ones included, is
that entry's: then it is that entry.
"""

from __future__ import annotations

import math
import re
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from impactlab._validation import read_text_file
from impactlab.materials.core import (
    PLAUSIBLE,
    Material,
    brinell_to_pa,
    hardness_below_yield,
)
from impactlab.materials.core import brinell_text as brinell_text  # also the priors' reader
from impactlab.materials.library import ALIASES, PRESETS
from impactlab.materials.naming import library_entry, name_key, nearest
from impactlab.units import read_minus, to_si

#: Keys of a definition by values -> (Material field, SI unit; "" for text, "1" for numbers).
KEYS: dict[str, tuple[str, str]] = {
    "e": ("E", "Pa"),
    "nu": ("nu", "1"),
    "sy": ("yield_strength", "Pa"),
    "s_y": ("yield_strength", "Pa"),
    "yield_strength": ("yield_strength", "Pa"),
    "rho": ("density", "kg/m^3"),
    "density": ("density", "kg/m^3"),
    "hb": ("brinell_hardness", "kgf/mm^2"),
    "brinell_hardness": ("brinell_hardness", "kgf/mm^2"),
    "n": ("meyer_index", "1"),
    "meyer_index": ("meyer_index", "1"),
    "name": ("name", ""),
    "condition": ("condition", ""),
    "brittle": ("brittle", "bool"),
}
#: The fields a definition by values must give.
REQUIRED: tuple[str, ...] = ("E", "nu", "yield_strength", "density")
_SPELLED = {"E": "E", "nu": "nu", "yield_strength": "Sy", "density": "rho"}
EXAMPLE = "E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"
#: Keys of ``impactlab materials NAME --json`` that describe an entry (its library key, its
#: source, the source's citation and address, a note, the writing version): read past by a
#: definition by values.
DESCRIPTIVE: tuple[str, ...] = ("key", "source", "note", "citation", "url", "impactlab_version")
#: The number that leads a quantity text (its exponent's digits are no power of a unit).
_LEAD = re.compile(r"\s*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


def library_names() -> str:
    """The library's names, comma-separated (for error messages)."""
    return ", ".join(PRESETS)


def from_library(name: str) -> Material | None:
    """The library entry called ``name`` (its key, an alias, or the display name every result
    prints: ``"AISI 1010 low-carbon steel (paper's flat)"``); None if there is none."""
    key = name_key(name)
    entry = PRESETS.get(ALIASES.get(key, key))
    return entry if entry is not None else library_entry(name)


def _number(field: str, unit: str, value: Any, label: str) -> float:
    if unit == "1":
        if isinstance(value, bool):
            raise ValueError(f"{label}: expected a number, got {value!r}")
        try:
            x = float(value)
        except (TypeError, ValueError):
            raise ValueError(f"{label}: expected a number, got {value!r}") from None
        if not math.isfinite(x):
            raise ValueError(f"{label} must be finite, got {value!r}")
        return x
    if isinstance(value, bool):
        raise ValueError(f"{label}: expected a quantity in {unit}, got {value!r}")
    if isinstance(value, str):  # "kg/m3": a power written without "^", after the number
        value = brinell_text(value) if field == "brinell_hardness" else value
        lead = _LEAD.match(read_minus(value))
        cut = lead.end() if lead else 0
        value = value[:cut] + re.sub(r"(?<=[A-Za-z])([23])\b", r"^\1", value[cut:])
    x = to_si(value, unit, name=label)  # SI: a hardness in Pa
    x = x / brinell_to_pa(1.0) if unit == "kgf/mm^2" else x
    _check_bare(field, value, x, label)
    return x


def _check_bare(field: str, value: Any, x: float, label: str) -> None:
    """ValueError for a bare number (no unit) of an implausible magnitude: ``Sy=276`` is 276 Pa,
    a unit left out (:data:`impactlab.materials.core.PLAUSIBLE`)."""
    try:
        float(value)
    except (TypeError, ValueError):
        return  # it has a unit: the material's own check warns
    low, high, unit, hint = PLAUSIBLE[field]
    if x > 0 and not low <= x <= high:  # <= 0: the material's own error says what is allowed
        side = f"below {low:g}" if x < low else f"above {high:g}"
        suggestion = ""
        try:  # the unit most likely meant, where the number then is plausible
            hinted = _number(field, unit, f"{value} {hint}", label)
        except ValueError:
            hinted = math.nan
        if low <= hinted <= high:
            suggestion = f", e.g. '{value} {hint}'"
        raise ValueError(
            f"{label} = {value} has no unit and is read in {unit}: {x:g} {unit} is {side} "
            f"{unit}, an implausible magnitude; give its unit{suggestion}"
        )


_TRUE, _FALSE = ("true", "yes", "1"), ("false", "no", "0")


def _flag(value: Any, label: str) -> bool:
    """True or False from a bool or the text ``true``/``yes``/``1``, ``false``/``no``/``0``."""
    if isinstance(value, bool):
        return value
    text = str(value).strip().lower()
    if text in _TRUE + _FALSE:
        return text in _TRUE
    raise ValueError(f"{label}: expected true or false, got {value!r}")


def from_values(values: Mapping[str, Any], where: str = "material") -> Material:
    """A Material from a definition by values (keys: :data:`KEYS`); ValueError naming
    ``where`` for an unknown key, a missing required value or a bad one."""
    fields: dict[str, Any] = {}
    for raw, value in values.items():
        key = str(raw).strip().lower()
        if key in DESCRIPTIVE or (key == "type" and value == "Material"):  # a record's own
            continue
        if key not in KEYS:
            raise ValueError(
                f"{where}: unknown property {str(raw)!r}; allowed: E, nu, Sy (yield_strength), "
                "rho (density), HB (brinell_hardness), n (meyer_index), name, condition, "
                "brittle"
            )
        field, unit = KEYS[key]
        if field in fields:
            raise ValueError(f"{where}: {field} is given twice")
        label = f"{where} {str(raw).strip()}"
        if isinstance(value, Mapping):  # {"value": 95.0, "unit": "kgf/mm^2"}; null: unset
            value = _object(value, unit, label)
        if value is None:  # not given (a JSON null, Python's None): a required one is missing
            continue
        if unit == "bool":
            fields[field] = _flag(value, label)
        else:
            fields[field] = str(value).strip() if unit == "" else _number(field, unit, value, label)
    missing = [_SPELLED[f] for f in REQUIRED if f not in fields]
    if missing:
        raise ValueError(
            f"{where}: a material by values needs E, nu, Sy and rho; missing {', '.join(missing)} "
            f"(e.g. '{EXAMPLE}'; or a library name: {library_names()})"
        )
    name = fields.pop("name", "") or _label(fields)
    try:
        material = Material(name=name, **fields)
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None
    slip = hardness_below_yield(material)
    if slip:
        raise ValueError(f"{where}: {slip}")
    # named as a library entry: that entry (Material refuses the name with other values)
    return library_entry(name) or material


def _object(value: Mapping[str, Any], unit: str, label: str) -> Any:
    """A quantity written ``{"value": x, "unit": u}`` (``impactlab materials NAME --json``): x
    itself when u is the key's own unit (a bare number is in it), else ``"x u"``; None for an
    unset value (x null)."""
    value = {k: v for k, v in value.items() if k != "nonfinite"}  # a record's unset value
    if set(value) != {"value", "unit"} or unit in ("", "bool"):
        raise ValueError(
            f"{label}: expected a number or a quantity ('69 GPa', or {{'value': 69, 'unit': "
            f"'GPa'}} in a mapping), got {dict(value)!r}"
        )
    x, given = value["value"], str(value["unit"]).strip()
    return x if x is None or given in (unit, "") else f"{x} {given}"


def _label(fields: Mapping[str, Any]) -> str:
    """``"custom (E 69 GPa, nu 0.33, Sy 276 MPa, rho 2700 kg/m^3)"``."""
    parts = [
        f"E {fields['E'] / 1e9:.4g} GPa",
        f"nu {fields['nu']:.4g}",
        f"Sy {fields['yield_strength'] / 1e6:.4g} MPa",
        f"rho {fields['density']:.4g} kg/m^3",
    ]
    if "brinell_hardness" in fields:
        parts.append(f"HB {fields['brinell_hardness']:.4g}")
    return f"custom ({', '.join(parts)})"


def _items(text: str, where: str) -> list[str]:
    """``text`` split at each ``,`` or ``;`` outside quotes (``'...'`` or ``"..."``); a quote
    opens only where a value starts, so an apostrophe inside one (``paper's flat``) is text."""
    items, start, quote = [], 0, ""
    for i, ch in enumerate(text):
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "'\"" and _starts_value(text[start:i]):
            quote = ch
        elif ch in ",;":
            items.append(text[start:i])
            start = i + 1
    if quote:
        raise ValueError(f"{where}: a {quote} opened in {text!r} is not closed")
    return [*items, text[start:]]


def _starts_value(item: str) -> bool:
    """Whether the item read so far ends with ``=`` and blanks only: the next character starts
    its value."""
    _key, eq, value = item.partition("=")
    return bool(eq) and not value.strip()


def _unquoted(value: str) -> str:
    """``value`` without one pair of enclosing quotes (``'Al, 6061'`` -> ``Al, 6061``)."""
    if len(value) >= 2 and value[0] == value[-1] and value[0] in "'\"":
        return value[1:-1].strip()
    return value


def parse_values(text: str, where: str = "material") -> dict[str, str]:
    """``"E=69GPa, nu=0.33"`` as ``{"E": "69GPa", "nu": "0.33"}`` (``,`` or ``;`` between; a
    value holding either is quoted: ``name="Al 6061, aged"``)."""
    out: dict[str, str] = {}
    for item in _items(text, where):
        if not item.strip():
            continue
        key, eq, value = item.partition("=")
        value = _unquoted(value.strip())
        if not eq or not key.strip() or not value:
            raise ValueError(
                f"{where}: expected key=value pairs such as '{EXAMPLE}' (quote a value that "
                f'holds a comma: name="Al 6061, aged"), got {item.strip()!r}'
            )
        if key.strip() in out:
            raise ValueError(
                f"{where}: {key.strip()} is given twice ({out[key.strip()]!r} and "
                f"{value!r}); give each property once"
            )
        out[key.strip()] = value
    return out


def from_file(path: Path, where: str = "material") -> Material:
    """A material from a TOML file (the table at top level or under ``[material]``); ValueError
    naming ``where`` and the file when it cannot be read, is not UTF-8 text or not TOML."""
    try:
        data = tomllib.loads(read_text_file(path, "TOML", f"{where}: {str(path)!r}"))
    except OSError as exc:
        raise ValueError(f"{where}: cannot read {str(path)!r}: {exc.strerror or exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{where}: {str(path)!r} is not valid TOML: {exc}") from None
    table = data.get("material", data)
    if not isinstance(table, dict):
        raise ValueError(f"{where}: [material] in {str(path)!r} must be a table")
    beside = sorted(set(data) - {"material"}) if table is not data else []
    if beside:  # never left out without a word
        raise ValueError(
            f"{where}: {str(path)!r} has key(s) {', '.join(beside)} beside its [material] "
            "table, which would not be read: move them into [material] (or give the material "
            "at the top level only)"
        )
    return from_values(table, f"{where} ({path.name})")


def get_material(value: Any, where: str = "material") -> Material:
    """The material ``value`` names or defines; ValueError naming ``where`` otherwise (it lists
    the library's names).

    ``value`` is one of:

    - a :class:`Material`, returned as it is;
    - a library name, case and ``_``/``-`` free, or an alias (``"al-6061-t6"``, ``"6061-t6"``,
      ``"AISI_1010"``); ``list(impactlab.materials.PRESETS)`` (or ``impactlab materials`` on
      the command line) lists them, ``impactlab.materials.ALIASES`` the aliases;
    - a definition by values, as text ``"E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"`` or as a
      mapping with the same keys (case free). Required: ``E`` (Young's modulus, Pa), ``nu``
      (Poisson's ratio), ``Sy`` or ``S_y`` or ``yield_strength`` (Pa), ``rho`` or ``density``
      (kg/m^3). Optional: ``HB`` or ``brinell_hardness`` (kgf/mm^2; ``"95 HB"``), ``n`` or
      ``meyer_index``, ``name``, ``condition``, ``brittle`` (true/false). A quantity carries
      its unit (``"69 GPa"``, or ``{"value": 69, "unit": "GPa"}`` in a mapping); a bare number
      is in SI (Pa, kg/m^3; HB in kgf/mm^2);
    - the path of a TOML file (a ``Path``, or text ending in ``.toml``) holding such a table,
      at its top level or under ``[material]``.

    Example::

        >>> from impactlab import get_material
        >>> get_material("6061-t6").name
        'aluminium 6061-T6'
        >>> get_material({"E": "69 GPa", "nu": 0.33, "Sy": "276 MPa", "rho": 2700}).E
        69000000000.0
    """
    if isinstance(value, Material):
        return value
    if isinstance(value, Mapping):
        return from_values(value, where)
    if isinstance(value, Path):
        return from_file(value, where)
    if not isinstance(value, str) or not value.strip():
        raise ValueError(
            f"{where}: expected a material name, 'key=value' properties or a TOML file, "
            f"got {value!r}"
        )
    text = value.strip()
    if "=" in text:
        return from_values(parse_values(text, where), where)
    entry = from_library(text)
    if entry is not None:
        return entry
    prefix = "" if where == "material" else f"{where}: "  # a caller's wrapper names its input
    if text.lower().endswith(".toml"):
        path = Path(text)
        if not path.is_file():
            raise ValueError(f"{prefix}material file {text!r} does not exist")
        return from_file(path, where)
    if ("/" in text or "\\" in text) and Path(text).exists():  # a path, not a name
        what = "a folder" if Path(text).is_dir() else "a file whose name does not end in .toml"
        raise ValueError(
            f"{prefix}{text!r} is {what}; give a material's name, its properties "
            f"('{EXAMPLE}') or a TOML file (.toml)"
        )
    near = nearest(name_key(text))
    raise ValueError(
        f"{prefix}unknown material {text!r}{near}; known: {library_names()} (see 'impactlab "
        f"materials'), or give its properties: '{EXAMPLE}'"
    )


def library_key(material: Material) -> str | None:
    """The library name of ``material`` when it is a library entry, unchanged; else None."""
    return next((k for k, m in PRESETS.items() if m == material), None)
