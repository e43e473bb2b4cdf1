"""A drop's e removes the gravity impulse of its sequence (e = e_raw + g T/|v_n,in|): a nearly
lossless drop reports e above 1 with no energy gained. Such a drop carries GRAVITY_DOMINATED
(not ok) in ``simulate_drop`` and ``simulate_drops`` alike, its warning says why; the rigid
engine's e keeps the gravity impulse and has no such case."""

from __future__ import annotations

import json
import math
import sys
from typing import Any

import numpy as np
import pytest

import impactlab as il
from impactlab.cli import main
from impactlab.dynamics.drop_gravity import e_lifted_by_gravity
from impactlab.flags import (
    FLAG_ENERGY_GAIN,
    FLAG_GRAVITY_DOMINATED,
    FLAG_LAW_EXTRAPOLATED,
    FLAG_OTHER_END,
    ResultFlag,
    messages,
)

#: the paper's rigid rod, Hertz, frictionless, dropped vertically: lossless
ELASTIC: dict[str, Any] = {"law": "hertz", "mu": 0.0, "angle": math.pi / 2}


@pytest.mark.parametrize(("v", "e"), [(1.41, 1.00135), (0.1, 1.03243), (0.03, 1.13932)])
def test_e_above_one_by_the_removed_impulse_is_flagged(v: float, e: float) -> None:
    d = il.simulate_drop(il.Rod.paper(), velocity=(0.0, -v), **ELASTIC)
    assert d.e == pytest.approx(e, abs=1e-5)  # the number is kept
    assert d.e_raw == pytest.approx(1.0, abs=1e-6)
    assert ResultFlag.GRAVITY_DOMINATED in d.flags and not d.ok
    first = d.warnings[0]
    assert first.startswith(f"gravity-dominated: e = {d.e:.6g} exceeds 1 only through")
    assert "e_raw" in first and "gravity=False" in first
    # the impulse criterion did not hold: its sentence (the rod rests or rocks) is not said
    assert messages(ResultFlag.GRAVITY_DOMINATED)[0] not in d.warnings
    assert d.to_dict()["ok"] is False and d.to_dict()["warnings"][0] == first
    batch = il.simulate_drops(il.Rod.paper(), vy=-v, **ELASTIC)
    assert int(batch.flags[0]) == int(d.flags) and not batch.ok[0]
    assert "gravity-dominated" in batch.messages[0]


def test_without_gravity_e_is_one_and_plain() -> None:
    d = il.simulate_drop(il.Rod.paper(), velocity=(0.0, -0.1), gravity=False, **ELASTIC)
    assert d.e == d.e_raw == pytest.approx(1.0, abs=1e-6)
    assert ResultFlag.GRAVITY_DOMINATED not in d.flags and d.ok


def test_a_lossy_drop_is_unchanged() -> None:
    d = il.simulate_drop(il.Rod.paper(), angle="20 deg", velocity=(0.0, -1.41), mu=0.2)
    assert d.e < 1.0 and d.ok and int(d.flags) & ~FLAG_LAW_EXTRAPOLATED == 0


def test_the_rigid_engine_keeps_the_impulse() -> None:
    for v in (1.41, 0.1, 0.03):
        r = il.simulate(il.Rod.paper(), velocity=(0.0, -v), **ELASTIC)
        assert r.e <= 1.0 and r.ok


def test_both_criteria_keep_the_impulse_sentence() -> None:
    """Gravity-dominated by its impulse too (m g T > 0.1 P_n at 2 cm/s): the usual sentence."""
    d = il.simulate_drop(il.Rod.paper(), velocity=(0.0, -0.02), **ELASTIC)
    assert d.e > 1.2 and ResultFlag.GRAVITY_DOMINATED in d.flags and not d._e_lifted
    assert messages(ResultFlag.GRAVITY_DOMINATED)[0] in d.warnings
    assert not any("exceeds 1 only through" in w for w in d.warnings)


def test_the_rule() -> None:
    rtol = 1e-7
    tol = 10 * rtol + 1e-10
    e = np.array([1.01, 1.01, 1.01, 1.01, 1.0 + 0.5 * tol, 1.02, math.nan, 0.9])
    raw = np.array([1.0, 1.0 + 0.5 * tol, 1.0 + 2 * tol, 1.0, 1.0, 1.0, 1.0, 0.8])
    flags = np.array([0, 0, 0, FLAG_ENERGY_GAIN, 0, FLAG_OTHER_END, 0, 0])
    got = e_lifted_by_gravity(e, raw, flags, rtol)
    assert got.tolist() == [True, True, False, False, False, False, False, False]
    assert bool(e_lifted_by_gravity(1.01, 1.0, FLAG_GRAVITY_DOMINATED, rtol))


def test_the_drop_command_says_it(capsys: pytest.CaptureFixture[str]) -> None:
    old = sys.argv
    sys.argv = ["impactlab", "drop", "--rigid", "--angle", "90 deg", "--vy", "-0.1 m/s",
                "--law", "hertz", "--mu", "0", "--json"]  # fmt: skip
    code = 0
    try:
        main()
    except SystemExit as exc:
        code = int(exc.code or 0)
    finally:
        sys.argv = old
    out = capsys.readouterr()
    assert code == 0, out.err
    data = json.loads(out.out)
    assert data["flags"] & FLAG_GRAVITY_DOMINATED and data["ok"] is False
    assert "warning: gravity-dominated: e = 1.03" in out.err


@pytest.mark.parametrize("vy", [-2.0, -5.0])
def test_a_loose_rtol_still_marks_e_above_one(vy: float) -> None:
    """At rtol 1e-5 the gravity share g T/|v| (9e-4 at 2 m/s, 3e-4 at 5 m/s) lies below the
    energy criterion's 100 rtol but far above e_raw's own error (4e-6)."""
    r = il.simulate_drop(
        il.Rod.paper(), law="hertz", mu=0.0, angle=math.pi / 2, velocity=(0.0, vy), rtol=1e-5
    )
    assert r.e > 1.0 and r.e_raw <= 1.0 + 1e-4
    assert ResultFlag.GRAVITY_DOMINATED in r.flags and not r.ok
