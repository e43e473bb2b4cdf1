"""The module map of docs/architecture.md ("Module map") holds every module of the package and
no other, under its own package, and the names its rows give are in those modules; every data
folder is named; and every dotted name the page gives for a module (`sweep.plots`,
`impactlab.dynamics.kernels`, `slip_batch.slip_case`) is a module of the package, or a name
defined in one (but in the rows of the caches that were removed)."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "architecture.md"
PACKAGE = ROOT / "src" / "impactlab"


def _section(title: str) -> str:
    text = PAGE.read_text(encoding="utf-8")
    start = text.index(f"\n## {title}\n")
    end = text.find("\n## ", start + 3)
    return text[start : end if end > 0 else len(text)]


def _modules() -> dict[str, Path]:
    """Dotted name -> source file of every module and package under src/impactlab."""
    out: dict[str, Path] = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


def _packages() -> set[str]:
    return {m for m, p in _modules().items() if p.name == "__init__.py"}


def _map() -> dict[str, list[str]]:
    """Package heading -> the module names (relative to it) of its table, in order."""
    out: dict[str, list[str]] = {}
    current = None
    for line in _section("Module map").splitlines():
        heading = re.match(r"### `(impactlab[\w.]*)`", line)
        if heading:
            current = heading.group(1)
            assert current not in out, f"the module map has two headings {current}"
            out[current] = []
        elif line.startswith("| `"):
            assert current is not None, line
            out[current] += re.findall(r"`([\w.]+)`", line.split("|")[1])
    return out


def test_the_module_map_holds_every_module_under_its_package() -> None:
    listed = _map()
    assert set(listed) == _packages(), (
        f"packages without a heading: {sorted(_packages() - set(listed))}; "
        f"headings of no package: {sorted(set(listed) - _packages())}"
    )
    entries = [f"{package}.{name}" for package, names in listed.items() for name in names]
    twice = sorted({e for e in entries if entries.count(e) > 1})
    assert not twice, f"listed twice in the module map: {twice}"
    modules = {m for m, p in _modules().items() if p.name != "__init__.py"}
    assert len(modules) > 300
    missing = sorted(modules - set(entries))
    stale = sorted(set(entries) - modules)
    assert not missing and not stale, (
        f"docs/architecture.md's module map misses {missing} and lists {stale}, which are no "
        "modules (each module goes in the table of its own package)"
    )


def test_every_data_folder_is_named() -> None:
    text = _section("Module map") + _section("What lives where")
    named = set(re.findall(r"`([\w./-]+/)`", text))
    folders = [
        d.relative_to(PACKAGE).as_posix() + "/"
        for d in PACKAGE.rglob("*")
        if d.is_dir() and d.name != "__pycache__" and not (d / "__init__.py").is_file()
    ]
    assert folders
    unnamed = sorted(f for f in folders if not any(f.startswith(n) for n in named))
    assert not unnamed, f"docs/architecture.md names no folder of {unnamed}"


def _resolves(token: str, modules: dict[str, Path]) -> bool:
    """A dotted token is a module (by its full name or a tail of it: `sweep.plots`,
    `kinematics.gravity`), or a name defined in the longest such module (`integrator.locate`)."""
    parts = token.removeprefix("impactlab.").split(".")
    for k in range(len(parts), 0, -1):
        tail = "." + ".".join(parts[:k])
        found = [m for m in modules if ("." + m).endswith(tail)]
        if found:
            rest = parts[k:]
            if not rest:
                return True
            return any(
                re.search(rf"\b{rest[0]}\b", modules[m].read_text(encoding="utf-8")) for m in found
            )
    return False


def test_every_dotted_module_name_of_the_page_exists() -> None:
    modules = _modules()
    short = {m.rsplit(".", 1)[-1] for m in modules}
    text = re.sub(r"```.*?```", "", PAGE.read_text(encoding="utf-8"), flags=re.S)
    text = "\n".join(ln for ln in text.splitlines() if "**removed**" not in ln)  # Caches
    tokens = {
        t
        for t in re.findall(r"`([a-z_][\w.]*\.[\w.]*\w)`", text)
        if t.removeprefix("impactlab.").split(".")[0] in short and not t.endswith((".py", ".md"))
    }
    assert len(tokens) > 100
    wrong = sorted(t for t in tokens if not _resolves(t, modules))
    assert not wrong, f"docs/architecture.md names modules that do not exist: {wrong}"


def test_every_name_a_row_of_the_map_gives_is_in_its_module() -> None:
    """| `registry` | the registry of laws (`_LAWS`), `get_law`, ... |: each backticked
    identifier of a row's text occurs in the source of the row's modules."""
    modules = _modules()
    current = ""
    wrong = []
    for line in _section("Module map").splitlines():
        heading = re.match(r"### `(impactlab[\w.]*)`", line)
        current = heading.group(1) if heading else current
        if line.startswith("| `") and current:
            cells = line.split("|")
            names = re.findall(r"`([\w.]+)`", cells[1])
            source = "".join(modules[f"{current}.{n}"].read_text(encoding="utf-8") for n in names)
            wrong += [
                (names, name)
                for name in re.findall(r"`([A-Za-z_]\w*)`", cells[2])
                if not re.search(rf"\b{name}\b", source)
            ]
    assert not wrong, f"docs/architecture.md's module map gives names its modules lack: {wrong}"
