"""The recipes of docs/architecture.md ("Where to add things") say what the code needs: a
compiled law's id goes after ``TABULATED`` (stored records hold ids), a diagnostic output joins
the sweep's ``DIAGNOSTIC_OUTPUTS``, a new module its row in the module map, and a friction model
the batch does not run is refused by the messages the code has (not by a helper that is gone),
with the command line's lists of models named."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "architecture.md"
SRC = ROOT / "src" / "impactlab"


def _recipe(start: str) -> str:
    text = PAGE.read_text(encoding="utf-8")
    recipes = text[text.index("## Where to add things") :]
    recipes = recipes[: recipes.index("\n## ", 3)]
    i = recipes.index(start)
    j = recipes.find("\n**", i + len(start))
    return " ".join(recipes[i : j if j > 0 else len(recipes)].split())


def test_a_new_law_id_goes_after_tabulated_and_ids_never_move() -> None:
    from impactlab.contact import kernels as k

    text = _recipe("**A compiled contact law**")
    assert "before `TABULATED`, raising `N_LAWS`" not in text
    assert f"the next free one after `TABULATED` ({k.N_LAWS} today" in text
    assert "`RECORD_FORMAT`" in text and "never changes" in text
    # the kernels branch on a law by equality only, so an id after TABULATED needs no other change
    source = (SRC / "contact" / "kernels.py").read_text(encoding="utf-8")
    assert not re.search(r"\blaw(?:_id)? *[<>]=? *[A-Z]", source)


def test_a_diagnostic_output_joins_the_sweeps_set() -> None:
    from impactlab.sweep.engine import DIAGNOSTIC_OUTPUTS

    text = _recipe("**An output field.**")
    assert "`DIAGNOSTIC_OUTPUTS` in `sweep/engine.py`" in text
    assert all(f"`{name}`" in text for name in DIAGNOSTIC_OUTPUTS)


def test_a_new_module_gets_its_row_in_the_map() -> None:
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    assert "adds its row to the [module map](#module-map)" in text
    assert "`tests/docs/test_architecture_map.py` fails until" in text


def test_the_friction_recipe_names_the_real_refusals_and_the_cli_lists() -> None:
    from impactlab.friction import friction_names

    text = _recipe("**A friction model**")
    assert "batch_friction_error" not in PAGE.read_text(encoding="utf-8")
    batch = (SRC / "dynamics" / "batch.py").read_text(encoding="utf-8")
    assert "friction_id must be one of {" in batch and "friction_id must be one of {" in text
    assert "`_validate_categories` of `sweep/engine.py`" in text
    for cli in ("cli/simulate_help.py", "cli/drop.py"):
        assert f"`{cli}`" in text
        source = (SRC / cli).read_text(encoding="utf-8")
        assert all(name in source for name in friction_names()), cli
