"""The library's names on materials: which entry a name names, the rule that a material by
values carries a library name only with that entry's values, and the nearest name to an unknown
one.

A name names a library entry when it is the entry's key, an alias or its display name (case,
``_``, ``-`` and spaces free). A material whose values are that entry's, each to
:data:`SAME_VALUE_RTOL` (the round-off of a unit conversion: ``rho=7.87 g/cm^3`` is
7869.999999999999 kg/m^3), may carry the name; with any other value it is refused
(:func:`library_name_clash`), in ``Material(...)`` as in ``get_material``'s text, mapping and
TOML forms.
"""

from __future__ import annotations

import difflib
import math
import re
import sys
from typing import Any

from impactlab._validation import value_text

#: A material (``impactlab.materials.core.Material``), typed loosely here: ``core`` imports this
#: module, so this module does not import ``core``.
Material = Any

#: Two values of a material are the same when they agree to this relative tolerance
#: (``math.isclose``): 1 part in 10^7, far below any source's precision (3 or 4 significant
#: digits) and above the round-off of a unit conversion: a value in g/cm^3 (1e-16), or in the
#: sources' psi, ksi and lb/in^3 converted with a 7-digit ksi (4e-8, the finite-element
#: reference's stored AISI 52100 values).
SAME_VALUE_RTOL = 1e-7

#: The values a material with a library entry's name must share with it (value -> its unit in
#: messages).
COMPARED: dict[str, str] = {
    "E": "Pa",
    "nu": "",
    "yield_strength": "Pa",
    "brinell_hardness": "kgf/mm^2",
    "meyer_index": "",
    "density": "kg/m^3",
    "brittle": "",
}


def name_key(name: str) -> str:
    """``name`` as the library compares names: lower case, ``_`` and spaces as ``-``."""
    return name.strip().lower().replace("_", "-").replace(" ", "-")


def _library() -> tuple[dict[str, Material], dict[str, str]]:
    """The library's entries and aliases; empty while the library is being built."""
    library = sys.modules.get("impactlab.materials.library")
    return getattr(library, "PRESETS", None) or {}, getattr(library, "ALIASES", None) or {}


def library_entry(name: str) -> Material | None:
    """The library entry whose key, alias or display name ``name`` is (case, ``_``, ``-`` and
    spaces free); None for any other name."""
    presets, aliases = _library()
    key = name_key(name)
    entry = presets.get(aliases.get(key, key))
    if entry is not None:
        return entry
    return next((m for m in presets.values() if name_key(m.name) == key), None)


def modified_entry(name: str) -> Material | None:
    """The library entry of a display name that ``Material`` labelled as a changed copy
    (``"AISI 1010, modified (E, nu)"``); None for any other name."""
    base, sep, rest = name.partition(", modified (")
    if not (sep and rest.endswith(")")):
        return None
    entry = library_entry(base)
    return entry if entry is not None and entry.name == base else None


def values_differ(a: Any, b: Any, rel_tol: float = 0.0) -> bool:
    """True unless ``a`` and ``b`` are the same value: both unset (None, or both NaN), the
    same flag, or numbers equal to ``rel_tol`` (``math.isclose``; 0: exactly equal)."""
    if a is None or b is None or isinstance(a, bool) or isinstance(b, bool):
        return bool(a != b)
    x, y = float(a), float(b)
    if math.isnan(x) or math.isnan(y):
        return not (math.isnan(x) and math.isnan(y))
    return not math.isclose(x, y, rel_tol=rel_tol, abs_tol=0.0)


def _shown(value: Any, unit: str, digits: int) -> str:
    if isinstance(value, bool):
        return "yes" if value else "no"
    if value is None or math.isnan(value):
        return "unset"
    return f"{value:.{digits}g}{f' {unit}' if unit else ''}" if digits else value_text(value, unit)


def shown(field: str, given: Any, library: Any) -> str:
    """``"given unit; the library's value unit"`` for an error (``unset`` for a value not
    given): each the shortest text that reads back as it, both to 12 significant digits where
    either needs as many (the round-off of a unit conversion), so that two values that differ
    by more than :data:`SAME_VALUE_RTOL` read apart in the same notation."""
    unit = COMPARED[field]
    numbers = [x for x in (given, library) if isinstance(x, float) and math.isfinite(x)]
    long = any(next(n for n in range(17) if float(f"{x:.{n}e}") == x) >= 11 for x in numbers)
    digits = 12 if long else 0  # value_text's own rule for one such value
    return f"{_shown(given, unit, digits)}; the library's {_shown(library, unit, digits)}"


