"""What the documentation states about the code stays equal to the code: the number of friction
models and contact laws, the flags, the default tolerances and friction coefficient, the range
of e, and the compile-time wording of the tutorials."""

from __future__ import annotations

import math
import re
from pathlib import Path

import impactlab as il
from impactlab.contact import builtin_law_names
from impactlab.dynamics.kernels.layout import DEFAULT_RTOL, PARTIAL_SLIP_RTOL
from impactlab.flags import ResultFlag
from impactlab.friction import DEFAULT_MU, friction_names

ROOT = Path(__file__).resolve().parents[2]
USER_DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
WORDS = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"]
NUMBERS = {w: i for i, w in enumerate(WORDS)}


def _texts() -> dict[str, str]:
    return {str(p.relative_to(ROOT)): p.read_text() for p in USER_DOCS if "dev" not in p.parts}


def test_the_count_of_friction_models_is_the_codes() -> None:
    """Every "the N friction models" and "N of the M friction models" counts them all."""
    n = len(friction_names())
    rule = re.compile(r"\b(?:the|all|of the) (\w+) friction models\b")
    wrong = [
        f"{name}: {m.group(0)!r}"
        for name, text in _texts().items()
        for m in rule.finditer(" ".join(text.split()))
        if NUMBERS.get(m.group(1).lower(), n) != n
    ]
    assert not wrong, f"{n} friction models ({', '.join(friction_names())}); docs say: {wrong}"


def test_the_count_of_laws_is_the_codes() -> None:
    """The built-in laws (a law registered by another test, or a user, is not the docs' count)."""
    text = " ".join((ROOT / "docs" / "flexible.md").read_text().split())
    assert f"the {WORDS[len(builtin_law_names())]} laws" in text


def test_glossary_names_every_flag() -> None:
    row = next(ln for ln in (ROOT / "docs/glossary.md").read_text().splitlines()
               if ln.startswith("| `flags`"))  # fmt: skip
    missing = [f.name for f in ResultFlag if f.name and f.value and f"`{f.name}`" not in row]
    assert not missing, f"the glossary's flags row misses {missing}"


def test_documented_defaults() -> None:
    doc = il.simulate.__doc__ or ""
    rule = r"``DEFAULT_RTOL`` = ([0-9.e-]+); ([0-9.e-]+) for\s+``friction=\"partial_slip\"``"
    m = re.search(rule, doc)
    assert m, "simulate's docstring names its default tolerances"
    assert (float(m.group(1)), float(m.group(2))) == (DEFAULT_RTOL, PARTIAL_SLIP_RTOL)
    glossary = (ROOT / "docs/glossary.md").read_text()
    stated = re.search(r"`impactlab\.friction\.DEFAULT_MU = ([0-9.]+)`", glossary)
    assert stated and float(stated.group(1)) == DEFAULT_MU


def test_glossary_range_of_e_and_its_example() -> None:
    """The glossary does not promise e <= 1 where the engine (rightly) exceeds it, and its
    example is the engine's number."""
    row = next(ln for ln in (ROOT / "docs/glossary.md").read_text().splitlines()
               if ln.startswith("| `e` |"))  # fmt: skip
    assert "[0, 1]" not in row
    stated = float(re.search(r"e = (1\.\d+) for the paper's rod at 45 deg", row).group(1))
    r = il.simulate(il.Rod.paper(), law="hertz", mu=0.0, angle=math.radians(45),
                    velocity=(0.0, -1.41))  # fmt: skip
    assert round(r.e, 4) == stated > 1.0


def test_tutorials_do_not_promise_a_one_minute_compile_of_everything() -> None:
    text = " ".join((ROOT / "docs/tutorials/index.md").read_text().split())
    assert "about 15-20 s more for each of partial slip, the flexible rod and the batch" in text
    assert "every part, about 80 s" in text
    readme = " ".join((ROOT / "README.md").read_text().split())
    assert "`impactlab warm`" in readme
