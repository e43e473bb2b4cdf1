"""Docstrings and comments name what exists: the calibration's lock error by its name, the
fields of a parsed ``.dat`` file, the Monte Carlo function; and the FE modules keep no function
nothing calls (every ``def`` of ``fe/mesh.py`` and ``fe/accuracy.py`` is used somewhere in the
package, the tests, the benchmarks, the tools, the examples or the docs)."""

from __future__ import annotations

import dataclasses
import importlib
import re
from collections import Counter
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SRC = ROOT / "src" / "impactlab"


def test_the_lock_error_is_named_as_it_is_defined() -> None:
    lock = (SRC / "calibrate" / "statelock.py").read_text(encoding="utf-8")
    classes = set(re.findall(r"^class (\w+)", lock, flags=re.M))
    assert "StateInUseError" in classes
    for name in ("api.py", "sampler.py"):
        text = (SRC / "calibrate" / name).read_text(encoding="utf-8")
        named = set(re.findall(r"\bStateInUse\w*", text))
        assert named and named <= classes, (name, named - classes)


def test_the_dat_file_docstring_names_its_fields() -> None:
    from impactlab.fe.ccx import DatFile

    fields = {f.name for f in dataclasses.fields(DatFile)}
    doc = DatFile.__doc__ or ""
    named = set(re.findall(r"``([a-z_]+)``", doc)) | set(re.findall(r"``([a-z_]+)\[", doc))
    assert named and named <= fields, named - fields


@pytest.mark.parametrize("module", ["impactlab.analytic.monte_carlo"])
def test_the_comments_name_what_the_module_defines(module: str) -> None:
    mod = importlib.import_module(module)
    path = Path(mod.__file__ or "")
    comments = [ln for ln in path.read_text(encoding="utf-8").splitlines() if "#" in ln]
    named = {n for ln in comments for n in re.findall(r"``([A-Za-z_]\w*)``", ln)}
    assert named
    assert all(hasattr(mod, n) for n in named), sorted(n for n in named if not hasattr(mod, n))


_SEARCHED = ("src", "tests", "benchmarks", "tools", "examples", "notebooks", "docs")


@pytest.fixture(scope="module")
def words() -> Counter[str]:
    """Every word of the files searched, counted."""
    counts: Counter[str] = Counter()
    for top in _SEARCHED:
        for p in (ROOT / top).rglob("*"):
            if p.suffix in {".py", ".md", ".ipynb"} and "__pycache__" not in p.parts:
                counts.update(re.findall(r"\w+", p.read_text(encoding="utf-8", errors="replace")))
    return counts


@pytest.mark.parametrize("source", ["fe/mesh.py", "fe/accuracy.py"])
def test_every_function_of_the_fe_module_is_used(source: str, words: Counter[str]) -> None:
    text = (SRC / source).read_text(encoding="utf-8")
    defined = set(re.findall(r"^\s*def ([a-z]\w*)\(", text, flags=re.M))
    unused = sorted(n for n in defined if words[n] <= 1)  # its definition only
    assert not unused, f"{source} defines functions nothing uses: {unused}"
