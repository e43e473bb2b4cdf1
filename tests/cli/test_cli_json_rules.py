"""``--json`` follows one rule in every command: the warnings go to stderr too (one line each),
and a result in doubt says so by ``ok`` and ``doubts``, ``invert`` by the rule of ``analyze``."""

from __future__ import annotations

import json

EXAMPLE = ("examples/data/drop.csv", "examples/data/dent.npy", "--pixel-size", "12 um",
           "--height-unit", "um", "--up", "+y", "--geometry", "examples/data/markers.toml",
           "--flat", "al-6061-t6")  # fmt: skip


def test_analyze_json_prints_its_warnings_on_stderr(cli_main) -> None:
    code, out, err = cli_main("analyze", *EXAMPLE, "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["warnings"] and not data["ok"]
    lines = err.splitlines()
    for text in data["warnings"]:
        assert f"warning: {text}" in lines, (text, err)


def test_invert_json_says_ok_and_its_doubts_as_analyze(cli_main) -> None:
    code, out, err = cli_main("invert", "--case", "paper-20", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["ok"] is False
    assert len(data["doubts"]) == 2 and all(d in data["warnings"] for d in data["doubts"])
    assert data["doubts"][0].startswith("implausible T")
    code, out, err = cli_main(
        "invert", "--angle", "20 deg", "--vi", "-1.41", "--e", "0.5", "--mu", "0.2",
        "--delta-p", "22 um", "--ls", "1400 um", "--json",
    )  # fmt: skip
    assert code == 0, err
    data = json.loads(out)
    assert data["ok"] is True and data["doubts"] == []


def test_invert_doubts_follow_analyzes_phrases() -> None:
    from impactlab.cli.invert_output import inversion_doubts

    impossible = "e = 1.2 +- 0.01 lies above 1 (...): no impact gives it; check the measurement"
    plain = "the Monte Carlo discarded 6 % of its samples"
    assert inversion_doubts([plain, impossible], ["implausible F: ..."]) == [
        impossible,
        "implausible F: ...",
    ]
    assert inversion_doubts([plain], []) == []
