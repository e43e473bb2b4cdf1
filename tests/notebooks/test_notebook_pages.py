"""The page builder of the notebook gallery (``notebook_pages.py``): a page shows what each cell
printed and the value it displayed, as Jupyter shows it, and stays the same from run to run."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

from notebook_pages import OUT, Output, markdown_table, render, run_cells, steady  # noqa: E402

NOTEBOOK = """# %% [markdown]
# # A notebook

# %%
x = 2
print("two")
x + 1

# %%
x;  # a semicolon: Jupyter shows nothing

# %%
print("printed, returns None")

# %%
import pandas as pd

pd.DataFrame({"a_b": [1.5, 2.0], "c": ["x|y", None]}, index=["r1", "r2"])

# %%
{"k": [1, 2]}

# %%
if x:
    y = 1
"""


def _run(tmp_path: Path, text: str) -> list[Output]:
    path = tmp_path / "nb.py"
    path.write_text(text)
    return run_cells(path, tmp_path)


def test_a_cell_shows_the_value_of_its_last_expression(tmp_path: Path) -> None:
    out = _run(tmp_path, NOTEBOOK)
    assert [o.printed for o in out] == ["", "two\n", "", "printed, returns None\n", "", "", ""]
    shown = [o.shown for o in out]
    assert shown[1] == "```text\n3\n```"
    assert shown[2] == shown[3] == shown[6] == ""  # `;`, None, a statement
    assert shown[5] == "```text\n{'k': [1, 2]}\n```"
    assert shown[4].splitlines() == [
        "|  | a\\_b | c |",
        "| --- | ---: | --- |",
        "| r1 | 1.5 | x\\|y |",
        "| r2 | 2.0 | NaN |",
    ]
    page = render("nb", (tmp_path / "nb.py").read_text(), out)
    assert f'print("two")\nx + 1\n```\n\n```text\ntwo\n```\n\n{OUT}\n\n```text\n3\n```' in page
    assert page.count(OUT) == 4  # one in the page's note, three values


def test_a_large_frame_is_shown_as_jupyter_cuts_it() -> None:
    import pandas as pd

    df = pd.DataFrame({f"c{j}": [float(i * j) for i in range(100)] for j in range(30)})
    lines = markdown_table(df).splitlines()
    assert lines[-1] == "100 rows x 30 columns"
    assert len(lines) == 2 + 11 + 2  # header, rule, 5 + … + 5 rows, blank, size
    assert lines[0].split(" | ")[10:13] == ["c9", "…", "c20"]
    assert lines[7].startswith("| … | …")
    assert lines[8].startswith("| 95 | 0.0 | 95.0")


def test_a_memory_address_stops_the_page(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"nb\.py, cell 2 displays .* memory address \(0x"):
        _run(tmp_path, "# %%\nclass A:\n    pass\n\n# %%\nA()\n")


def test_a_displayed_figure_is_the_image_it_saved(tmp_path: Path) -> None:
    head = "# %%\nfrom matplotlib.figure import Figure\n"
    out = _run(tmp_path, head + '\n# %%\nfig = Figure()\nfig.savefig("f.png")\nfig\n')
    assert out[1].shown == "" and (tmp_path / "f.png").is_file()
    page = render("nb", head + '\n# %%\nfig = Figure()\nfig.savefig("f.png")\nfig\n', out)
    assert page.endswith("fig\n```\n\n![f.png](img/nb-f.png)\n")
    with pytest.raises(ValueError, match="displays a figure: save it"):
        _run(tmp_path, head + "\n# %%\nFigure()\n")


def test_numbers_that_change_between_runs_are_masked() -> None:
    a = "stats(wall_s=0.3337, n=867, host='vm:18816')"
    b = "stats(wall_s=0.2911, n=867, host='vm:20417')"
    assert steady(a, b, "cell") == "stats(wall_s=…, n=867, host='vm:…')"
    assert steady(a, a, "cell") == a
    with pytest.raises(ValueError, match="cell differs from one run to the next"):
        steady("order: a, b", "order: b, a", "cell")
