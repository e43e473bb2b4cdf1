"""A result that is not ok says so in its table (``print(result)``, the notebook's HTML and the
command line's), as invert and analyze do: an ``ok`` row naming the flags that make it so, which
a result that is ok (an advisory flag at most) does not have."""

from __future__ import annotations

import math

import impactlab as il

ROD = il.Rod.paper()
PAPER = {"angle": math.radians(20), "velocity": (0.0, -1.41)}


def test_a_result_not_ok_has_an_ok_row_naming_its_flags() -> None:
    r = il.simulate(ROD, friction="impulse_ratio", mu=0.9, **PAPER)
    assert not r.ok
    assert r.summary()["ok"] == "no: energy_gain (see the warnings)"
    assert "no: energy_gain (see the warnings)" in str(r)
    assert "no: energy_gain" in r._repr_html_()
    keys = list(r.summary())
    assert keys.index("ok") == keys.index("flags") - 1


def test_an_ok_result_with_an_advisory_flag_has_none() -> None:
    r = il.simulate(ROD, mu=0.2, **PAPER)
    assert r.ok and r.flags  # LAW_EXTRAPOLATED only
    assert "ok" not in r.summary()


def test_the_command_line_table_shows_it(cli_main) -> None:
    argv = ("simulate", "rod", "--angle", "20 deg", "--vy", "-1.41")
    code, out, _ = cli_main(*argv, "--friction", "impulse_ratio", "--mu", "0.9")
    assert code == 0 and "no: energy_gain (see the warnings)" in out
    code, out, _ = cli_main(*argv, "--mu", "0.2")
    assert code == 0 and "no: " not in out
