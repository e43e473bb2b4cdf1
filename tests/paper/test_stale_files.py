"""A rerun leaves one run in the folder whatever became of the earlier one: killed without an
exception (its marker stuck at "running"), or its marker damaged."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest

from impactlab.paper import reproduction as R

DOCS = Path(__file__).resolve().parents[2] / "docs"

# the files a run with the simulations writes and one without them does not
SIMULATED = {
    "simulations.csv",
    "simulation_inputs.json",
    "eq12_check.csv",
    "fe_reference.csv",
    "physics_comparison.csv",
    "physics_drop_20deg.png",
    "fig4_dent.png",
    "forces_20deg.png",
    "forces_45deg.png",
    "forces_70deg.png",
}


def _folder(tmp_path: Path, marker: str) -> Path:
    """A folder as a killed full run leaves it: the simulated files, an analytic table, the
    user's own notes and the marker text ``marker``."""
    out = tmp_path / "r"
    out.mkdir()
    for name in SIMULATED | {"table3.csv", "report.md"}:
        (out / name).write_text("from the earlier run")
    (out / "my_notes.txt").write_text("mine")
    (out / "simulations_mine.csv").write_text("mine too")
    (out / R.MARKER).write_text(marker)
    return out


@pytest.mark.parametrize(
    "marker",
    [
        json.dumps({"tool": "impactlab reproduce", "status": "running", "files": ["table3.csv"]}),
        '{"tool": "impactlab reproduce", "status": "comp',
        "",
    ],
    ids=["stuck-running", "damaged", "empty"],
)
def test_a_killed_runs_files_are_removed(tmp_path, recwarn, marker):
    out = _folder(tmp_path, marker)
    res = R.reproduce(out, simulate=False)
    ours = {p.name for p in res.files.values()}
    assert not ours & SIMULATED
    assert {p.name for p in out.iterdir()} == ours | {
        R.MARKER,
        "my_notes.txt",
        "simulations_mine.csv",
    }
    assert (out / "my_notes.txt").read_text() == "mine"
    assert (out / "simulations_mine.csv").read_text() == "mine too"
    assert (out / "table3.csv").read_text() != "from the earlier run"
    assert res.extras["removed"] == tuple(sorted(SIMULATED))
    said = [str(w.message) for w in recwarn if issubclass(w.category, R.ReproductionWarning)]
    assert len(said) == len(SIMULATED)
    saved = json.loads((out / R.MARKER).read_text())
    assert saved["status"] == "complete" and saved["files"] == sorted(ours)


def test_a_write_cut_short_is_removed(tmp_path, recwarn):
    """The temporary file of a write killed half way goes; one of the user's stays."""
    out = _folder(tmp_path, "{}")
    (out / ".report.md.4242.partial").write_text("half")
    (out / ".notes.txt.4242.partial").write_text("the user's")
    res = R.reproduce(out, simulate=False)
    assert not (out / ".report.md.4242.partial").exists()
    assert (out / ".notes.txt.4242.partial").read_text() == "the user's"
    assert ".report.md.4242.partial" in res.extras["removed"]


def test_a_full_run_writes_only_the_known_files(full_reproduction):
    written = {p.name for p in full_reproduction.files.values()}
    assert written == R.FILES
    assert {p.name for p in full_reproduction.out_dir.iterdir()} == written | {R.MARKER}


def test_the_page_lists_the_known_files():
    page = (DOCS / "paper" / "reproduction.md").read_text()
    table = page.split("## What it writes")[1].split("Safety:")[0]
    listed = set(re.findall(r"`([\w.-]+\.(?:csv|png|json|md|html))`", table))
    assert listed == R.FILES | {R.MARKER}


def test_after_a_complete_run_only_its_listed_files_are_its_own(tmp_path, recwarn):
    """A file the user saved under a name of the reproduction in a folder whose last run
    completed (and did not list it) is the user's: kept, no warning calls it an earlier run's."""
    out = _folder(
        tmp_path,
        json.dumps({"tool": "impactlab reproduce", "status": "complete", "files": ["table3.csv"]}),
    )
    res = R.reproduce(out, simulate=False)
    assert (out / "simulations.csv").read_text() == "from the earlier run"
    assert "simulations.csv" not in res.extras["removed"]
    assert not any("simulations.csv" in str(w.message) for w in recwarn)


def test_a_link_in_the_folder_is_replaced_not_written_through(tmp_path, analytic_reproduction):
    """A link named as a file of the reproduction: this run writes its own file in the folder,
    and the file the link named, outside it, is left as it was."""
    out = tmp_path / "r"
    shutil.copytree(analytic_reproduction.out_dir, out)  # an earlier run's folder
    mine = tmp_path / "userdata" / "table2.csv"
    mine.parent.mkdir()
    mine.write_text("my precious table")
    (out / "table2.csv").unlink()
    (out / "table2.csv").symlink_to(mine)
    with pytest.warns(R.ReproductionWarning, match="was a link"):
        R.reproduce(out, simulate=False)
    assert mine.read_text() == "my precious table"
    assert not (out / "table2.csv").is_symlink()
    assert (out / "table2.csv").read_text().startswith("source,")


@pytest.mark.parametrize("status", ["complete", "running"])
def test_a_marker_never_makes_a_file_of_the_users_removable(tmp_path, recwarn, status):
    """Only names a reproduction can write are removed: a marker listing a file of the user's,
    or a path outside the folder, removes neither."""
    out = tmp_path / "t4"
    out.mkdir()
    (out / "thesis.tex").write_text("precious")
    (tmp_path / "victim.txt").write_text("victim")
    listed = ["thesis.tex", "../victim.txt", "report.md", ".thesis.tex.1.partial"]
    (out / ".thesis.tex.1.partial").write_text("mine too")
    (out / R.MARKER).write_text(
        json.dumps({"tool": "impactlab reproduce", "status": status, "files": listed})
    )
    res = R.reproduce(out, simulate=False)
    assert (out / "thesis.tex").read_text() == "precious"
    assert (out / ".thesis.tex.1.partial").read_text() == "mine too"
    assert (tmp_path / "victim.txt").read_text() == "victim"
    assert not {"thesis.tex", ".thesis.tex.1.partial"} & set(res.extras["removed"])
    assert not any("thesis" in str(w.message) for w in recwarn)
    saved = json.loads((out / R.MARKER).read_text())
    assert "thesis.tex" not in saved["files"]
