"""The inversion's limits: a sigma wider than its input's range is refused, a Monte Carlo that
discards many samples warns (Python and command line, text and JSON) and says how many it
used, a dent below 1 nm is refused and one below 0.1 um warned about (as ``analyze`` does),
and a measurement file's ``samples`` and ``seed`` are integers."""

from __future__ import annotations

import json
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from inversion_cases import PAPER_20

import impactlab as il
from impactlab.analytic import invert
from impactlab.analytic._measurements import MIN_DENT_DEPTH, PLAUSIBLE_DENT_DEPTH
from impactlab.analytic.inversion import MC_REJECTED_WARNING

CliMain = Callable[..., tuple[int, str, str]]

#: The same drop on the command line.
PAPER_20_ARGS = (
    "invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2",
    "--delta-p", "22 um", "--ls", "1400 um", "--samples", "2000",
)  # fmt: skip


def _invert(**changes: Any) -> il.InversionResult:
    return invert(**{**PAPER_20, "n_samples": 2000, **changes})


@pytest.mark.parametrize(
    ("changes", "needle"),
    [
        ({"e": (0.5, 2.0)}, "the sigma of e = 2.0 does not fit its range"),
        ({"e": (0.5, 0.26)}, "e in [0, 1], at most 0.25"),
        ({"angle": (0.35, 0.5)}, "the sigma of angle = 0.5 rad (28.65 deg)"),
    ],
)
def test_sigma_wider_than_the_range_is_refused(changes: dict[str, Any], needle: str) -> None:
    with pytest.raises(ValueError, match="does not fit its range") as err:
        _invert(**changes)
    assert needle in str(err.value)


def test_sigma_within_the_range_is_accepted() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = _invert(e=(0.5, 0.02), mu=(0.2, 0.01))
    assert res.mc_rejected == 0.0 and res.mc_used == res.n_samples == 2000


def test_many_rejected_samples_warn_with_the_count_used() -> None:
    with pytest.warns(il.ImplausibleInputWarning, match=r"of the 2000 Monte Carlo samples") as rec:
        res = _invert(mu=(0.2, 0.19))
    assert res.mc_rejected > MC_REJECTED_WARNING
    assert res.mc_used == round(res.n_samples * (1.0 - res.mc_rejected))
    assert f"rest on the {res.mc_used} kept" in str(rec[0].message)
    assert "mc_used" in res.to_dict() and f"({res.mc_used} used)" in str(res)


def test_samples_discarded_for_e_above_1_are_named_as_such(cli_main: CliMain) -> None:
    # e = 1.02 +- 0.01 is read as 1 +- 0.01: half of e's samples lie above 1, none sticks
    code, _, err = cli_main(*PAPER_20_ARGS, "--e", "1.02", "--sigma-e", "0.01")
    assert code == 0
    rejected = [w for w in err.splitlines() if "Monte Carlo samples were discarded" in w]
    assert len(rejected) == 1, err
    assert "(more than 5%): 48.3% drew e > 1 (e = 1 +- 0.01 lies at the physical limit" in err
    assert "truncated to [0, 1]" in err and "sticking" not in rejected[0]
    assert "check the sigmas" not in err


def test_each_cause_of_discarded_samples_has_its_share() -> None:
    with pytest.warns(il.ImplausibleInputWarning) as rec:
        res = _invert(mu=(0.2, 0.3), e=(0.95, 0.2))
    text = next(str(w.message) for w in rec if "samples were discarded" in str(w.message))
    causes = text.split(": ", 1)[1].split(". ")[0]
    shares = [float(part.split("%")[0]) for part in causes.split("; ")]
    assert len(shares) == 3 and "drew e > 1 (e = 0.95 +- 0.2 lies 0.25 sigma inside" in text
    assert "fell in the sticking regime" in text and "drew mu < 0" in text
    assert sum(shares) == pytest.approx(100 * res.mc_rejected, abs=0.2)  # each counted once
    assert "check the sigmas" in text


