"""``repr(ExperimentResult)`` is one short line (the files, the headline estimates with their
sigma and unit, ok, the counts of errors and warnings), ``str`` the whole table."""

from __future__ import annotations

from impactlab.experiment import ExperimentResult


def test_an_empty_result() -> None:
    res = ExperimentResult(markers_path=None, scan_path=None)
    assert repr(res) == "ExperimentResult(no files, ok=True)"


def test_errors_and_warnings_are_counted() -> None:
    res = ExperimentResult(
        markers_path="/data/drop 1.c3d",
        scan_path="/data/dent.x3p",
        errors={"scan": "bad file"},
        warnings=["one", "two"],
    )
    text = repr(res)
    assert text == "ExperimentResult(drop 1.c3d + dent.x3p, ok=False, 1 error, 2 warnings)"
    assert "\n" not in text and len(text) < 200


def test_the_analysed_example_shows_its_estimates(analysed_example) -> None:
    text = repr(analysed_example)
    assert text.startswith("ExperimentResult(drop.csv + dent.npy, e=0.50")
    for part in (" ± ", "delta_p=", " m,", "duration=", " s,", "mean_force=", " N,", "ok=True)"):
        assert part in text
    assert len(text) < 300
