"""One result family for impacts and drops: a drop's history columns and sequence totals are
named in ``impactlab.schema`` (the impact's name where the quantity is the same, per end with
``schema.end_column``; names of their own otherwise), the names before 0.3 read the same data
with a DeprecationWarning naming the new one, both results share one display path, and
``simulate`` and ``simulate_drop`` keep the history by default."""

from __future__ import annotations

import html
import inspect
import json
import math
import warnings

import numpy as np
import pytest

import impactlab
from impactlab import schema
from impactlab._display import field_rows
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_history import DROP_HISTORY_COLUMNS, DropHistory
from impactlab.dynamics.drop_result import UNITS, DropResult
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.result_display import ResultDisplay
from impactlab.dynamics.results import ImpactResult
from impactlab.sweep import Study
from impactlab.sweep.engine import ENGINE, SEQUENCE_OUTPUTS
from impactlab.sweep.study_meta import resolve_outputs

KW = {"mu": 0.2, "angle": math.radians(40), "velocity": (0.0, -1.4)}


@pytest.fixture(scope="module")
def drop() -> DropResult:
    """A rigid rod's drop (one contact, fast) with its history."""
    return simulate_drop(impactlab.Rod.paper(), **KW)


def test_schema_names_every_engine_column_in_order() -> None:
    renamed = [schema.RENAMED_DROP_HISTORY.get(n, n) for n in F.DROP_HISTORY_FIELDS]
    assert tuple(renamed) == DROP_HISTORY_COLUMNS
    assert len(set(DROP_HISTORY_COLUMNS)) == len(DROP_HISTORY_COLUMNS) == F.N_DROP_HISTORY
    impact = {f.name: f for f in schema.HISTORY_FIELDS}
    for f in schema.DROP_HISTORY_FIELDS:  # an impact column's name: its unit too
        base = f.name[:-2] if f.name[-2:] in schema.END_SUFFIXES else f.name
        if base in impact:
            assert impact[base].unit == f.unit, f.name
    assert schema.end_column("normal_force", 1) == "normal_force_1"
    with pytest.raises(ValueError, match="end must be 0"):
        schema.end_column("normal_force", 2)


def test_old_history_columns_warn_and_read_the_same_column() -> None:
    data = np.arange(7 * F.N_DROP_HISTORY, dtype=float).reshape(7, F.N_DROP_HISTORY)
    h = DropHistory(data)
    for j, old in enumerate(F.DROP_HISTORY_FIELDS):
        new = schema.RENAMED_DROP_HISTORY.get(old)
        np.testing.assert_array_equal(h[DROP_HISTORY_COLUMNS[j]], data[:, j])
        np.testing.assert_array_equal(getattr(h, DROP_HISTORY_COLUMNS[j]), data[:, j])
        if new is None:  # the same name as before (t, phi)
            continue
        with pytest.warns(DeprecationWarning, match=f"'{old}' is renamed '{new}'"):
            np.testing.assert_array_equal(h[old], data[:, j])
    with pytest.raises(KeyError, match="unknown history column 'nope'"):
        h["nope"]
    np.testing.assert_array_equal(h.tip_height, -h.penetration_0)
    assert set(h.units) == set(DROP_HISTORY_COLUMNS)
    df = h.to_dataframe()
    assert list(df.columns) == list(h.fields) and df.attrs["units"]["normal_force_0"] == "N"
    np.testing.assert_array_equal(df["energy_balance_error"].to_numpy(), data[:, -1])


def test_renamed_totals_keep_their_old_names_for_one_release(drop: DropResult) -> None:
    d = drop.to_dict(include_history=True)
    text = json.dumps(d)
    for old, new in schema.RENAMED_DROP_FIELDS.items():
        assert new in UNITS and schema.unit(new) == schema.unit(old)
        value = getattr(drop, new)
        assert math.isfinite(value) and d[new] == value
        assert old not in d and f'"{old}"' not in text.split('"contacts"')[0]
        with pytest.warns(DeprecationWarning, match=f"'{old}' is renamed '{new}'"):
            assert getattr(drop, old) == value
        with pytest.warns(DeprecationWarning, match=f"'{old}' is renamed '{new}'"):
            assert d[old] == value
    assert set(d["history"]) == set(DROP_HISTORY_COLUMNS)
    with warnings.catch_warnings():  # the new names never warn
        warnings.simplefilter("error")
        drop.to_dict()
        str(drop), repr(drop), drop._repr_html_(), drop.to_pint()


def test_one_rigid_contact_reads_the_same_under_both_names(drop: DropResult) -> None:
    """A rigid rod's drop of one contact: the sequence totals are the impact's fields."""
    r = impactlab.simulate(impactlab.Rod.paper(), rtol=1e-10, **KW)
    d = simulate_drop(impactlab.Rod.paper(), rtol=1e-10, history=False, **KW)
    assert d.n_contacts == 1
    for old, new in schema.RENAMED_DROP_FIELDS.items():
        assert getattr(d, new) == pytest.approx(getattr(r, old), rel=1e-6), new


def test_impact_and_drop_share_the_display_path(drop: DropResult) -> None:
    impact = impactlab.simulate(impactlab.Rod.paper(), **KW)
    for name in ("__str__", "__repr__", "_repr_html_", "_rows"):
        assert getattr(ImpactResult, name) is getattr(ResultDisplay, name), name
        assert getattr(DropResult, name) is getattr(ResultDisplay, name), name
    for r in (impact, drop):
        rows = field_rows(r.summary(), r.display_units())
        lines = str(r).splitlines()
        assert lines[0] == type(r).__name__
        assert [ln.split()[0] for ln in lines[1 : len(rows) + 1]] == [a for a, _b, _c in rows]
        assert "\n" not in repr(r) and repr(r).startswith(type(r).__name__ + "(")
        assert all(html.escape(b) in r._repr_html_() for _a, b, _c in rows)
    assert "dent_depth" in repr(drop) and "delta_p" in repr(impact)


def test_one_history_default() -> None:
    defaults = {
        f.__name__: inspect.signature(f).parameters["history"].default
        for f in (impactlab.simulate, impactlab.simulate_drop)
    }
    assert defaults == {"simulate": True, "simulate_drop": True}


def test_sequence_columns_only_in_flexible_stores() -> None:
    rigid = Study(name="r", grid={"angle": [0.3, 0.6]}, fixed={"vy": -1.4, "mu": 0.2})
    flexible = Study(
        name="f", grid={"angle": [0.3, 0.6]}, fixed={"vy": -1.4, "mu": 0.2, "body": "flexible_rod"}
    )
    assert not set(SEQUENCE_OUTPUTS) & set(resolve_outputs(rigid, ENGINE))
    assert set(SEQUENCE_OUTPUTS) <= set(resolve_outputs(flexible, ENGINE))
    assert {"delta_p", "duration"} <= set(resolve_outputs(flexible, ENGINE))
