"""The text of a quantity as a user writes it, read before pint parses it (``impactlab.units``).

pint computes with what it is given and drops what it does not know without a word: a decimal
comma is a thousands separator, a Unicode minus sign is nothing, ``"2*1.41 m/s"`` is 2.82 m/s.
Here are the checks that make the number pint reads the one written (one number, ``_`` digit
groups allowed; the exponent of a unit, ``m^2``, is no number), the minus signs and the
characters text may hold, and bare numbers (text that is only a number).
"""

from __future__ import annotations

import math
import numbers
import re
import unicodedata
from typing import Any

#: Digits, ``_`` between two of them allowed as a group separator (``1_000``, as Python and pint
#: read it); a number (digits, decimal point); its exponent (``e-3``).
_DIGITS = r"[0-9](?:_?[0-9])*"
_NUM = rf"(?:{_DIGITS}(?:\.(?:{_DIGITS})?)?|\.{_DIGITS})"
_EXP = rf"(?:[eE][+-]?{_DIGITS})?"
#: A leading number (sign, digits, decimal point, exponent) and what follows it.
_LEADING_NUMBER = re.compile(rf"\s*[+-]?{_NUM}{_EXP}(.*)")
#: A number not glued to a name or to another number (the 2 of ``m2`` is none); the same with
#: its exponent (``1.41e-3``): the first number of a text (``"(2*3) m"``).
_NUMBER = re.compile(rf"(?<![\w.]){_NUM}")
_FIRST_NUMBER = re.compile(rf"(?<![\w.]){_NUM}{_EXP}")
#: What precedes the exponent of a unit (``m^2``, ``s**-1``): a unit or a bracket, ``^`` or ``**``,
#: a sign; right after the leading number it makes a power of that number (``2**2 m``).
_POWER = re.compile(r"\S\s*(?:\^|\*\*)\s*[+-]?\s*$")
#: Minus signs besides '-' and Unicode's dashes (Pd), which pint drops without a word
#: (``"\u22120.3 m/s"`` would be +0.3 m/s): minus, modifier, commercial, heavy; soft hyphen.
_MINUS_SIGNS = "\u2212\u02d7\u2052\u2796\u00ad"
_DIGIT_AHEAD = re.compile(r"\.?[0-9]")  # what makes a dash a minus sign: a number after it
_TIMES = "\u00b7\u00d7\u22c5\u2219"  # multiplication signs (pint drops most): written ``*``
_ASCII = ".+-*/^()_%,"  # the ASCII text holds besides letters, digits, spaces (a comma: refused)
_SYMBOLS = "°‰⁰¹²³⁴⁵⁶⁷⁸⁹⁻"  # others pint reads: degree, per mille, superscript digits, minus
#: The 1 of a reciprocal unit (``1/s``, ``(1/s)``): a unit, not a second number (``1/2`` is one).
_RECIPROCAL = re.compile(r"(^|[\s(])1\s*/(?=\s*[A-Za-z(])")


def one_number(name: str, text: str, shown: str, unit: str) -> None:
    """ValueError naming ``name`` unless ``text`` (the user's ``shown``) holds one number: pint
    computes with numbers side by side or joined by arithmetic, so ``"20 deg 3"`` would be
    60 deg, ``"1.41 m/s 2"`` and ``"2*1.41 m/s"`` 2.82 m/s, ``"1.41/2 m/s"`` 0.705 m/s and
    ``"2**2 m"`` 4 m. The 1 of a reciprocal unit (``"6500 1/s"``) and the exponent of a unit
    (``m^2``, ``s**-1``) are no second number."""
    lead = _LEADING_NUMBER.fullmatch(text)
    if lead is not None:
        rest = lead.group(1)
    else:  # "(2*3) m", "- 0.3 m/s": the first number, wherever it stands
        first = first_number(text)
        rest = text if first is None else f"{text[: first.start()]} {text[first.end() :]}"
    rest = _RECIPROCAL.sub(r"\1/", rest)  # "6500 1/s" holds one number
    if plain(unit) and rest.strip() == "1":  # "0.02 1": a pure number in the unit 1
        rest = ""
    if any(not _POWER.search(rest[: m.start()]) for m in _NUMBER.finditer(rest)):
        raise ValueError(
            f"{name}: {shown!r} holds more than one number (pint would compute with them); "
            f"{write_one(unit)}"
        )


def _is_dash(c: str) -> bool:
    """True for a dash or minus sign other than ``-`` (:data:`_MINUS_SIGNS`, Unicode's Pd)."""
    return c != "-" and (c in _MINUS_SIGNS or unicodedata.category(c) == "Pd")


def read_minus(text: str) -> str:
    """``text`` with each dash or minus sign right before a number written ``-`` (``"\u22124"``
    -> ``"-4"``, ``"1.41e\u20133 m/s"`` -> ``"1.41e-3 m/s"``); the rest unchanged."""
    return "".join(
        "-" if _is_dash(c) and _DIGIT_AHEAD.match(text, i + 1) else c for i, c in enumerate(text)
    )


