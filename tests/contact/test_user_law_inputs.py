"""The inputs of a law of one's own say what to change: a callable that leaves Hertz before the
switch is told to give ``switch_interference``; every length of ``register_law`` takes units;
a 2-D array, a semicolon- or tab-separated CSV and a radius in the wrong unit (a bare number is
metres) are each named in one line."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from impactlab.contact import (
    IndentationCurves,
    get_law,
    law_names,
    register_law,
    unregister_law,
)
from impactlab.contact._common import jg_critical
from impactlab.contact.law_file import read_law_file
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = 8.8e-3
DC, FC = jg_critical(PAIR.E_star, R, PAIR.yield_strength, PAIR.nu)
GHAEDNIA = get_law("ghaednia").build(PAIR, R)


def natural_f(delta: float) -> float:
    """The Ghaednia force: it leaves Hertz before the pair's delta_c."""
    return float(GHAEDNIA.force(delta))


def natural_dr(delta_max: float) -> float:
    return float(GHAEDNIA.unload(delta_max).delta_r)


def _tables() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The Ghaednia law sampled up to 300 um (delta, F, delta_max, delta_r; SI)."""
    d = np.geomspace(1e-8, 300e-6, 64)
    f = np.array([natural_f(x) for x in d])
    dm = d[31::4]
    return d, f, dm, np.array([natural_dr(x) for x in dm])


def test_a_callable_off_hertz_at_the_default_switch_is_told_to_give_it() -> None:
    with pytest.raises(ValueError, match="switch_interference") as err:
        register_law("nat-default", loading=natural_f, unloading=natural_dr, pair=PAIR, radius=R,
                     delta_max=300e-6)  # fmt: skip
    text = str(err.value)
    assert "\n" not in text
    assert (
        f"F(switch_interference = {DC:.4g} m, by default the pair's Jackson-Green delta_c)" in text
    )
    assert "-6.7 % from Hertz's" in text
    assert "give switch_interference=<where F leaves Hertz>" in text
    assert "first loading point" not in text and "index 0" not in text  # not the tables' words
    assert "unit mistake" not in text  # a few per cent off: no unit hint
    with pytest.raises(ValueError, match=r"F\(switch_interference = 4e-07 m\) is"):
        register_law("nat-given", loading=natural_f, unloading=natural_dr, pair=PAIR, radius=R,
                     delta_max=300e-6, switch_interference=4e-7)  # fmt: skip
    assert not any(n.startswith("nat-") for n in law_names())


def test_where_the_callable_leaves_hertz_it_registers() -> None:
    sw = GHAEDNIA.switch_interference
    law = register_law("nat-switch", loading=natural_f, unloading=natural_dr, pair=PAIR,
                       radius=R, delta_max=300e-6, switch_interference=sw)  # fmt: skip
    try:
        assert law.own_curves.elastic_limit * DC == pytest.approx(sw, rel=1e-12)
    finally:
        unregister_law("nat-switch")


def test_every_length_of_register_law_takes_units() -> None:
    sw = GHAEDNIA.switch_interference
    kw = {"loading": natural_f, "unloading": natural_dr, "pair": PAIR}
    law = register_law("nat-units", radius="8.8 mm", delta_max="300 um",
                       switch_interference=f"{sw * 1e6!r} um", **kw)  # fmt: skip
    try:
        c = law.own_curves
        assert c.delta[-1] * DC == pytest.approx(300e-6, rel=1e-12)
        assert c.elastic_limit * DC == pytest.approx(sw, rel=1e-12)
    finally:
        unregister_law("nat-units")
    with pytest.raises(ValueError, match="delta_max"):
        register_law("nat-bad", radius=R, delta_max="300 N", switch_interference=sw, **kw)
    with pytest.raises(ValueError, match="switch_interference"):
        register_law("nat-bad", radius=R, delta_max=300e-6, switch_interference="0.3", **kw)


def test_a_two_dimensional_array_is_named() -> None:
    d, f, dm, dr = _tables()
    table = np.c_[d, f]
    with pytest.raises(ValueError, match=r"^delta must be 1-D .* shape \(64, 2\)"):
        IndentationCurves.from_arrays(PAIR, R, table, f, dm, dr)
    with pytest.raises(ValueError, match=r"^delta_r must be 1-D .* shape \(9, 1\)"):
        IndentationCurves.from_arrays(PAIR, R, d, f, dm, dr[:, None])


def _write(path: Path, a: np.ndarray, b: np.ndarray, sep: str = ",") -> Path:
    lines = [f"x{sep}y"] + [f"{float(x)!r}{sep}{float(y)!r}" for x, y in zip(a, b, strict=True)]
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize(("sep", "said"), [(";", "';'"), ("\t", "a tab")])
def test_a_csv_with_another_separator_is_told_to_use_commas(
    tmp_path: Path, sep: str, said: str
) -> None:
    d, f, dm, dr = _tables()
    load = _write(tmp_path / "load.csv", d, f, sep)
    unload = _write(tmp_path / "unload.csv", dm, dr)
    with pytest.raises(ValueError, match="comma-separated") as err:
        IndentationCurves.from_csv(PAIR, R, load, unload)
    text = str(err.value)
    assert "line 2 has 1 column(s)" in text
    assert f"the line holds {said}: the file must be comma-separated" in text
    assert "truncated" not in text


def test_a_radius_in_mm_given_as_metres_gets_a_hint(tmp_path: Path) -> None:
    d, f, dm, dr = _tables()
    load, unload = _write(tmp_path / "l.csv", d, f), _write(tmp_path / "u.csv", dm, dr)
    with pytest.raises(ValueError, match="unit mistake") as err:
        IndentationCurves.from_csv(PAIR, 8.8, load, unload)
    text = str(err.value)
    assert "-96.8 % from Hertz's" in text
    assert "radius = 8.8 m is in metres (a bare number is metres)" in text
    assert 'with radius = "8.8 mm" the force is' in text
    # forces in kN: no radius fits; every unit is named
    with pytest.raises(ValueError, match=r"check radius = 0\.0088 m .* forces in N"):
        IndentationCurves.from_arrays(PAIR, R, d, f / 1e3, dm, dr)
    # 13 % off Hertz (plastic from the first point): no unit hint
    with pytest.raises(ValueError, match=r"-13\.2 % from Hertz's") as err:
        IndentationCurves.from_arrays(PAIR, R, d[30:], f[30:], dm, dr)
    assert "unit mistake" not in str(err.value)


def test_a_law_file_with_a_bare_radius_gets_the_hint(tmp_path: Path) -> None:
    d, f, dm, dr = _tables()
    _write(tmp_path / "loading.csv", d, f)
    _write(tmp_path / "unloading.csv", dm, dr)
    keys = {"name": "bare-radius", "body_material": "aisi-201", "flat_material": "aisi-1010",
            "loading": "loading.csv", "unloading": "unloading.csv"}  # fmt: skip
    path = tmp_path / "law.toml"
    path.write_text("".join(f"{k} = {json.dumps(v)}\n" for k, v in keys.items()) + "radius = 8.8\n")
    with pytest.raises(ValueError, match=r'with radius = "8\.8 mm" the force is'):
        read_law_file(path)
    assert "bare-radius" not in law_names()


def test_a_callable_for_another_radius_gets_the_hint() -> None:
    with (
        pytest.raises(ValueError, match="unit mistake") as err,
        pytest.warns(UserWarning, match="plausible range"),
    ):
        register_law("nat-radius", loading=natural_f, unloading=natural_dr, pair=PAIR,
                     radius=8.8, delta_max=300e-6, switch_interference=1e-7)  # fmt: skip
    text = str(err.value)
    assert "F(switch_interference = 1e-07 m) is" in text
    assert 'with radius = "8.8 mm" the force is' in text
