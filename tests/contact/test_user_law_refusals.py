"""What a law of one's own refuses, and what its results say: tables whose loading fit cannot
follow them (a curve stiffer than Hertz), names that read as a built-in law's, sampling
arguments given with tables; the range line names the table's end and the curves' source; a
CSV row of three columns is told that the table takes two."""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

import impactlab as il
from impactlab.contact import (
    IndentationCurves,
    get_law,
    law_names,
    register_law,
    unregister_law,
)
from impactlab.contact._common import jg_critical
from impactlab.contact.indentation_data import shipped_curves
from impactlab.contact.law_file import read_law_file
from impactlab.contact.range_note import range_note
from impactlab.contact.registered import TABLE_FIT_TOLERANCE, check_law_name, check_table_fit
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = il.Rod.paper().tip_radius
DC, FC = jg_critical(PAIR.E_star, R, PAIR.yield_strength, PAIR.nu)


def _hertz(d: np.ndarray) -> np.ndarray:
    return 4.0 / 3.0 * PAIR.E_star * math.sqrt(R) * d**1.5


def _tables(stiff: bool) -> tuple[np.ndarray, ...]:
    """(delta, F, delta_max, delta_r) [m, N]: F/F_Hertz rising from 1 to 1.5 (``stiff``), or
    Hertz then a softer power law."""
    d = np.geomspace(DC, 200e-6, 30)
    if stiff:
        f = _hertz(d) * (1.0 + 0.5 * (d / DC - 1.0) / (d[-1] / DC - 1.0))
    else:
        f = FC * (d / DC) ** 1.25
    dm = d[::3]
    return d, f, dm, 0.8 * dm * (1.0 - DC / dm)


@pytest.fixture
def names() -> Iterator[list[str]]:
    """Names a test registers, unregistered after it."""
    taken: list[str] = []
    yield taken
    for name in taken:
        unregister_law(name)


def _write_law_file(folder: Path, name: str, tables: tuple[np.ndarray, ...]) -> Path:
    d, f, dm, dr = tables
    np.savetxt(folder / "l.csv", np.column_stack((d, f)), delimiter=",", header="delta,F")
    np.savetxt(folder / "u.csv", np.column_stack((dm, dr)), delimiter=",", header="dm,dr")
    path = folder / f"{name}.toml"
    path.write_text(
        f'name = "{name}"\nbody_material = "aisi-201"\nflat_material = "aisi-1010"\n'
        f'radius = {R!r}\nloading = "l.csv"\nunloading = "u.csv"\n'
    )
    return path


def test_a_table_stiffer_than_hertz_is_refused_with_where_and_what_to_check(
    tmp_path: Path,
) -> None:
    curves = IndentationCurves.from_arrays(PAIR, R, *_tables(stiff=True))
    with pytest.raises(ValueError, match="departs from the data's force") as caught:
        register_law("stiff-table", curves)
    text = str(caught.value)
    assert "law 'stiff-table'" in text and "-0.333 (relative)" in text
    assert "loading point index 29 (data row 30 of 30" in text and "F/F_Hertz = 1.5" in text
    assert "2.5 %" in text and "F/F_Hertz never rises" in text and "\n" not in text
    assert "stiff-table" not in law_names()
    with pytest.raises(ValueError, match=r"law file .*stiff-file.*departs from the data's force"):
        read_law_file(_write_law_file(tmp_path, "stiff-file", _tables(stiff=True)))


def test_the_shipped_and_hardened_fe_curves_pass_the_table_check(names: list[str]) -> None:
    from impactlab.fe.tabulated import hardened_curves

    for curves in (*shipped_curves(), hardened_curves()):
        check_table_fit("fe", curves)  # within 2.5 % (docs/laws/tabulated.md: 2.3 % largest)
    assert TABLE_FIT_TOLERANCE == 0.025
    soft = IndentationCurves.from_arrays(PAIR, R, *_tables(stiff=False))
    names.append("soft-table")
    register_law("soft-table", soft)  # a table the fit follows is kept