def bare_number(value: Any) -> float | None:
    """The number of ``value`` when it states no unit: a real number (not a bool), or text that
    is only a number (as ``float`` reads it, any dash being ``-``: ``"\u22124"`` -> -4.0); None
    for anything else (``"4 m/s"``, ``"fast"``)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real | str):
        return None
    text = "".join("-" if _is_dash(c) else c for c in value) if isinstance(value, str) else value
    try:
        return float(text)
    except ValueError:
        return None


def bare_text(value: Any) -> Any:
    """``value`` with ``-`` for its minus sign when it is text that is only a number
    (``"\u22124"`` -> ``"-4"``, :func:`bare_number`); any other value unchanged."""
    number = bare_number(value) if isinstance(value, str) else None
    return value if number is None else "".join("-" if _is_dash(c) else c for c in value)


def minus_signs(name: str, text: str, unit: str) -> str:
    """``text`` with its minus signs read (:func:`read_minus`), spaces ``" "``, multiplication
    signs ``*``; ValueError naming ``name`` for a dash elsewhere (``"0.3 \u2013 m/s"``)."""
    out = read_minus(text)
    bad = next((c for c in out if _is_dash(c)), None)
    if bad is not None:
        example = "-0.4" if plain(unit) else f"-1.0 {unit}"
        raise ValueError(
            f"{name}: {text!r} holds a dash (U+{ord(bad):04X}) that is not a minus sign right "
            f"before a number; write a negative value with '-', e.g. '{example}'"
        )
    return "".join(" " if c.isspace() else "*" if c in _TIMES else c for c in out)


def characters(name: str, text: str, shown: str, unit: str) -> None:
    """ValueError naming ``name`` for a character of ``text`` (the user's ``shown``) that pint
    would drop or misread (``"0.3 m # note"``, a zero-width space): text holds letters (``µm``,
    ``Å``), ASCII digits, spaces, :data:`_ASCII` and :data:`_SYMBOLS` (``°``, ``s⁻¹``)."""
    for c in text:
        if c.isascii() and (c.isalnum() or c == " " or c in _ASCII):
            continue
        nfkc = unicodedata.normalize("NFKC", c)
        letter = c.isalpha() and nfkc.isalpha() and f"a{c}".isidentifier()
        if not c.isascii() and (letter or c in _SYMBOLS):  # not a mark pint drops: U+0E33
            continue
        what = f"U+{ord(c):04X} {unicodedata.name(c, '')}".rstrip()
        raise ValueError(
            f"{name}: {shown!r} holds {c!r} ({what}), which quantity text cannot hold (pint "
            f"would drop or misread it); {write_one(unit)}"
        )


#: The named number a quantity text may hold instead of digits (``"pi/4 rad"``).
_PI = re.compile(r"(?<![A-Za-z_])pi(?![A-Za-z_])|\u03c0")


def first_number(text: str) -> re.Match[str] | None:
    """The first number of ``text`` that is not the exponent of a unit (the 2 of ``m^2``, of
    ``kg m**2``, of ``s^-2``); None when it holds none (``"m/s^2"``, ``"pi rad"``)."""
    found = (m for m in _FIRST_NUMBER.finditer(text) if not _POWER.search(text[: m.start()]))
    return next(found, None)


def written(name: str, text: str, shown: str, q: Any, unit: str) -> None:
    """ValueError naming ``name`` unless pint read the number written in ``text`` (the user's
    ``shown``; its reciprocal after a slash, ``"pi/4 rad"``): a power computes another
    (``"(2)^2 m"`` is 4 m, ``"10\u207b\u00b3 m"`` 0.001 m), and a text with no number (a unit
    alone, ``" deg"``, ``"-m/s"``: pint reads 1 of it, a value left out) unless it names pi
    (``"pi rad"``); a NaN or infinity is left to the caller's finiteness check."""
    if not math.isfinite(float(q.magnitude)):
        return
    first = first_number(text)
    if first is None and not _PI.search(text):
        raise ValueError(f"{name}: {shown!r} holds a unit but no number; {write_one(unit)}")
    m, x = abs(float(q.magnitude)), float(first.group()) if first else 1.0
    over = first is not None and text[: first.start()].rstrip().endswith("/")  # pi/4: 1/4
    if first and not math.isclose(m, 1.0 / x if over and x else x, rel_tol=1e-12):
        raise ValueError(
            f"{name}: {shown!r} holds more than one number (pint would compute with them: "
            f"{q:~}); {write_one(unit)}"
        )


def plain(unit: str) -> bool:
    """True for the unit of a pure number (``"1"`` or empty)."""
    return unit.strip() in ("", "1")


def write_one(unit: str) -> str:
    """The hint of a refused quantity text: one number with ``unit`` (a plain one for a pure
    number: ``'1.0 1'`` would itself be refused)."""
    if plain(unit):
        return "write one plain number, e.g. '0.4'"
    return f"write one number and its unit, e.g. '1.0 {unit}'"


def refuse_comma(name: str, text: str, unit: str) -> None:
    """ValueError naming ``name`` when the quantity text ``text`` holds a comma: pint drops it
    as a thousands separator, so a decimal comma ``"2,5 mm"`` would read as 25 mm."""
    if "," in text:
        if text.strip()[:1] in "([":  # a pair written as one string: its values one by one
            raise ValueError(
                f"{name}: {text!r} is one string; give each component as its own quantity, "
                f"e.g. ('0 {unit}', '-1.41 {unit}')"
            )
        example = text.strip().replace(",", ".") if text.count(",") == 1 else f"2.5 {unit}"
        raise ValueError(
            f"{name}: {text!r} holds a comma; write one quantity with a decimal point, e.g. "
            f"'{example}' (a comma would be read as a thousands separator: '2,5' as 25)"
        )
