"""The inversion's inputs read one way only: a (value, sigma) pair is a tuple or a
:class:`Measured` (a list is refused, as an array is: ``invert`` takes one drop); a velocity
change that no impact gives marks the result not ok, as ``impactlab invert --json`` says; and
the command's table shows the inputs as its JSON does, the magnitudes ``invert`` uses."""

from __future__ import annotations

import json
import math
from collections.abc import Callable

import numpy as np
import pytest

import impactlab as il
from impactlab.analytic import Measured, invert
from impactlab.experiment.analysis import IMPOSSIBLE_PHRASES

CliMain = Callable[..., tuple[int, str, str]]
BASE = {"angle": math.radians(20), "v_i": -1.41, "e": 0.5, "mu": 0.2, "delta_p": 22e-6,
        "sliding_length": 1400e-6, "n_samples": 200}  # fmt: skip
CLI = ["invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2",
       "--delta-p", "22 um", "--ls", "1400 um", "--samples", "200"]  # fmt: skip


def _table(text: str) -> dict[str, tuple[str, str]]:
    """The rows of the rich table in ``text``: name -> (value, unit) (a row's first line)."""
    rows: dict[str, tuple[str, str]] = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.split("│")[1:-1]]
        if len(cells) == 3 and cells[0]:
            rows[cells[0]] = (cells[1], cells[2])
    return rows


# -- a (value, sigma) pair is a tuple or Measured -------------------------------------------------


@pytest.mark.parametrize(
    ("name", "value"),
    [("mu", [0.2, 0.13]), ("delta_p", [22e-6, 26e-6]), ("v_i", [1.41, 2.18]), ("e", [0.5])],
)
def test_a_list_is_no_value_sigma_pair(name: str, value: list[float]) -> None:
    """A list was read as (value, sigma): mu=[0.2, 0.13] ran as mu = 0.2 +- 0.13."""
    with pytest.raises(ValueError, match=r" is a list: ") as err:
        invert(**{**BASE, name: value})
    text = str(err.value)
    assert text.startswith(f"{name} = {value!r} is a list: ")
    assert "a tuple (value, sigma) or Measured(value, sigma)" in text
    assert "invert takes one drop" in text and "impact_duration" in text and "\n" not in text


def test_a_tuple_and_measured_stay_pairs_and_an_array_stays_refused() -> None:
    pair = invert(**{**BASE, "mu": (0.2, 0.01)})
    assert pair.inputs["mu"] == (0.2, 0.01)
    assert invert(**{**BASE, "mu": Measured(0.2, 0.01)}).inputs == pair.inputs
    with pytest.raises(ValueError, match=r"^mu must be a real number"):
        invert(**{**BASE, "mu": np.array([0.2, 0.13])})


# -- a velocity change no impact gives: the result is not ok --------------------------------------


def test_an_impossible_dv_cy_marks_the_result_not_ok() -> None:
    """It came back as plain success (F = 5610 N), with only a warning saying e = 120.4."""
    with pytest.warns(il.ImplausibleInputWarning, match="no impact gives it"):
        res = invert(**{**BASE, "dv_cy": 50.0})
    assert not res.ok and len(res.doubts) == 1 and round(res.mean_force) == 5610
    assert "implies e = 120.4" in res.doubts[0] and res.doubts[0] in res.warnings
    assert "ok=False" in repr(res) and "  ok: no" in str(res)
    assert f"  doubt: {res.doubts[0]}" in str(res)
    data = res.to_dict()
    assert data["ok"] is False and data["doubts"] == list(res.doubts)
    fine = invert(**{**BASE, "dv_cy": 0.62})
    assert fine.ok and fine.doubts == () and "ok" not in repr(fine) and "ok:" not in str(fine)
    assert fine.to_dict()["ok"] is True and fine.to_dict()["doubts"] == []


def test_a_misfit_rod_is_a_doubt_as_on_the_command_line() -> None:
    with pytest.warns(il.ImplausibleInputWarning, match="^rod: the mass and the inertia"):
        grams = il.Rod(length=0.3048, tip_radius=0.0088, mass=460.7, inertia=3.5667e-3)
    with pytest.warns(il.ImplausibleInputWarning):
        res = invert(**BASE, rod=grams)
    assert not res.ok and res.doubts[0].startswith("rod: the mass and the inertia do not fit")


def test_the_doubt_rule_is_analyzes() -> None:
    from impactlab.analytic.result import DOUBT_PHRASES, doubting

    assert set(IMPOSSIBLE_PHRASES) <= set(DOUBT_PHRASES)
    assert doubting(["plain", "x: no impact gives it"]) == ("x: no impact gives it",)


def test_cli_json_and_python_agree_on_an_impossible_dv_cy(cli_main: CliMain) -> None:
    code, out, err = cli_main(*CLI, "--dv-cy", "50 m/s", "--json")
    assert code == 0, err
    data = json.loads(out)
    with pytest.warns(il.ImplausibleInputWarning):
        res = invert(**{**BASE, "dv_cy": 50.0})
    assert data["ok"] is res.ok is False and data["doubts"] == list(res.doubts)
    code, out, err = cli_main(*CLI, "--dv-cy", "50 m/s")
    assert code == 0 and "no impact gives it" in err
    rows = _table(out)
    assert rows["ok"] == ("no", "") and rows["doubt"][0].startswith("dv_cy = 50 +- 0 m/s")


# -- one sign convention in the table and the JSON ------------------------------------------------


@pytest.mark.parametrize("vi", ["-1.41 m/s", "1.41 m/s"])
def test_cli_table_and_json_show_the_magnitude_of_v_i(cli_main: CliMain, vi: str) -> None:
    """The JSON showed 1.41 and the table -1.41 for --vi "-1.41 m/s"."""
    args = [*CLI[:3], "--vi", vi, *CLI[5:]]
    args += ["--ls", "-1400 um", "--sigma-vi", "0.01 m/s", "--sigma-ls", "50 um"]
    args += ["--correlation", "vi,ls=0.5"]
    code, out, err = cli_main(*args)
    assert code == 0, err
    rows = _table(out)
    assert rows["|v_i|"] == ("1.41 ± 0.01", "m/s") and "ok" not in rows
    assert rows["|sliding_length|"] == ("1400 ± 50", "um")
    assert "v_i" not in rows and "sliding_length" not in rows
    code, js, err = cli_main(*args, "--json")
    assert code == 0, err
    data = json.loads(js)
    assert data["inputs"]["v_i"]["value"] == 1.41
    assert data["inputs"]["sliding_length"]["value"] == 1.4e-3
    # the coefficient of the magnitudes, in the table as in the JSON
    (corr,) = data["correlation"]
    rho = corr["coefficient"]["value"]
    assert rho == (0.5 if vi.startswith("-") else -0.5)  # both given negative, or one
    assert rows["correlation"] == (f"(|v_i|, |sliding_length|) {rho:g}", "")
