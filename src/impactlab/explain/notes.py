"""An explanation's notes: one line per reason a configuration did not run and per caveat of an ok
row (naming the configurations that give it), per verdict that leaves a quantity out, names no
configuration, names one inconsistent with the measurements or is provisional, per drop whose
chi2 takes its correlation coefficients, and per warning of the runs, each naming its drops.
Lines that differ only in their numbers (a rate factor, a ratio, a mode count per drop) are one
line: a number that differs between them is given as its range (``k = 2.659 to 2.692``); each
row's own numbers are in its status or caveat (``summary``, JSON). Lines whose differing numbers
include one in a "from A to B" phrase (a mode caveat's "e moves from 0.3518 to 0.3254") stay
apart: a range there would read as a chain of values ("from 0.3518 to 0.3611 to 0.3254")."""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence

import pandas as pd

from impactlab.explain.correlated import Pairs, correlation_note
from impactlab.explain.runs import Outcome
from impactlab.explain.verdict import Verdict

__all__ = ["explanation_notes", "grouped"]

#: A number in a message (not one inside a word: ``aisi-1010``, ``al6061t6``).
_NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?!\w|\.\d)")
#: Text before a number, or after it, that makes it part of a "from A to B" phrase.
_FROM_TO_BEFORE = re.compile(r"\b(?:from|to)\s*$")
_FROM_TO_AFTER = re.compile(r"^\s*to\b")


def _pieces(text: str, kept: Sequence[str]) -> list[tuple[bool, str]]:
    """``text`` as (is a number, piece): numbers apart, the strings ``kept`` (the names of the
    configurations, whose numbers are part of the name) whole in the text between them."""
    names = sorted({k for k in kept if k}, key=len, reverse=True)
    parts = re.split(f"({'|'.join(map(re.escape, names))})", text) if names else [text]
    out: list[tuple[bool, str]] = []
    for part in parts:
        if part in names:
            out.append((False, part))
            continue
        at = 0
        for m in _NUMBER.finditer(part):
            out += [(False, part[at : m.start()]), (True, m.group())]
            at = m.end()
        out.append((False, part[at:]))
    return out


def _span(values: list[str]) -> str:
    """One number as text, or the range of those that differ: ``2.659 to 2.692``."""
    distinct = list(dict.fromkeys(values))
    low, high = min(distinct, key=float), max(distinct, key=float)
    return low if float(low) == float(high) else f"{low} to {high}"


def _in_phrase(pieces: list[tuple[bool, str]], i: int) -> bool:
    """Whether the number ``pieces[i]`` stands in a "from A to B" phrase."""
    before = pieces[i - 1][1] if i > 0 else ""
    after = pieces[i + 1][1] if i + 1 < len(pieces) else ""
    return bool(_FROM_TO_BEFORE.search(before) or _FROM_TO_AFTER.match(after))


def _merged(
    members: list[tuple[list[tuple[bool, str]], str]],
) -> list[tuple[str, list[str]]]:
    """One group's texts (same words, numbers apart) as one text with ranges, or, where a
    number that differs stands in a "from A to B" phrase, each distinct text apart."""
    first = members[0][0]
    differ = [i for i, (number, _) in enumerate(first)
              if number and len({float(m[0][i][1]) for m in members}) > 1]  # fmt: skip
    if any(_in_phrase(first, i) for i in differ):
        apart: dict[str, list[str]] = {}
        for pieces, where in members:
            apart.setdefault("".join(p for _, p in pieces), []).append(where)
        return [(text, list(dict.fromkeys(w))) for text, w in apart.items()]
    text = "".join(
        _span([m[0][i][1] for m in members]) if number else piece
        for i, (number, piece) in enumerate(first)
    )
    return [(text, list(dict.fromkeys(where for _, where in members)))]


def grouped(
    lines: Iterable[tuple[str, str]], kept: Sequence[str] = ()
) -> list[tuple[str, list[str]]]:
    """(text, where) pairs as (text, [where, ...]): the texts that differ only in their numbers
    (outside the strings ``kept``) in one, a number that differs given as its range, except
    where such a number stands in a "from A to B" phrase (those texts stay apart; module
    docstring); in order of first appearance."""
    groups: dict[tuple[str, ...], list[tuple[list[tuple[bool, str]], str]]] = {}
    for text, where in lines:
        pieces = _pieces(text, kept)
        key = tuple("#" if number else piece for number, piece in pieces)
        groups.setdefault(key, []).append((pieces, where))
    return [line for members in groups.values() for line in _merged(members)]


def explanation_notes(
    outcomes: Mapping[tuple[str, str], Outcome],
    summary: pd.DataFrame,
    verdicts: Iterable[Verdict] = (),
    correlation: Mapping[str, Pairs] | None = None,
) -> tuple[str, ...]:
    """The notes (module docstring): why a configuration did not run, the caveats of ok rows,
    the verdicts with a quantity left out, no configuration named, an inconsistent one named or
    provisional, the drops
    whose chi2 takes their ``correlation`` coefficients (drop -> pair -> coefficient), how
    many runs used the law beyond its range, and the runs' warnings (with the drops and
    configurations)."""
    names = list(dict.fromkeys(name for _, name in outcomes))
    rows = [(name, out.status, drop) for (drop, name), out in outcomes.items() if not out.ok]
    rows += [(str(r.configuration), str(r.caveat), str(r.drop))
             for r in summary[summary["caveat"] != ""].itertuples(index=False)]  # fmt: skip
    said: dict[tuple[str, tuple[str, ...]], list[str]] = {}  # (text, drops) -> configurations
    for name in dict.fromkeys(r[0] for r in rows):
        for text, drops in grouped(((t, d) for n, t, d in rows if n == name), names):
            said.setdefault((text, tuple(drops)), []).append(name)
    lines = [f"{', '.join(who)}: {text} (drops: {', '.join(drops)})"
             for (text, drops), who in said.items()]  # fmt: skip
    best = grouped(((v.note, v.drop) for v in verdicts if v.note), names)
    lines += [f"{text} (drops: {', '.join(drops)})" for text, drops in best]
    joint = grouped((correlation_note(p), d) for d, p in (correlation or {}).items())
    lines += [f"{text} (drops: {', '.join(drops)})" for text, drops in joint if text]
    ran = [out for out in outcomes.values() if out.ran]  # the runs that gave a result
    beyond = sum(out.law_extrapolated for out in ran)
    if beyond:
        lines.append(
            f"the contact law is used beyond its verified range in {beyond} of {len(ran)} runs "
            "(flag law_extrapolated, advisory: the prediction is kept, its own error unknown)"
        )
    warned = [(w, f"{drop} / {name}") for (drop, name), out in outcomes.items()
              for w in out.warnings]  # fmt: skip
    lines += [f"warning ({', '.join(where)}): {w}" for w, where in grouped(warned, names)]
    return tuple(lines)
