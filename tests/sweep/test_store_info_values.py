"""``impactlab.sweep.store_info`` returns the values ``impactlab sweep info --json`` prints
(integer chunk counts, the flag counts by name, the store's law ranges); the table of
``impactlab sweep info`` is formatted from them."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from sweep_fakes import FlaggingEvaluator, run_cli

from impactlab._version import __version__
from impactlab.cli.sweep_summary import info_table
from impactlab.sweep import FlaggedCasesWarning, Study, flag_counts, run_sweep, store_info
from impactlab.sweep.summary import flagged_text, flagged_values, format_flag_counts


class _Extrapolating(FlaggingEvaluator):
    """FlaggingEvaluator's flags, and the advisory law extrapolated where mu > 0.2."""

    identity = "store-info-values-evaluator/1"

    def flags_for(self, cases: Any) -> np.ndarray:
        return super().flags_for(cases) | np.where(cases["mu"] > 0.2, 4, 0)


@pytest.fixture
def store(tmp_path: Path) -> Path:
    """7 mu x 2 vy (14 cases) in chunks of 4 (4 chunks), the last chunk's marker removed."""
    study = Study(
        name="values",
        chunk_size=4,
        grid={"mu": np.round(np.linspace(0.0, 0.6, 7), 12), "vy": [-1.41, -0.3]},
        fixed={"angle": 0.5},
        outputs=["e"],
    )
    with pytest.warns(FlaggedCasesWarning, match=r"9 case\(s\) not ok"):
        res = run_sweep(study, tmp_path / "v.zarr", evaluator=_Extrapolating(), quiet=True)
    path = res.path
    (path / ".sweep" / "done" / "3").unlink()
    return Path(path)


def test_store_info_gives_numbers_and_the_counts_by_name(store: Path) -> None:
    info = store_info(store)
    assert (info["chunks_done"], info["chunks_total"]) == (3, 4)
    flagged = info["flagged"]
    assert isinstance(flagged, dict) and set(flagged) >= {"total", "not_ok"}
    assert all(isinstance(n, int) for n in flagged.values())
    assert "gravity_dominated" in flagged and "law_extrapolated" in flagged
    assert set(info["law_ranges"]) == {"ghaednia"}
    assert set(info["law_ranges"]["ghaednia"]) == {"range", "source"}
    assert info["impactlab_version"] == __version__


def test_store_info_is_what_info_json_prints(
    store: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store), "--json")
    assert code == 0, err
    printed = json.loads(out)
    info = store_info(store)
    assert info == printed and list(info) == list(printed)


def test_the_table_is_formatted_from_the_values(
    store: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    info = store_info(store)
    rows = info_table(info)
    assert rows["chunks_done"] == "3 of 4"
    assert rows["flagged"].startswith(f"{info['flagged']['not_ok']} case(s) not ok (")
    assert rows["flagged"].endswith(f"; {info['flagged']['total']} flagged in all")
    assert rows["law range: ghaednia"] == info["law_ranges"]["ghaednia"]["range"]
    assert not {"chunks_total", "law_ranges", "impactlab_version"} & set(rows)
    monkeypatch.setenv("COLUMNS", "2000")  # a wide table: each row on one line
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store))
    assert code == 0, err
    assert "3 of 4" in out and rows["flagged"] in out and "impactlab_version" not in out


def test_a_store_without_law_ranges_has_one_row_saying_so() -> None:
    rows = info_table({"chunks_done": 1, "chunks_total": 2, "law_ranges": None})
    assert rows == {"chunks_done": "1 of 2", "law ranges": "not recorded in this store"}


def test_flagged_text_of_the_values_is_the_counts_text() -> None:
    # a mask this version does not know keeps the store's name (old_name)
    meanings = "energy_gain gravity_dominated law_extrapolated old_name"
    attrs = {"flag_masks": [1, 2, 4, 64], "flag_meanings": meanings}
    flags = np.array([-1, 0, 1, 3, 4, 64, 66, 5])
    counts = flag_counts(flags, attrs)
    values = flagged_values(counts)
    assert values == {"total": 6, "not_ok": 5, "energy_gain": 3, "gravity_dominated": 2,
                      "law_extrapolated": 2, "old_name": 2}  # fmt: skip
    assert flagged_text(values) == format_flag_counts(counts)
    assert flagged_text(flagged_values(flag_counts(np.zeros(3, int), attrs))) == "none"