def library_name_clash(material: Material) -> str:
    """Why ``material`` may not carry its name ("" when it may): the name is a library entry's
    (:func:`library_entry`) and a value differs from the entry's by more than
    :data:`SAME_VALUE_RTOL`."""
    entry = library_entry(material.name)
    if entry is None:
        return ""
    differ = [
        f
        for f in COMPARED
        if values_differ(getattr(material, f), getattr(entry, f), SAME_VALUE_RTOL)
    ]
    if not differ:
        return ""
    key = next(k for k, m in _library()[0].items() if m is entry)
    values = ", ".join(f"{f} ({shown(f, getattr(material, f), getattr(entry, f))})" for f in differ)
    return (
        f"name {material.name!r} is a library material with other values: it names {key!r}, "
        f"which differs in {values}; a material by values may carry a library name only with "
        f"every value of that entry, the unset ones too: give another name, or "
        f"get_material({key!r}) for the library's entry"
    )


def _bare(text: str) -> str:
    return re.sub(r"[-._]", "", text)


#: A stainless steel named by its AISI grade (``ss-316``, ``sst-304``, ``stainless-316l``): the
#: hint treats it as ``aisi-316``, among the library's stainless steels alone.
STAINLESS = re.compile(r"(?:sst|ss|stainless)-?(?=\d)")


def _names(display: bool = True, among: frozenset[str] | None = None) -> dict[str, str]:
    """The library's names -> their entry's key: keys, aliases and (``display``) the display
    names (:func:`name_key`); of the entries ``among`` alone where given."""
    presets, aliases = _library()
    names = {k: k for k in presets} | dict(aliases)
    names |= {name_key(m.name): k for k, m in presets.items()} if display else {}
    return {n: k for n, k in names.items() if among is None or k in among}


def _words(among: frozenset[str] | None = None) -> dict[str, str]:
    """The first word of each of the library's names (``aluminium``, ``alumina``, ``soda``) ->
    its entry's key, where that word names one entry alone."""
    owners: dict[str, set[str]] = {}
    for name, key in _names(among=among).items():
        word = re.split(r"[-(,%]", name)[0]
        if len(word) >= 3:
            owners.setdefault(word, set()).add(key)
    return {w: next(iter(k)) for w, k in owners.items() if len(k) == 1}


def _ratio(a: str, b: str) -> float:
    return difflib.SequenceMatcher(None, a.replace("_", "-"), b.replace("_", "-")).ratio()


def _listed(keys: list[str]) -> str:
    """`` (did you mean 'x'?)``; for several entries each with its display name, in the
    library's order."""
    presets = _library()[0]
    keys = sorted(keys, key=list(presets).index)
    items = [f"{k!r} ({presets[k].name})" for k in keys] if len(keys) > 1 else [repr(keys[0])]
    text = items[0] if len(items) == 1 else f"{', '.join(items[:-1])} or {items[-1]}"
    return f" (did you mean {text}?)"


