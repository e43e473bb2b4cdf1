"""Every ``impactlab.<module>[.<name>]`` a developer page or the JSON page writes in backticks
is importable: a module of the package, or a name that module has (docs/json-schema.md said
``impactlab.contact.law_from_record``, which lives in ``impactlab.contact.registered``)."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import pytest

DOCS = Path(__file__).resolve().parents[2] / "docs"
PAGES = ["json-schema.md", *(f"engine/{p.name}" for p in sorted((DOCS / "engine").glob("*.md")))]


def _resolves(dotted: str) -> bool:
    parts = dotted.split(".")
    for k in range(len(parts), 0, -1):
        try:
            obj: object = importlib.import_module(".".join(parts[:k]))
        except ImportError:
            continue
        for name in parts[k:]:
            if not hasattr(obj, name):
                return False
            obj = getattr(obj, name)
        return True
    return False


@pytest.mark.parametrize("page", PAGES)
def test_every_dotted_impactlab_name_resolves(page: str) -> None:
    text = (DOCS / page).read_text(encoding="utf-8")
    names = set(re.findall(r"`(impactlab(?:\.\w+)+)", text))
    wrong = sorted(n for n in names if not _resolves(n))
    assert not wrong, f"docs/{page} names what impactlab does not have: {wrong}"
