"""The sweep's progress bar at 80 and 100 columns: a long study name is cut with an ellipsis,
the count, rate, elapsed time and ETA stay whole."""

from __future__ import annotations

import re
from types import SimpleNamespace

import pytest

import impactlab.sweep.progress_bar as progress_bar_module
from impactlab.sweep.progress_bar import progress_bar

NAMES = ("laws", "paper-rod-angle-velocity-map-ghaednia",
         "paper-rod-angle-velocity-regime-map-ghaednia-coulomb")  # fmt: skip


@pytest.mark.parametrize("width", [80, 100])
@pytest.mark.parametrize("name", NAMES)
def test_a_long_name_leaves_the_numbers_whole(monkeypatch, capsys, width: int, name: str) -> None:
    monkeypatch.setenv("COLUMNS", str(width))
    clock = iter([0.0, 2.0])  # the rate: 600 impacts in 2 s
    monkeypatch.setattr(progress_bar_module, "time", SimpleNamespace(perf_counter=clock.__next__))
    with progress_bar(1200, 0, name, True) as advance:
        advance(600)
    shown = re.sub(r"\x1b\[[0-9;?]*[a-zA-Z]", "", capsys.readouterr().err)
    line = [part for part in re.split(r"[\r\n]", shown) if "impacts" in part][-1]
    assert len(line) <= width
    label = line.split(" ")[0]
    assert label == name or (label.endswith("…") and name.startswith(label[:-1]))
    assert re.search(r" 600/1200 impacts 300/s +\d:\d\d:\d\d ETA (\d:\d\d:\d\d|-:--:--)$", line)
    assert line.count("…") == (label != name)
