"""A batch's repr and notebook summary say why its cases are not ok (the cases with each flag
that makes a case not ok, as a sweep's summary does), and keep each output's unit when no case
is ok."""

from __future__ import annotations

import re
from types import SimpleNamespace

import numpy as np

import impactlab as il
from impactlab.dynamics.batch_fields import batch_counts
from impactlab.flags import ResultFlag

_BRITTLE, _GAIN = int(ResultFlag.BRITTLE), int(ResultFlag.ENERGY_GAIN)
_EXTRAPOLATED = int(ResultFlag.LAW_EXTRAPOLATED)


class _Batch(SimpleNamespace):
    """What ``batch_counts`` reads of a batch: its flags, computed and ok masks, its length."""

    def __len__(self) -> int:
        return len(self.flags)


def _counts(flags: list[int], computed: list[bool]) -> str:
    f, c = np.array(flags), np.array(computed)
    return batch_counts(_Batch(flags=f, computed=c, ok=c & ((f & ~_EXTRAPOLATED) == 0)))


def test_counts_name_each_reason_of_the_not_ok_cases() -> None:
    flags = [_BRITTLE | _EXTRAPOLATED, _BRITTLE, _BRITTLE | _GAIN, _EXTRAPOLATED, _GAIN]
    assert _counts(flags, [True, True, True, True, False]) == (
        "5 cases, 4 computed, 1 ok (1 marked: law extrapolated), "
        "3 not ok (energy gain: 1, brittle: 3)"
    )
    assert _counts([0, _EXTRAPOLATED], [True, True]) == (
        "2 cases, 2 computed, 2 ok (1 marked: law extrapolated), 0 not ok"
    )


def test_batch_repr_and_html_say_why_and_keep_units_without_ok_cases() -> None:
    sphere = il.Sphere(radius=3e-3, material=il.get_material("aisi-52100"))
    glass = il.get_material("soda-lime-glass")
    b = il.simulate_batch(sphere, glass, law="hertz", vy=-np.array([20.0, 30.0]))
    assert "2 computed, 0 ok, 2 not ok (brittle: 2)" in repr(b)
    html = b._repr_html_()
    assert "<p>2 cases, 2 computed, 0 ok, 2 not ok (brittle: 2); " in html
    cells = re.findall(r"<tr><td>(\w+)</td><td>-</td><td>-</td><td>-</td><td>(.*?)</td>", html)
    assert dict(cells) == {
        "e": "", "delta_p": "um", "sliding_length": "um", "duration": "ms",
        "mean_force": "N", "max_force": "N",
    }  # fmt: skip


def test_drop_batch_html_keeps_units_without_ok_cases() -> None:
    drops = il.simulate_drops(il.Rod.paper(), angle=0.35, vy=[-0.001], time_limit=0.01)
    assert "0 ok, 0 not ok" in repr(drops)
    html = drops._repr_html_()
    assert "<td>-</td><td>ms</td>" in html and "<td>-</td><td>um</td>" in html
