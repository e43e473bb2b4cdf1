"""The batches' inputs read as ``simulate`` reads them (pint Quantities and strings with units,
dimensionless ones in percent), the words of a flagged case and of a keyword a batch does not
take, the columns of a history in ``dir()``, a failed case's regime in ``to_dataframe`` and the
set-up rows of a drop's summary."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
import pint
import pytest

import impactlab as il
from impactlab._validation import check_array
from impactlab.dynamics.kernels.layout import HISTORY_FIELDS
from impactlab.flags import ResultFlag, messages

ROD = il.Rod.paper()
AL = il.get_material("al-6061-t6")
U: Any = pint.UnitRegistry()  # a registry of the user's, not impactlab's
CliMain = Callable[..., tuple[int, str, str]]


def _head(flag: ResultFlag) -> str:
    """A flag's name as its message begins (``"energy gain"``)."""
    return messages(flag)[0].split(":")[0]


def test_a_dimensionless_quantity_array_is_its_pure_number() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # pint's UnitStrippedWarning: the unit dropped
        assert check_array("mu", U.Quantity([10.0, 20.0], "percent")).tolist() == [0.1, 0.2]
        assert check_array("mu", U.Quantity(20.0, "percent")).tolist() == 0.2
        assert check_array("mu", U.Quantity([0.1, 0.3], "")).tolist() == [0.1, 0.3]
    with pytest.raises(ValueError, match=r"^mu is a pure number: .*0\.2.*\[length\]"):
        check_array("mu", U.Quantity([0.2], "m"))


@pytest.mark.parametrize("mu", [U.Quantity(20, "percent"), U.Quantity([20.0], "percent")])
def test_batch_reads_mu_in_percent_as_simulate_does(mu: object) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        b = il.simulate_batch(ROD, mu=mu, angle="20 deg", vy="-1.41 m/s")
        d = il.simulate_drops(ROD, mu=mu, angle="20 deg", vy="-1.41 m/s")
    r = il.simulate(ROD, mu=U.Quantity(20, "percent"), angle="20 deg", velocity=(0, -1.41))
    assert b.mu.tolist() == d.mu.tolist() == [0.2] == [r.mu]
    assert b.e[0] == pytest.approx(r.e, rel=1e-9)


@pytest.mark.parametrize("run", [il.simulate_batch, il.simulate_drops])
def test_a_dimensional_mu_is_refused_naming_mu(run: Callable[..., object]) -> None:
    for mu in (U.Quantity(0.2, "m/s"), U.Quantity([0.2, 0.3], "m/s")):
        with pytest.raises(ValueError, match=r"^mu is a pure number"):
            run(ROD, mu=mu, angle=0.35, vy=-1.41)
    with pytest.raises(ValueError, match=r"^mu is a pure number"):
        il.simulate(ROD, mu=U.Quantity(0.2, "m/s"), angle=0.35, velocity=(0, -1.41))


def test_batch_arrays_with_units_are_si() -> None:
    b = il.simulate_batch(
        ROD,
        mu=U.Quantity([10.0, 20.0], "percent"),
        angle=U.Quantity([20.0, 30.0], "deg"),
        vy=U.Quantity(-1410.0, "mm/s"),
        vx=[0.0, U.Quantity(0.0, "km/h")],
    )
    plain = il.simulate_batch(ROD, mu=[0.1, 0.2], angle=np.radians([20, 30]), vy=-1.41, vx=0.0)
    assert b.mu.tolist() == [0.1, 0.2] and b.angle == pytest.approx(np.radians([20, 30]))
    assert b.vy.tolist() == [-1.41, -1.41]
    assert b.e == pytest.approx(plain.e, rel=1e-12)
    listed = il.simulate_batch(
        ROD, mu=0.2, angle=[U.Quantity(20, "deg"), U.Quantity(30, "deg")], vy=-1.41
    )  # numpy alone reads these as [0, 0]
    assert listed.angle == pytest.approx(np.radians([20, 30]))


def test_a_wrong_dimension_in_a_batch_names_the_input() -> None:
    with pytest.raises(ValueError, match=r"^angle\[1\]: .*30.* has the wrong dimension"):
        il.simulate_batch(ROD, mu=0.2, angle=[0.35, U.Quantity(30, "mm")], vy=-1.41)
    with pytest.raises(ValueError, match=r"^vy: .* has the wrong dimension"):
        il.simulate_batch(ROD, mu=0.2, angle=0.35, vy=U.Quantity([-1.41], "m"))
    with pytest.raises(ValueError, match=r"^mu\[1\] is a pure number"):
        il.simulate_batch(ROD, mu=[0.2, U.Quantity(0.2, "m/s")], angle=0.35, vy=-1.41)


