"""Help texts that say what a bare number means, the real defaults, and what happens without an
input; the pages quote only options that exist."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

from impactlab.cli import app

FIRST_RUN = Path(__file__).resolve().parents[2] / "docs" / "engine" / "first-run.md"


def _help(*command: str) -> str:
    r = CliRunner().invoke(app, [*command, "--help"], terminal_width=100)
    assert r.exit_code == 0, r.output
    return " ".join(r.output.split())


def test_first_run_quotes_invert_options_that_exist() -> None:
    options = set(re.findall(r"`invert (--[a-z-]+)`", FIRST_RUN.read_text(encoding="utf-8")))
    assert options == {"--flat"}
    assert all(f"{o} " in _help("invert") for o in options)


def test_simulate_states_the_bare_unit_and_the_defaults() -> None:
    from impactlab.dynamics.flexcore.layout import DROP_DEFAULT_RTOL
    from impactlab.dynamics.kernels.layout import DEFAULT_RTOL, PARTIAL_SLIP_RTOL

    assert (DEFAULT_RTOL, PARTIAL_SLIP_RTOL, DROP_DEFAULT_RTOL) == (2e-7, 3e-8, 1e-7)
    text = _help("simulate")
    assert "e.g. '2 s' (bare number: s; default 500 ms)" in text
    assert (
        "(default 2e-7, 3e-8 with partial_slip, 1e-7 for the flexible rod; 1e-5 at most for the "
        "flexible rod and with partial_slip, 1e-4 with mindlin)" in text
    )


def test_fe_radius_says_metres_and_its_bound() -> None:
    assert "Sphere radius, e.g. '5 mm' (bare number: m; at most 1 m)." in _help("fe", "indent")


@pytest.mark.parametrize(
    ("radius", "hint"),
    [("5", " (a bare number is in m: give a unit, e.g. '5 mm')"), ("2 m", "")],
)
def test_fe_refuses_a_sphere_larger_than_a_metre(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, radius: str, hint: str
) -> None:
    from impactlab import fe

    monkeypatch.setattr(fe, "indent", lambda *a, **k: pytest.fail("ccx would have run"))
    code, _, err = cli_main("fe", "indent", "--max", "5 um", "--radius", radius)
    metres = float(radius.split()[0])
    assert (code, err) == (
        2,
        f"error: --radius {radius!r} ({metres:g} m) is larger than 1 m, the largest sphere "
        f"taken{hint}\n",
    )


def test_invert_e_says_what_happens_without_it(cli_main: Any) -> None:
    assert "it or --dv-cy is required (without either the command is refused, T too)" in _help(
        "invert"
    )
    code, _, err = cli_main("invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--mu", "0.2",
                            "--delta-p", "22 um", "--ls", "1400 um")  # fmt: skip
    assert (code, err) == (
        2,
        "error: missing input(s): --e (or --dv-cy) (or use --case paper-20|paper-45|paper-70 or"
        " --file)\n",
    )
