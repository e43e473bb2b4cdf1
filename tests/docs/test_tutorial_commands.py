"""What the tutorials show from the command line holds for a newcomer in a fresh shell: every
shell command names the virtualenv's ``python`` or ``impactlab`` (the set-up does not activate
it), what the commands write into the clone is git-ignored and listed in the set-up, the
``invert`` table and JSON are described as they are (magnitudes, ``n_samples`` asked for), the
warning of an e at its limit is quoted as printed, and the ``print(r)`` excerpt marks every row
it leaves out."""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable
from pathlib import Path

import pytest

from impactlab.bodies import Rod
from impactlab.dynamics import simulate
from impactlab.materials import AISI_1010

ROOT = Path(__file__).resolve().parents[2]
TUTORIALS = ROOT / "docs" / "tutorials"
#: what the tutorials' commands and snippets write into the clone
OUTPUTS = (
    "out/", "s.json", "figures/", "drop-files/", "results/", "calib/", "regime-map.zarr/",
    "regime-map-cli.zarr/", "regime-map-cli.nc", "regime-map-cli.csv",
    "uncertainty-20deg.zarr/", "plots/", "reproduction/", "drop.c3d", "dent.x3p",
    "force_time.png", "regime_map.png",
)  # fmt: skip
#: the page's command that prints the warning of an e at its limit
E_AT_LIMIT = ("invert", "--angle", "20 deg", "--mu", "0.2", "--vi", "-1.41", "--e", "1.02",
              "--sigma-e", "0.01", "--delta-p", "22 um", "--ls", "1400 um")  # fmt: skip

CliMain = Callable[..., tuple[int, str, str]]


def _page(name: str) -> str:
    return (TUTORIALS / name).read_text(encoding="utf-8")


def _blocks(text: str, langs: tuple[str, ...] = ("bash", "text", "")) -> list[str]:
    """The fenced blocks of ``text`` whose language is one of ``langs`` (``""``: none)."""
    found: list[tuple[str, list[str]]] = []
    lang: str | None = None
    for line in text.splitlines():
        if line.startswith("```"):
            lang = line[3:].strip() if lang is None else None
            if lang is not None:
                found.append((lang, []))
        elif lang is not None:
            found[-1][1].append(line)
    return ["\n".join(lines) for kind, lines in found if kind in langs]


def _flat(text: str) -> str:
    return " ".join(text.split())


@pytest.mark.parametrize("page", sorted(TUTORIALS.glob("*.md")), ids=lambda p: p.name)
def test_shell_commands_name_the_virtualenv(page: Path) -> None:
    for block in _blocks(page.read_text(encoding="utf-8")):
        for line in block.splitlines():
            bare = re.match(r"(impactlab|python) ", line)
            assert bare is None, f"{page.name}: {line!r} needs .venv/bin/ (no venv is active)"


def test_what_the_tutorials_write_is_ignored_and_listed() -> None:
    ignored = set((ROOT / ".gitignore").read_text(encoding="utf-8").split())
    setup = _page("index.md")
    for name in OUTPUTS:
        assert f"/{name}" in ignored, f".gitignore lacks /{name}"
        assert {f"`{name}`", f"`{name.rstrip('/')}`"} & set(re.findall(r"`[^`]+`", setup)), name
    written = set()
    for page in TUTORIALS.glob("*.md"):
        text = page.read_text(encoding="utf-8")
        written |= set(re.findall(r"--out ([\w./-]+)", text))
        written |= set(re.findall(r"(?:savefig|save_figures\(r,) ?\(?\"([\w./-]+)\"", text))
    for path in written:
        top = path.split("/")[0]
        assert {f"/{top}", f"/{top}/"} & ignored, f"{path} is written into the clone"


def test_the_invert_table_is_described_as_it_is(cli_main: CliMain) -> None:
    code, out, _ = cli_main("invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5",
                            "--mu", "0.2", "--delta-p", "22 um", "--ls", "1400 um",
                            "--sigma-ls", "50 um", "--sigma-mu", "0.01")  # fmt: skip
    assert code == 0
    assert re.search(r"\|v_i\|\s+│\s+1\.41 │ m/s", out), out
    assert re.search(r"\|sliding_length\|\s+│\s+1400 ± 50 │ um", out), out
    page = _flat(_page("invert.md"))
    assert "signs kept" not in page and "echoes the inputs" not in page
    assert "`|v_i| 1.41 m/s` and `|sliding_length| 1400 ± 50 um`" in page


def test_n_samples_is_what_was_asked_for(cli_main: CliMain) -> None:
    code, out, _ = cli_main("invert", "--case", "paper-20", "--json")
    data = json.loads(out)
    assert code == 0 and (data["n_samples"], data["mc_used"]) == (20000, 0)
    page = _flat(_page("invert.md"))
    assert "`n_samples` the samples asked for" in page and "`n_samples` drawn" not in page
    assert "the JSON's `n_samples` still says 20000, the number asked for" in page


@pytest.mark.parametrize("e", ["1.02", "1.0"])
def test_the_warning_of_an_e_at_its_limit_is_quoted(cli_main: CliMain, e: str) -> None:
    args = [e if a == "1.02" else a for a in E_AT_LIMIT]
    code, _, err = cli_main(*args, "--samples", "20000")
    assert code == 0
    lines = [w for w in err.splitlines() if "Monte Carlo samples were discarded" in w]
    assert len(lines) == 1 and "drew e > 1" in lines[0] and "sticking" not in lines[0], err
    quoted = next(b for b in _blocks(_page("invert.md")) if "drew e > 1" in b)
    assert _flat(quoted) == _flat(lines[0])


def test_the_print_excerpt_marks_every_row_left_out() -> None:
    r = simulate(Rod.paper(), AISI_1010, law="ghaednia", friction="coulomb", mu=0.2,
                 angle=math.radians(20), velocity=(0.0, -1.41))  # fmt: skip
    real = str(r).splitlines()
    page = _page("simulate.md")
    block = next(b for b in _blocks(page) if b.startswith("ImpactResult"))
    shown = block.splitlines()
    names = [line.split()[0] for line in real]
    at = -1
    for line in shown:
        if line.strip() == "...":
            continue
        name = line.split()[0]
        index = names.index(name)
        gap = index - at > 1
        assert not gap or shown[shown.index(line) - 1].strip() == "...", f"{name}: rows left out"
        body = line.split("...")[0].rstrip() if line.endswith("...") else line
        assert real[index].startswith(body), (line, real[index])
        at = index
    assert at == len(real) - 1
