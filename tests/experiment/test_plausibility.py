"""``analyze`` and ``invert`` warn when the inferred duration or force disagrees with the
simulated impact or the single-impact assumption, and say by how much."""

from __future__ import annotations

import json
from typing import Any

from typer.testing import CliRunner

from impactlab.cli import app
from impactlab.experiment.consistency import (
    PLAUSIBLE_RATIO,
    check_against_model,
    check_single_impact,
    times_text,
)


def test_factor_text_and_threshold() -> None:
    assert times_text(34.0) == "34 times" and times_text(0.25) == "1/4 of"
    within = check_against_model(
        1e-3, 50.0, model_duration=1e-3 * PLAUSIBLE_RATIO * 0.99, model_force=50.0, law="hertz"
    )
    assert within == []
    [t_msg] = check_against_model(
        4.18e-3, 68.0, model_duration=0.123e-3, model_force=None, law="ghaednia",
        sigma_duration=0.04e-3,
    )  # fmt: skip
    assert "T = 4.18 ms is 34 times the simulated impact's duration 0.123 ms" in t_msg
    assert "ghaednia law" in t_msg and "not the error of Eq. 12" in t_msg
    [f_msg] = check_against_model(1e-3, 10.0, model_duration=None, model_force=400.0, law="brake")
    assert "F = 10 N is 1/40 of the simulated impact's mean force 400 N" in f_msg


def test_single_impact_gap() -> None:
    assert check_single_impact(1e-3, 4e-3, 2) is None
    msg = check_single_impact(6e-3, 4e-3, 2)
    assert msg is not None and "T = 6 ms is 1.5 times the 4 ms" in msg and "guard = 2" in msg


def test_analyze_warns_beside_the_model(flat_json: tuple[list[str], Any]) -> None:
    args, res = flat_json  # conftest.py: the run with --flat aisi-1010 --json
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    T = data["inversion"]["duration"]["value"]
    T_model = data["model"]["duration"]["value"]
    ratio = T / T_model
    implausible = [w for w in data["warnings"] if w.startswith("plausibility: implausible T")]
    assert bool(implausible) == (not 1 / PLAUSIBLE_RATIO <= ratio <= PLAUSIBLE_RATIO)
    if implausible:
        assert f"{ratio:.3g} times" in implausible[0]
    table = CliRunner().invoke(app, [*args, "--flat", "aisi-1010"], env={"COLUMNS": "200"})
    assert "model L_s = |contact_travel|" in table.stdout  # the mark's extent: a magnitude


def test_invert_paper_case_warns_with_the_factor(monkeypatch, capsys) -> None:
    import sys

    from impactlab.cli import main

    monkeypatch.setattr(sys, "argv", ["impactlab", "invert", "--case", "paper-20", "--json"])
    main()
    data = json.loads(capsys.readouterr().out)
    ratio = data["duration"]["value"] / data["model"]["duration"]["value"]
    assert ratio > PLAUSIBLE_RATIO  # Eq. 12's T of the paper's drop: ms, the contact: 0.1 ms
    assert any(f"{ratio:.3g} times" in w for w in data["warnings"])
