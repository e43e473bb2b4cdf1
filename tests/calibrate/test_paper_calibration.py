"""The paper's three drops as a calibration (``impactlab.paper.calibration_report``): the
measurements, and (IMPACTLAB_CALIBRATE_LONG=1, a few minutes: flexible drops) the ranked
configurations with the posterior of zeta and the report's blocks."""

from __future__ import annotations

import math
import os

import pytest

from impactlab.paper import data as D
from impactlab.paper.calibration_report import (
    calibrate_paper,
    calibration_section,
    hardened_law,
    paper_measurements,
    paper_models,
    shipped_calibration,
    write_calibration_report,
)
from impactlab.paper.physics import ROWS
from impactlab.paper.report import Heading, Table, to_markdown

LONG = pytest.mark.skipif(
    os.environ.get("IMPACTLAB_CALIBRATE_LONG", "") in ("", "0"),
    reason="flexible drops, about 0.1 s each (minutes): set IMPACTLAB_CALIBRATE_LONG=1",
)


def test_the_three_drops_and_models():
    m = paper_measurements()
    assert m.labels == ("20 deg", "45 deg", "70 deg")
    x = D.EXPERIMENTS[45]
    assert m.inputs["angle"][1] == pytest.approx(math.radians(45))
    assert m.inputs["vy"][1] == x.v_i and m.inputs["mu"][1] == x.mu
    assert m.observed["delta_p"][1] == pytest.approx(abs(x.delta_p))
    assert m.sigma["delta_p"][1] == pytest.approx(0.1 * abs(x.delta_p))
    assert m.observed["scar_length"][0] == pytest.approx(abs(D.EXPERIMENTS[20].L_s))
    from impactlab.contact import law_names

    before = law_names()
    with hardened_law() as name:  # every row of the physics section, the FE-tabulated one too
        models = paper_models(name)
        assert name in law_names()
    assert law_names() == before  # the process's laws as they were
    assert [p.name for p in models] == [c.name for c in ROWS] and len(models) == 4
    assert models[2].rate == "cowper-symonds" and models[0].body is None
    assert models[3].law == "paper-fe-hardened" and models[3].body == "flexible_rod"


def test_the_shipped_calibration_ranks_every_row_and_says_where_it_comes_from() -> None:
    """The report's calibration section is the shipped run: every configuration of the physics
    section ranked, the sampler's settings, and a sentence saying the numbers are shipped and
    whether the chains converged."""
    summary = shipped_calibration()
    assert {r["configuration"] for r in summary["ranking"]} == {c.name for c in ROWS}
    text = to_markdown(calibration_section(summary, 12), "t")
    assert "shipped with the package" in text and "does not rerun the calibration" in text
    assert ("did not converge" in text) != ("converged (R-hat <= 1.05 over the walkers" in text)


@LONG
@pytest.mark.slow
def test_ranked_configurations_and_section(tmp_path):
    cal = calibrate_paper(walkers=4, steps=10, n_ppc=4)
    assert {r["model"] for r in cal.ranking} == {c.name for c in ROWS}
    assert any("'rigid rod' does not use damping" in w for w in cal.warnings)
    blocks = calibration_section(cal, 12)
    assert isinstance(blocks[0], Heading) and any(isinstance(b, Table) for b in blocks)
    text = to_markdown(blocks, "t")
    assert "PSIS-LOO" in text and "zeta" in text and "no model reproduces" in text
    files = write_calibration_report(tmp_path, cal)
    assert "data:image/png;base64," in files["html"].read_text()


@pytest.mark.parametrize("steps", ["abc", "3"])
def test_the_command_refuses_bad_steps_in_one_line(steps: str, capsys) -> None:
    from impactlab.paper.calibration_report import main

    assert main(["out", steps]) == 2
    assert capsys.readouterr().err == f"error: STEPS must be an integer >= 10, got {steps!r}\n"


def test_the_module_runs_without_a_runpy_warning() -> None:
    """``python -m impactlab.paper.calibration_report`` is not imported by ``impactlab.paper``
    before it runs (runpy's RuntimeWarning)."""
    import subprocess
    import sys

    res = subprocess.run(
        [sys.executable, "-W", "error::RuntimeWarning", "-m",
         "impactlab.paper.calibration_report", "out", "abc"],
        capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert res.returncode == 2 and "RuntimeWarning" not in res.stderr, res.stderr