def nearest(key: str, among: frozenset[str] | None = None) -> str:
    """`` (did you mean 'x'?)`` for the library entry nearest to ``key`` (:func:`name_key`):

    - the entry one of whose keys or aliases has ``key`` as its first word (``al``:
      al-6061-t6), else one whose key or alias holds ``key`` or is held by it (``-``, ``.`` and
      ``_`` aside; ``soda``: soda-lime-glass, the closest such); where ``key`` begins the names
      of several entries, each of them (``alu``: ``'al-6061-t6' (aluminium 6061-T6) or
      'alumina-99.5' (alumina 99.5 %)``);
    - else the nearest spelling of a key, an alias, a display name or the first word of one
      (``alumnium``: al-6061-t6, whose display name and aliases say aluminium);
    - ``""`` for none, and for one character (``a``: nothing is near).

    An entry of another grade or temper (``al-6061-t4``: al-6061-t6; ``aisi-1018``: aisi-1010;
    ``alumina-96``; ``aisi-304l``) is named as such, not as a spelling of the name
    (:func:`_other_grade`): the entry of its family whose grade number is nearest
    (``aisi-316``: aisi-304). A stainless steel by its grade (:data:`STAINLESS`: ``ss-316``)
    is named as ``aisi-316`` is, among the library's stainless steels alone; ``among``: the
    entries that may be named (None: all)."""
    if (stainless := STAINLESS.match(key)) is not None:
        presets = _library()[0]
        steels = frozenset(k for k, m in presets.items() if "stainless" in m.name.lower())
        return nearest(f"aisi-{key[stainless.end() :]}", steels) if steels else ""
    names = _names(display=False, among=among)
    k = _bare(key)
    if len(k) < 2 or not names:
        return ""
    holding = [n for n in names if k in _bare(n) or (len(_bare(n)) >= 3 and _bare(n) in k)]
    holding = [n for n in holding if n.split("-")[0] == key] or holding
    if not holding:
        names, words = _names(among=among), _words(among)  # a first word: a closer spelling
        score = {n: _ratio(key, n) for n in names} | {w: _ratio(key, w) - 0.15 for w in words}
        best = max(score, key=lambda n: score[n])
        if score[best] < 0.6:
            return ""
        return _graded(key, best, names.get(best) or words[best], among)
    ranked = difflib.get_close_matches(key, holding, n=len(holding), cutoff=0.0) or holding
    starting = list(dict.fromkeys(names[n] for n in ranked if _bare(n).startswith(k)))
    if len(starting) > 1:
        return _listed(starting[:4])
    return _graded(key, ranked[0], names[ranked[0]], among)


def _number(name: str) -> float | None:
    """The grade number of a library name: the first number after its family (``aisi-304l``:
    304; ``alumina-99.5``: 99.5); None for none."""
    found = re.search(r"\d+(?:\.\d+)?", name.partition("-")[2])
    return float(found.group()) if found else None


def _graded(key: str, name: str, entry: str, among: frozenset[str] | None = None) -> str:
    """:func:`_listed` for ``entry`` (found by its key or alias ``name``), or, where ``name``
    or ``entry`` is another grade or temper than ``key``, a hint that says so, naming the entry
    of that family (``among`` them where given) whose grade number is nearest ``key``'s."""
    if not (_other_grade(key, name) or _other_grade(key, entry)):
        return _listed([entry])
    number, family = _number(key), entry.split("-")[0]
    if number is not None:
        grades = [
            g
            for g in _library()[0]
            if g.split("-")[0] == family and (among is None or g in among) and _other_grade(key, g)
        ]
        distance = {g: abs(n - number) for g in grades if (n := _number(g)) is not None}
        entry = min([entry, *distance], key=lambda g: distance.get(g, math.inf))
    display = _library()[0][entry].name
    return (
        f" (the library's nearest is {entry!r} ({display}), another grade or temper: not "
        "the same material, its properties differ)"
    )


def _other_grade(key: str, name: str) -> bool:
    """Whether the library name ``name`` designates another grade or temper than ``key``: the
    same family (the first word, split at ``-``) and a designation that is no typo of the
    entry's (``al-6061-t4``, ``al-2024-t3``, ``al-6061-o``: al-6061-t6; ``aisi-1045``); a typo
    is a designation that completes the other (``aisi-20``: aisi-201), the same characters
    reordered (``alumina-9.95``), or one character more or less (``al-661-t6``,
    ``aisi-512100``). Letters after the entry's grade number name another grade (``aisi-304l``,
    the low-carbon 304; ``aisi-304h``)."""
    mine, theirs = key.lower().split("-", 1), name.lower().split("-", 1)
    if len(mine) < 2 or len(theirs) < 2 or mine[0] != theirs[0] or mine[1] == theirs[1]:
        return False
    a, b = mine[1], theirs[1]
    if a.startswith(b) and b[-1].isdigit() and re.fullmatch(r"[a-z]{1,2}", a[len(b) :]):
        return True
    if a.startswith(b) or b.startswith(a) or sorted(a) == sorted(b):
        return False
    short, long_ = sorted((a, b), key=len)
    one_more = len(long_) == len(short) + 1 and any(
        long_[:k] + long_[k + 1 :] == short for k in range(len(long_))
    )
    return not one_more