def test_a_case_that_is_not_ok_names_its_flags() -> None:
    b = il.simulate_batch(
        ROD, friction="impulse_ratio", mu=[0.2, 0.9], angle=math.radians(45), vy=-1.41
    )
    assert b.ok.tolist() == [True, False]
    assert int(b.flags[1]) & ResultFlag.ENERGY_GAIN
    assert b.messages[0] == "ok"
    text = b.messages[1]
    assert text.startswith(f"computed, not ok (flags {int(b.flags[1])}): ")
    assert _head(ResultFlag.ENERGY_GAIN) in text
    tip = il.simulate_batch(ROD, mu=0.2, angle=math.radians(5), vy=-1.41)
    assert not tip.ok[0] and _head(ResultFlag.BEYOND_TIP) in tip.messages[0]


@pytest.mark.parametrize(
    ("keyword", "words"),
    [
        ("history", "a batch keeps no history"),
        ("theta", "the rod's angle to the flat is angle="),
        ("angel", "(did you mean 'angle'?)"),
    ],
)
def test_a_keyword_the_batch_does_not_take_is_explained(keyword: str, words: str) -> None:
    extra: dict[str, Any] = {"angle": 0.35, keyword: True}
    with pytest.raises(TypeError) as info:
        il.simulate_batch(ROD, mu=0.2, vy=-1.41, **extra)
    text = str(info.value)
    assert text.startswith(f"simulate_batch() got unexpected keyword argument(s) {keyword}")
    assert words in text and "it takes angle, body, constant_angle," in text
    if keyword == "history":
        assert "impactlab.simulate(" in text


def test_the_batch_keeps_its_signature_and_docstring() -> None:
    import inspect

    params = inspect.signature(il.simulate_batch).parameters
    assert "mu" in params and "partial_slip_cells" in params and "history" not in params
    assert (il.simulate_batch.__doc__ or "").startswith("Many impacts of one body")


def test_dir_of_a_history_lists_its_columns() -> None:
    h = il.simulate(ROD, mu=0.2, angle=0.35, velocity=(0, -1.41)).history
    assert h is not None
    assert set(HISTORY_FIELDS) <= set(dir(h)) and "to_dataframe" in dir(h)
    with pytest.raises(AttributeError, match=r"did you mean 'normal_force'\?"):
        _ = h.normal_forc


def test_a_failed_cases_regime_is_na_in_the_dataframe() -> None:
    b = il.simulate_batch(ROD, mu=[0.2, -1.0], angle=0.35, vy=-1.41)
    df = b.to_dataframe()
    assert str(df["regime"].dtype) == "category"
    assert df["regime"].isna().tolist() == [False, True] and df["regime"][0] == "slip"
    shown = df[["regime", "flags", "n_steps"]].to_string().splitlines()[2].split()
    assert shown == ["1", "<NA>", "<NA>", "<NA>"]


SETUP = ["body", "flat", "law", "friction", "mu", "angle", "velocity_in", "spin_in", "rate"]


def test_a_drops_summary_says_what_was_dropped() -> None:
    d = il.simulate_drop(ROD, AL, mu=0.2, angle=math.radians(20),
                         velocity=(0.0, -1.41), history=False)  # fmt: skip
    s = d.summary()
    assert list(s)[: len(SETUP)] == SETUP
    assert s["flat"] == AL.name and "AISI 201" in s["body"]
    assert s["angle"] == d.angle and s["velocity_in"] == d.velocity_in
    text = str(d)
    assert "20 deg" in text and "(0, -1.41) m/s" in text and AL.name in text
    assert AL.name in d._repr_html_()


def test_impactlab_drop_prints_the_set_up(cli_main: CliMain) -> None:
    code, out, err = cli_main(
        "drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2", "--rigid",
        "--flat", "al-6061-t6",
    )  # fmt: skip
    assert code == 0, err
    rows = [line.split("│")[1].strip() for line in out.splitlines() if line.count("│") >= 3]
    assert [r for r in rows if r][: len(SETUP)] == SETUP
    assert "aluminium 6061-T6" in out
