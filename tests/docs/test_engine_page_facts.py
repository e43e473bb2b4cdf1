"""docs/engine/index.md states what the code holds: the modules the compiled engine imports from
the models' layer, the functions of each Python module in its table, the `Rod` signature, the
tolerance cap of a partial-slip drop, the sign of psi2 that the Verification page uses, and a
`partial_slip` section that sends its numbers to the Verification page."""

from __future__ import annotations

import inspect
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "engine" / "index.md"
SRC = ROOT / "src" / "impactlab"
ANCHOR = "partial-slip-mindlin-deresiewicz-friction-against-its-converged-solution-and-kharazs-data"


def _text() -> str:
    return PAGE.read_text(encoding="utf-8")


def _section(title: str) -> str:
    text = _text()
    start = text.index(f"\n## {title}\n")
    return text[start : text.index("\n## ", start + 3)]


def test_the_engine_imports_what_the_page_says() -> None:
    engine = [SRC / "dynamics" / d for d in ("kernels", "core", "slipcore", "flexcore")]
    imported = {
        m
        for folder in engine
        for path in folder.glob("*.py")
        for m in re.findall(
            r"^\s*from impactlab\.((?:contact|bodies)\.\w+) import", path.read_text(), re.M
        )
    }
    assert "contact.slopes" in imported
    said = " ".join(_section("Where the code lives").split())
    missing = sorted(m for m in imported if f"{m}`" not in said)
    assert not missing, f"the page's import list leaves out {missing}"


def test_each_entry_point_is_in_the_module_its_row_names() -> None:
    """A row whose job starts with an entry point (`simulate_batch`, `run_arrays`, ...) names
    the module that defines it."""
    checked = []
    for line in _section("Where the code lives").splitlines():
        cells = line.split("|")
        if not line.startswith("| `dynamics.") or len(cells) < 3:
            continue
        modules = re.findall(r"`dynamics\.(\w+)`", cells[1])
        job = cells[2].strip()
        lead = job.split(":")[0] if job.startswith("`") else ""
        while re.search(r"\([^()]*\)", lead):  # the parentheses, innermost first
            lead = re.sub(r"\([^()]*\)", "", lead)
        names = re.findall(r"`(\w+)`", lead)
        for name in names:
            sources = [(SRC / "dynamics" / f"{m}.py").read_text() for m in modules]
            assert any(re.search(rf"^(?:def|class) {name}\b", s, re.M) for s in sources), (
                f"the page's row {modules} names {name}, which those modules do not define"
            )
            checked.append(name)
    assert {"simulate", "simulate_batch", "run_arrays", "ImpactResult"} <= set(checked)


def test_the_rod_signature_is_the_class_s() -> None:
    from impactlab.bodies import Rod

    m = re.search(r"`Rod\(([^)]*)\)`", _text())
    assert m
    written = [p.split("=")[0].strip() for p in m.group(1).split(",")]
    assert written == list(inspect.signature(Rod).parameters)


def test_a_partial_slip_drop_is_said_to_have_the_cap() -> None:
    from impactlab.dynamics.drop_checks import drop_rtol

    assert drop_rtol.__name__ in _text()
    flat = " ".join(_text().split())
    assert "follows its tolerance as `mindlin` does and keeps the whole range" not in flat
    assert "A flexible rod's drop with `partial_slip` has the same cap" in flat


def test_psi2_has_the_sign_of_the_verification_page() -> None:
    flat = " ".join(_section("Friction models").split())
    verification = " ".join((ROOT / "docs" / "verification" / "index.md").read_text().split())
    assert "gross slip psi2 = psi1 - 4 chi" in verification
    assert r"$\psi_2 = \psi_1 - 4\chi$ in gross slip" in flat
    assert r"$\psi_2 \approx 0.52\,\psi_1$" in flat and r"$\psi_2 \approx 0.22\,\psi_1$" in flat
    assert r"4\chi - \psi_1" not in flat and "-0.52" not in flat


def test_partial_slip_has_its_section_with_the_verification_link() -> None:
    text = _section("Friction models")
    start = text.index("### `partial_slip`")
    section = text[start:]
    assert f"verification/index.md#{ANCHOR}" in section
    assert "see the verification page" in section
