"""How a calibration shows itself in a console and a notebook: a short summary (the ranking,
each model's posterior in display units, the warnings' count), never the raw arrays; the same
rows as ``impactlab calibrate``'s tables."""

from __future__ import annotations

import re

import pytest

from impactlab.calibrate import CalibrationWarning
from impactlab.calibrate.display import (
    POSTERIOR_HEAD,
    RANKING_HEAD,
    posterior_rows,
    ranking_rows,
)


def test_the_calibration_shows_its_ranking_and_posteriors_not_its_arrays(mu_calibration) -> None:
    text = repr(mu_calibration)
    assert len(text) < 2000
    assert "array(" not in text and "[[" not in text
    lines = text.splitlines()
    assert lines[0] == (
        "Calibration of 1 model(s) on 2 drops (2 measured values of e), ranked by PSIS-LOO"
    )
    assert lines[2].split()[:4] == ["rank", "model", "elpd_loo", "se"]
    assert lines[3].split()[:2] == ["1", "ghaednia/coulomb"]
    post = mu_calibration.posteriors["ghaednia/coulomb"]
    s = post.summary["mu"]
    row = next(line.split() for line in lines if line.split()[:1] == ["mu"])
    assert float(row[1]) == float(f"{s['median']:.4g}")  # the median, four digits
    n = len(mu_calibration.warnings)
    assert lines[-1] == (f"{n} warning(s) given: see .warnings" if n else "no warnings")


def test_a_notebook_gets_the_same_rows_as_html(mu_calibration) -> None:
    page = mu_calibration._repr_html_()
    assert page.startswith("<div>") and page.endswith("</div>")
    assert page.count("<table>") == 1 + len(mu_calibration.posteriors)
    for head in (*RANKING_HEAD, *POSTERIOR_HEAD):
        assert f"<th>{head}</th>" in page
    for cell in ranking_rows(mu_calibration.ranking)[0][:3]:
        assert f"<td>{cell}</td>" in page


def test_the_commands_tables_and_the_repr_share_their_rows(mu_calibration, capsys) -> None:
    from impactlab.cli.calibrate import _print

    _print(mu_calibration)
    out = capsys.readouterr().out
    post = mu_calibration.posteriors["ghaednia/coulomb"]
    for row in (*ranking_rows(mu_calibration.ranking), *posterior_rows(post)):
        for cell in row:
            assert cell in out, cell
            assert cell in repr(mu_calibration) or cell == ""


def test_a_posterior_its_measurements_and_predictions_are_summaries(mu_calibration) -> None:
    post = mu_calibration.posteriors["ghaednia/coulomb"]
    assert repr(post).splitlines()[0].startswith("ModelPosterior ghaednia/coulomb (")
    assert "array(" not in repr(post)
    assert "<td>mu</td>" in post._repr_html_()
    assert repr(mu_calibration.measurements) == ("Measurements(2 drops: a, b; 2 values of e)")
    with pytest.warns(CalibrationWarning, match="extrapolated in 100 %"):
        pred = mu_calibration.predict({"label": "new", "angle": "30 deg", "vy": -2.0}, draws=4)
    text = repr(pred)
    assert text.splitlines()[0] == "DropPredictions of ghaednia/coulomb at 4 posterior draws"
    assert re.search(r"^\s+new\s+e\s+\S+\s+\[\S+, \S+\]\s+-\s+0 %", text, flags=re.M), text
    assert "<td>new</td>" in pred._repr_html_()