@pytest.mark.parametrize("name", ["kogut_komvopoulos", "jackson_green"])
def test_a_name_that_reads_as_a_built_in_one_is_refused(name: str, tmp_path: Path) -> None:
    builtin = name.replace("_", "-")
    curves = IndentationCurves.from_arrays(PAIR, R, *_tables(stiff=False))
    with pytest.raises(ValueError, match=f"reads as the built-in law '{builtin}'"):
        register_law(name, curves)
    with pytest.raises(ValueError, match=f"law file .*reads as the built-in law '{builtin}'"):
        read_law_file(_write_law_file(tmp_path, name, _tables(stiff=False)))
    assert get_law(builtin).law == builtin  # the built-in law keeps its name
    assert check_law_name("my_steel") == "my_steel"


def test_source_is_kept_and_sampling_arguments_are_refused_with_tables(
    names: list[str],
) -> None:
    curves = IndentationCurves.from_arrays(PAIR, R, *_tables(stiff=False))
    for key, value in (
        ("pair", PAIR),
        ("radius", R),
        ("delta_max", 1e-4),
        ("points", 64),
        ("tolerance", 0.01),
    ):
        with pytest.raises(ValueError, match=f"^{key} applies to sampled callables"):
            register_law("with-source", curves, **{key: value})  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^pair, radius apply to sampled callables"):
        register_law("with-source", curves, pair=PAIR, radius=R)
    names.append("with-source")
    law = register_law("with-source", curves, source="lab notebook 12, p. 40")
    assert law.own_curves.source == "lab notebook 12, p. 40"
    assert curves.source == "measured indentation data"  # the caller's curves are left as given
    assert "lab notebook 12, p. 40" in law.build(PAIR, R).source


def test_the_range_line_names_the_table_end_and_the_source(names: list[str]) -> None:
    curves = IndentationCurves.from_arrays(PAIR, R, *_tables(stiff=False), source="drop rig")
    names.append("ranged")
    model = register_law("ranged", curves).build(PAIR, R)
    line = range_note(model.law_id, model.params)
    end = model.max_interference
    assert line is not None and f"{end:.4g} m ({end / DC:.4g} delta_c)" in line
    assert line.endswith("source: measured: drop rig")
    shipped = get_law("tabulated").build(PAIR, R)
    line = range_note(shipped.law_id, shipped.params)
    assert line is not None and "(1000 delta_c)" in line
    assert "source: paper-aisi201-on-aisi1010: FE reference case" in line


@pytest.mark.parametrize(
    ("row", "hint"),
    [
        ("1e-6,0.1,7", "the table takes exactly two: leave out the others"),
        ("1e-6", "is the file truncated?"),
    ],
)
def test_a_row_of_another_width_gets_the_hint_that_fits(
    tmp_path: Path, row: str, hint: str
) -> None:
    loading = tmp_path / "l.csv"
    loading.write_text(f"delta,F\n{row}\n")
    with pytest.raises(ValueError, match="line 2 has") as caught:
        IndentationCurves.from_csv(PAIR, R, loading, tmp_path / "u.csv")
    assert hint in str(caught.value)
    other = "is the file truncated?" if "two" in hint else "exactly two"
    assert other not in str(caught.value)


def test_a_callable_stiffer_than_hertz_within_a_loose_tolerance_warns() -> None:
    """With tolerance=0.9 the law ran plain Hertz for a callable up to 4x stiffer, silently."""
    from impactlab.contact.sample_checks import ForceDepartsWarning

    pair = ContactPair(AISI_201, AISI_1010)
    radius = 8.8e-3

    def hertz(d: float) -> float:
        return 4.0 / 3.0 * pair.E_star * math.sqrt(radius) * d**1.5

    def residual(dm: float) -> float:
        return 0.8 * dm * max(1.0 - 1e-6 / dm, 0.0) ** 2

    kw = {"pair": pair, "radius": radius, "delta_max": 300e-6, "switch_interference": 1e-6}
    try:
        with pytest.warns(ForceDepartsWarning, match=r"law 'stiff-toy': its force departs"):
            register_law(
                "stiff-toy", loading=lambda d: hertz(d) * (1.0 + (d / 1e-6 - 1.0) * 0.01),
                unloading=residual, tolerance=0.9, **kw,
            )  # fmt: skip
    finally:
        unregister_law("stiff-toy")


@pytest.mark.parametrize("name", ["h\u0435rtz", "law\u00b2", "stahl-\u00df", "x\u0660"])
def test_a_law_name_beyond_ascii_is_refused(name: str) -> None:
    """A homoglyph name (h\u0435rtz: a Cyrillic e) registered, and printed as "hertz"."""
    with pytest.raises(ValueError, match="lower-case ASCII letters"):
        check_law_name(name)
