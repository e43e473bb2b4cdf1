"""Measured indentation tables are checked in SI before they become curves: a table in the
wrong unit, past the radius or outside the loading range is refused in one line naming the
file, its line and the values as written (m, N); a CSV without a header keeps its first row;
pint Quantities are converted. Also: the documented leave-one-out errors and the
tabulated law's elastic limit in its details."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from impactlab.contact import IndentationCurves, get_law
from impactlab.contact._common import jg_critical
from impactlab.contact.indentation_data import ResidualRaisedWarning, shipped_curves
from impactlab.contact.table_input import read_table
from impactlab.contact.tabulated import interpolation_error
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = 8.8e-3
DC, FC = jg_critical(PAIR.E_star, R, PAIR.yield_strength, PAIR.nu)
ROOT = Path(__file__).resolve().parents[2]


def _tables() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Loading (delta [m], F [N]) and unloading (delta_max [m], delta_r [m]) sampled from the
    Jackson-Green law of the paper's pair: 40 points from 0.05 to 1000 delta_c."""
    m = get_law("jackson-green").build(PAIR, R)
    d = np.geomspace(0.05 * DC, 1000 * DC, 40)
    f = np.array([float(m.force(x)) for x in d])
    dm = np.geomspace(0.3 * DC, 1000 * DC, 9)
    dr = np.array([m.unload(x).delta_r for x in dm])
    return d, f, dm, dr


def _csv(path: Path, a: np.ndarray, b: np.ndarray, header: str | None = "x,y") -> Path:
    lines = ([header] if header else []) + [
        f"{float(x)!r},{float(y)!r}" for x, y in zip(a, b, strict=True)
    ]
    path.write_text("\n".join(lines) + "\n")
    return path


def _files(tmp_path: Path, **change: np.ndarray) -> tuple[Path, Path]:
    d, f, dm, dr = _tables()
    cols = {"d": d, "f": f, "dm": dm, "dr": dr} | change
    load = _csv(tmp_path / "load.csv", cols["d"], cols["f"])
    unload = _csv(tmp_path / "unload.csv", cols["dm"], cols["dr"])
    return load, unload


def test_the_sampled_tables_make_a_law_with_a_permanent_dent(tmp_path: Path) -> None:
    c = IndentationCurves.from_csv(PAIR, R, *_files(tmp_path))
    assert c.elastic_limit == pytest.approx(0.05) and c.delta.size == 40
    assert c.residual_ratio[-1] > 0.5  # the control the unit mistakes below are refused against


@pytest.mark.parametrize(("unit", "scale", "line"), [("mm", 1e3, 7), ("um", 1e6, 2)])
def test_an_unloading_table_in_mm_or_um_is_refused_naming_the_unit(
    tmp_path: Path, unit: str, scale: float, line: int
) -> None:
    """Formerly accepted as a law without permanent deformation (e 0.93 against 0.45)."""
    _, _, dm, dr = _tables()
    load, unload = _files(tmp_path, dm=dm * scale, dr=dr * scale)
    with pytest.raises(ValueError, match="is not smaller than the sphere radius") as err:
        IndentationCurves.from_csv(PAIR, R, load, unload)
    text = str(err.value)
    assert text.startswith(f"unloading CSV {str(unload)!r} line {line}: delta_max = ")
    assert "is not smaller than the sphere radius 0.0088 m" in text
    assert f"(written in {unit}? give them in m)" in text and "\n" not in text


def test_unloading_maxima_outside_the_loading_range_are_refused(tmp_path: Path) -> None:
    """Below the radius but past the loading curve: fewer than 2 maxima inside its range."""
    d, f, _, _ = _tables()
    short = d <= 10 * DC
    dm = np.geomspace(0.3 * DC, 10 * DC, 6)
    load, unload = _files(tmp_path, d=d[short], f=f[short], dm=dm * 1e3, dr=0.2 * dm * 1e3)
    with pytest.raises(ValueError, match="within the loading curve's range") as err:
        IndentationCurves.from_csv(PAIR, R, load, unload)
    text = str(err.value)
    span = f"{d[0]:.4g}-{d[short][-1]:.4g} m"
    assert (
        f"unloading CSV {str(unload)!r}: 0 delta_max within the loading curve's range, {span}"
        in text
    )
    assert "(written in mm? give them in m)" in text


def test_a_loading_curve_past_the_radius_is_refused(tmp_path: Path) -> None:
    d, _, _, _ = _tables()
    load, unload = _files(tmp_path, d=d * 1e6)
    with pytest.raises(ValueError, match=r"line \d+: delta = .* m is not smaller than the sphere"):
        IndentationCurves.from_csv(PAIR, R, load, unload)


