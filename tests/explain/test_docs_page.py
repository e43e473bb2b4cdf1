"""docs/explain.md: every python block runs as written (in order, in a fresh folder), every
command line of its text blocks runs, and the numbers it states are the ones explain gives."""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

PAGE = Path(__file__).resolve().parents[2] / "docs" / "explain.md"
TEXT = PAGE.read_text(encoding="utf-8")


def test_the_pages_code_runs(tmp_path, monkeypatch, cli_main) -> None:
    monkeypatch.chdir(tmp_path)
    scope: dict[str, object] = {}
    for block in re.findall(r"^```python\n(.*?)^```", TEXT, re.S | re.M):
        exec(compile(block, str(PAGE), "exec"), scope)
    x = scope["x"]
    assert x.best("al 20") is not None
    blocks = re.findall(r"^```text\n(.*?)^```", TEXT, re.S | re.M)
    lines = [line for block in blocks for line in block.splitlines()]
    commands = [line for line in lines if line.startswith("impactlab explain ")]
    assert len(commands) == 5
    for line in commands:
        code, out, err = cli_main(*shlex.split(line)[1:], "--quiet")
        assert code == 0, (line, err)
        assert out
    assert (tmp_path / "explained" / "explain.csv").is_file()


def test_the_numbers_it_states(paper_explained) -> None:
    c = paper_explained.comparison
    c = c[c["drop"] == "20 deg"].set_index(["configuration", "quantity"])
    cs = "flexible rod + rate-dependent flat (cowper-symonds, upper estimate)"
    assert round(c.loc[("rigid body", "delta_p"), "predicted"] * 1e6) == 62
    assert round(c.loc[("rigid body", "scar_length"), "predicted"] * 1e6) == 22
    assert round(c.loc[("flexible rod", "delta_p"), "predicted"] * 1e6) == 32
    assert round(c.loc[("flexible rod", "scar_length"), "predicted"] * 1e6) == 261
    assert c.loc[(cs, "delta_p"), "predicted"] * 1e6 == pytest.approx(22.9, abs=0.05)
    assert c.loc[(cs, "delta_p"), "z"] == pytest.approx(0.4, abs=0.05)
    assert c.loc[(cs, "e"), "predicted"] == pytest.approx(0.74, abs=0.005)
    assert c.loc[(cs, "e"), "z"] == pytest.approx(8, abs=0.5)
    s = paper_explained.summary
    assert not (s["within_2_sigma"] == s["n_measured"]).any()  # none explains all three
    assert paper_explained.result("20 deg", "flexible rod").n_contacts == 4
    for phrase in ("dent of 62 um", "scar of 22 um", "touches the flat 4 times",
                   "dent of 32 um", "scar of 261 um", "22.9 um (z = +0.4)", "0.74"):  # fmt: skip
        assert phrase in " ".join(TEXT.split()), phrase


def test_the_quoted_verdict_line_is_the_commands(cli_main, paper_file, paper_explained) -> None:
    """The page's 70 deg verdict line is the command's, character for character, and the
    p-values it states are the verdicts'."""
    code, out, err = cli_main("explain", str(paper_file), "--quiet")
    assert code == 0, err
    line = next(x for x in out.splitlines() if x.startswith("verdict (70 deg): "))
    quoted = [x for x in TEXT.splitlines() if x.startswith("verdict (70 deg): ")]
    assert quoted == [line]
    p20, p70 = (paper_explained.verdict(d).p_value for d in ("20 deg", "70 deg"))
    assert f"(p = {p20:.2g} and {p70:.2g}, below 0.01:" in " ".join(TEXT.split())