def test_zero_dent_is_refused_and_a_shallow_one_warned() -> None:
    with pytest.raises(ValueError, match="below 1 nm"):
        _invert(delta_p=0.0)
    with pytest.raises(ValueError, match="below 1 nm"):
        _invert(delta_p=0.5 * MIN_DENT_DEPTH)
    with pytest.warns(il.ImplausibleInputWarning, match=r"50 nm is shallower than 0.1 um"):
        res = _invert(delta_p=0.5 * PLAUSIBLE_DENT_DEPTH)
    assert res.duration > 0.0


def test_cli_refuses_a_zero_dent(cli_main: CliMain) -> None:
    args = [a if a != "22 um" else "0 um" for a in PAPER_20_ARGS]
    code, out, err = cli_main(*args)
    assert code == 2 and out == ""
    assert err.startswith("error: --delta-p = 0.0 m is below 1 nm") and "Traceback" not in err


def test_cli_refuses_sigma_e_beyond_the_range(cli_main: CliMain) -> None:
    code, _, err = cli_main(*PAPER_20_ARGS, "--sigma-e", "2")
    assert code == 2 and err.startswith("error: --sigma-e = 2.0 does not fit its range")


def test_cli_rejected_samples_warn_in_text_and_json(cli_main: CliMain) -> None:
    code, out, err = cli_main(*PAPER_20_ARGS, "--sigma-mu", "0.19")
    assert code == 0
    assert "mc_used" in out and "note:" not in out  # the warning says it, on stderr
    assert err.startswith("warning: ") and "Monte Carlo samples were discarded" in err
    assert "fell in the sticking regime (alpha >= 0)" in err and "check the sigmas" in err
    code, out, err = cli_main(*PAPER_20_ARGS, "--sigma-mu", "0.19", "--json")
    data = json.loads(out)
    assert code == 0 and data["n_samples"] == 2000 and isinstance(data["mc_used"], int)
    assert data["mc_used"] == round(2000 * (1.0 - data["mc_rejected"]["value"]))
    assert any("% fell in the sticking regime" in w for w in data["warnings"])
    assert "Monte Carlo samples" in err


@pytest.mark.parametrize(
    ("line", "needle"),
    [
        ("seed = 1.5", "seed in the measurement file must be an integer >= 0, got 1.5"),
        ("samples = 200.7", "samples in the measurement file must be an integer >= 100, got 200.7"),
        ("samples = 50", "samples in the measurement file must be an integer >= 100, got 50"),
        ("seed = -3", "seed in the measurement file must be an integer >= 0, got -3"),
    ],
)
def test_file_counts_must_be_integers(
    cli_main: CliMain, tmp_path: Path, line: str, needle: str
) -> None:
    path = tmp_path / "drop.toml"
    path.write_text(f'case = "paper-20"\n{line}\n[sigma]\ne = 0.01\n')
    code, out, err = cli_main("invert", "--file", str(path))
    assert code == 2 and out == ""
    assert err.strip() == f"error: {needle}"


def test_exact_inputs_draw_no_samples(cli_main: CliMain) -> None:
    """Without any sigma nothing is drawn: ``mc_used`` is 0 and the Monte Carlo values are the
    nominal ones, bit for bit, in Python and in the JSON."""
    res = _invert()
    assert res.mc_used == 0 and res.n_samples == 2000 and res.mc_rejected == 0.0
    assert res.T_mc == res.T_median_mc == res.duration
    assert res.T_interval_mc == (res.duration, res.duration)
    assert res.F_mc == res.F_median_mc == res.mean_force
    assert res.sigma_T_mc == res.sigma_F_mc == 0.0
    code, out, _ = cli_main(*PAPER_20_ARGS, "--json")
    data = json.loads(out)
    assert code == 0 and data["mc_used"] == 0
    assert data["T_mc"]["value"] == data["duration"]["value"]