def test_pint_quantities_are_converted_to_si() -> None:
    import pint

    u = pint.UnitRegistry()
    d, f, dm, dr = _tables()
    plain = IndentationCurves.from_arrays(PAIR, R, d, f, dm, dr)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no "unit stripped" warning: nothing is stripped
        given = IndentationCurves.from_arrays(
            PAIR, R, (d * 1e6) * u.um, (f / 1e3) * u.kN, (dm * 1e6) * u.um, (dr * 1e3) * u.mm
        )
    assert np.allclose(given.residual_ratio, plain.residual_ratio, rtol=1e-12)
    assert np.allclose(given.force, plain.force, rtol=1e-12)
    with pytest.raises(ValueError, match="force must be a quantity in N, got one in"):
        IndentationCurves.from_arrays(PAIR, R, d, f * u.m, dm, dr)


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (
            lambda c: c["f"].__setitem__(20, c["f"][19] * 0.9),
            r"^loading CSV '.*' line 22: F must not decrease along the loading curve, got "
            r"\d+\.?\d* N then \d+\.?\d* N \(delta = [\d.e+-]+ m\)$",
        ),
        (
            lambda c: c["d"].__setitem__(20, c["d"][19]),
            r"^loading CSV '.*' line 22: delta must be strictly increasing, got "
            r"([\d.e+-]+) m then \1 m$",
        ),
        (
            lambda c: c["f"].__setitem__(0, 0.0),
            r"^loading CSV '.*' line 2: delta and F must be > 0, got 2\.181e-08 m, 0 N",
        ),
        (
            lambda c: c["dr"].__setitem__(0, 0.1 * c["dm"][0]),
            None,  # 0.3 delta_c is past the elastic limit (0.05): a small dent is allowed
        ),
    ],
)
def test_a_bad_row_names_its_file_line_and_si_values(tmp_path: Path, edit, message) -> None:
    d, f, dm, dr = _tables()
    cols = {"d": d.copy(), "f": f.copy(), "dm": dm.copy(), "dr": dr.copy()}
    edit(cols)
    load, unload = _files(tmp_path, **cols)
    if message is None:  # a first ratio of 0.1, then 0: raised onto 0.1, with a warning
        with pytest.warns(ResidualRaisedWarning, match=r"unloading CSV '.*' line 3: 0 raised"):
            IndentationCurves.from_csv(PAIR, R, load, unload)
        return
    with pytest.raises(ValueError, match=message) as err:
        IndentationCurves.from_csv(PAIR, R, load, unload)
    assert "delta/delta_c" not in str(err.value) and "index" not in str(err.value)


def test_a_first_row_at_zero_is_named_not_the_internal_elastic_limit(tmp_path: Path) -> None:
    d, f, _, _ = _tables()
    load, unload = _files(tmp_path, d=np.r_[0.0, d], f=np.r_[0.0, f])
    with pytest.raises(ValueError, match="must be > 0") as err:
        IndentationCurves.from_csv(PAIR, R, load, unload)
    text = str(err.value)
    assert text.startswith(f"loading CSV {str(load)!r} line 2: delta and F must be > 0")
    assert "elastic_limit" not in text


def test_too_few_points_and_nan_name_the_file(tmp_path: Path) -> None:
    d, f, _, _ = _tables()
    load, unload = _files(tmp_path, d=d[:3], f=f[:3])
    with pytest.raises(ValueError, match=r"^loading CSV '.*': the loading curve needs at least 4 "
                       r"points past the elastic limit \(its first point, delta = 2\.181e-08 m\), "
                       r"got 2$"):  # fmt: skip
        IndentationCurves.from_csv(PAIR, R, load, unload)
    load.write_text(load.read_text().replace(repr(float(f[1])), "nan"))
    with pytest.raises(ValueError, match=r"^loading CSV '.*' line 3 is not two finite numbers"):
        IndentationCurves.from_csv(PAIR, R, load, unload)


def test_a_csv_without_a_header_keeps_its_first_row(tmp_path: Path) -> None:
    d, f, dm, dr = _tables()
    with_header = IndentationCurves.from_csv(PAIR, R, *_files(tmp_path))
    load = _csv(tmp_path / "l.csv", d, f, header=None)
    unload = _csv(tmp_path / "u.csv", dm[-2:], dr[-2:], header=None)  # two rows, no header
    x, _, lines = read_table(load, "loading CSV", "delta [m], F [N]")
    assert x.size == 40 and lines[0] == 1
    bare = IndentationCurves.from_csv(PAIR, R, load, unload)
    assert bare.delta.size == with_header.delta.size == 40
    assert bare.elastic_limit == with_header.elastic_limit and bare.delta_max.size == 2
    commented = tmp_path / "c.csv"
    commented.write_text("# rig 3\n\ndelta_m,F_N\n" + load.read_text())
    assert read_table(commented, "loading CSV", "delta [m], F [N]")[0].size == 40


def _doc_row(label: str) -> list[str]:
    text = (ROOT / "docs" / "laws" / "tabulated.md").read_text(encoding="utf-8")
    line = next(ln for ln in text.splitlines() if ln.startswith(f"| {label} |"))
    return [c.strip() for c in line.strip("|").split("|")][1:7]


#: The columns of the error bounds table (docs/laws/tabulated.md), by curves.
_COLUMNS = (
    "paper-aisi201-on-aisi1010",
    "aisi201-on-al6061t6",
    "elastic-sphere-on-aisi4340",
    "aisi201-on-pmma",
    "elastic-52100-on-aisi304",
    "elastic-52100-on-copper-ofhc",
)


def test_the_documented_leave_one_out_errors_are_the_measured_ones() -> None:
    curves = {c.name: c for c in shipped_curves()}
    force = _doc_row("leave-one-out, whole curve: each interior FE point predicted by the fit "
                     "to the others")  # fmt: skip
    residual = _doc_row("`delta_r/delta_max`, leave-one-out")
    for name, f_cell, r_cell in zip(_COLUMNS, force, residual, strict=True):
        ef, er = interpolation_error(curves[name])
        assert f_cell == f"{100 * ef:.1f} %", name
        assert r_cell == (f"{er:.1g}" if er < 0.01 else f"{er:.2g}"), name


def test_the_tabulated_details_give_the_elastic_limit_in_delta_c() -> None:
    m = get_law("tabulated").build(PAIR, R)
    assert "elastic_limit" not in m.details
    assert m.details["elastic_limit_over_delta_c"] == 1.0
    assert m.switch_interference == pytest.approx(m.details["delta_c"])
