"""``impactlab simulate``: summary, JSON, config file, plots, one-line errors."""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from impactlab.bodies import PAPER_ROD
from impactlab.cli import app, main
from impactlab.dynamics import simulate
from impactlab.friction import DEFAULT_MU

runner = CliRunner()


def test_json_matches_the_api() -> None:
    res = runner.invoke(
        app, ["simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2", "--json"]
    )
    assert res.exit_code == 0, res.output
    data = json.loads(res.output)
    r = simulate(
        PAPER_ROD,
        law="ghaednia",
        friction="coulomb",
        mu=0.2,
        angle=math.radians(20),
        velocity=(0.0, -1.41),
    )
    assert data["e"] == pytest.approx(r.e, rel=1e-12)
    assert data["delta_p"] == pytest.approx(r.delta_p, rel=1e-12)
    assert data["regime"] == "slip"


def test_default_mu_is_the_api_default_and_is_printed() -> None:
    res = runner.invoke(app, ["simulate", "rod", "--vy", "-1.41 m/s", "--json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.output)
    r = simulate(PAPER_ROD, angle=math.radians(20), velocity=(0.0, -1.41))
    assert data["mu"] == DEFAULT_MU == r.mu
    assert data["e"] == r.e
    text = runner.invoke(app, ["simulate", "rod", "--vy", "-1.41 m/s"]).output
    assert "mu" in text


def test_bare_angle_is_degrees_and_units_parse() -> None:
    a = runner.invoke(app, ["simulate", "rod", "--angle", "20", "--vy", "-1410 mm/s", "--json"])
    b = runner.invoke(
        app, ["simulate", "rod", "--angle", "0.3490658503988659 rad", "--vy", "-1.41", "--json"]
    )
    assert a.exit_code == 0 and b.exit_code == 0, (a.output, b.output)
    assert json.loads(a.output)["e"] == pytest.approx(json.loads(b.output)["e"], rel=1e-9)


def test_config_file_and_plots(tmp_path: Path) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(
        '[simulate]\nbody = "sphere"\nradius = "5 mm"\nvy = "-1 m/s"\n'
        'vx = "0.2 m/s"\nfriction = "mindlin"\nmu = 0.3\nlaw = "hertz"\n'
    )
    res = runner.invoke(
        app, ["simulate", "--config", str(cfg), "--plot", "--out", str(tmp_path / "figs")]
    )
    assert res.exit_code == 0, res.output
    assert "e_energy" in res.output
    for name in ("force_time", "force_penetration", "contact_path", "dent"):
        for ext in ("png", "pdf"):
            f = tmp_path / "figs" / f"impact_{name}.{ext}"
            assert f.is_file() and f.stat().st_size > 1000
    assert json.loads((tmp_path / "figs" / "impact_result.json").read_text())["law"] == "hertz"


@pytest.mark.parametrize(
    ("args", "match"),
    [
        (["simulate", "rod", "--angle", "20", "--vy", "1.0"], "does not approach"),
        (["simulate", "rod", "--vy", "-1", "--friction", "foo"], "unknown friction model"),
        (["simulate", "rod", "--vy", "-1", "--mu", "-0.5"], "mu must be >= 0"),
        (["simulate", "cube", "--vy", "-1"], "body must be 'rod' or 'sphere'"),
        (["simulate", "rod"], "--vy is required"),
        (["simulate", "rod", "--vy", "-1 kg"], "wrong dimension"),
    ],
)
def test_user_errors_are_one_line(
    args: list[str], match: str, capsys: pytest.CaptureFixture[str]
) -> None:
    old = sys.argv
    sys.argv = ["impactlab", *args]
    try:
        with pytest.raises(SystemExit) as exc:
            main()
    finally:
        sys.argv = old
    assert exc.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and match in err[0], err
