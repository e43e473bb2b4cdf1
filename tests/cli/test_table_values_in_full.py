"""A table's value longer than its column (a source's address) is folded onto more lines,
never cut with an ellipsis: ``impactlab materials NAME`` shows one material in full."""

from __future__ import annotations

from impactlab.materials import get_material
from impactlab.references import REFERENCES


def test_the_source_address_is_shown_in_full(cli_main, monkeypatch) -> None:
    monkeypatch.setenv("COLUMNS", "80")
    code, out, err = cli_main("materials", "6061-t6")
    assert code == 0, err
    url = REFERENCES[get_material("6061-t6").source].url
    assert len(url) > 60  # longer than the value column at 80 columns
    assert "…" not in out
    cells = [line.split("│")[2].strip() for line in out.splitlines() if line.count("│") == 4]
    start = next(i for i, c in enumerate(cells) if c.startswith("https://"))
    assert url in "".join(cells[start:])
