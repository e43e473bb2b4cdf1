"""An inversion keeps the texts of its warnings (``InversionResult.warnings``), the same as
``impactlab invert --json`` lists, and still warns each as an ImplausibleInputWarning."""

from __future__ import annotations

import json
import warnings
from collections.abc import Callable

import pytest
from inversion_cases import WIDE

import impactlab as il

CliMain = Callable[..., tuple[int, str, str]]

CLI = ["invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.7",
       "--sigma-mu", "0.05", "--delta-p", "22 um", "--ls", "1400 um", "--json"]  # fmt: skip


def test_the_result_carries_the_warnings_the_cli_lists(cli_main: CliMain) -> None:
    with pytest.warns(il.ImplausibleInputWarning) as issued:
        res = il.invert(**WIDE)
    # mu = 0.92 mu_c: first the advice on a tangentially compliant contact
    assert len(res.warnings) == 5 and "tangentially compliant" in res.warnings[0]
    assert res.warnings[1].startswith("T is ill-conditioned here")
    assert "discarded" in res.warnings[2] and "heavy tail" in res.warnings[3]
    assert "95 % interval of T" in res.warnings[4]  # its upper end above 0.1 s
    assert [str(w.message) for w in issued] == list(res.warnings)  # still issued, in order
    assert all(w.filename == __file__ for w in issued)  # at the caller's line
    code, out, err = cli_main(*CLI)
    assert code == 0, err
    data = json.loads(out)
    assert data["warnings"] == list(res.warnings) == res.to_dict()["warnings"]
    assert f"warning: {res.warnings[0]}" in str(res)


def test_no_warning_none_kept_and_the_callers_filters_hold() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        exact = il.invert(**{**WIDE, "mu": 0.2})
    assert exact.warnings == ()
    with warnings.catch_warnings():
        warnings.simplefilter("error", il.ImplausibleInputWarning)
        with pytest.raises(il.ImplausibleInputWarning, match="tangentially compliant"):
            il.invert(**WIDE)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", il.ImplausibleInputWarning)
        assert len(il.invert(**WIDE).warnings) == 5  # kept, whatever is shown
