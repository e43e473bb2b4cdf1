"""A batch applies ``simulate``'s rules to each case: a speed finite and > 0, an incidence in
(-90, 90) deg, refused by case index with the rule (not a "does not approach" status with the
wrong sign); gravity=None is refused, not read as no gravity; a slow grazing slide that
chatters under gravity says what helps; and a batch's one-line counts do not call a case
with only the advisory flag a failure."""

from __future__ import annotations

import warnings
from types import SimpleNamespace

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics.batch_fields import batch_counts
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.outcome import status_error
from impactlab.flags import FLAG_ENERGY_GAIN, FLAG_LAW_EXTRAPOLATED


def test_a_batch_refuses_bad_speeds_by_index() -> None:
    with pytest.raises(ValueError, match=r"^speed") as caught:
        il.simulate_batch(il.PAPER_ROD, angle=0.3, speed=[2, -1, 0, np.nan], incidence=0.1, mu=0.2)
    assert str(caught.value).startswith(
        "speed must be finite and > 0 m/s in every case, got speed[1] = -1.0 m/s, speed[2] = "
        "0.0 m/s, speed[3] = nan m/s (3 of 4 cases)"
    )
    with pytest.raises(ValueError, match=r"^speed must be finite and > 0 m/s, got -1\.0 m/s$"):
        il.simulate_batch(il.PAPER_ROD, angle=0.3, speed=-1.0, incidence=0.1, mu=0.2)


@pytest.mark.parametrize(
    ("incidence", "message"),
    [
        (2.0, r"got 114\.592 deg; a bare incidence is radians"),
        ("100 deg", r"got 100 deg$"),
        ([0.1, 30.0], r"got incidence\[1\] = 1718\.87 deg \(1 of 2 cases\)"),
    ],
)
def test_a_batch_refuses_an_incidence_outside_90_deg(incidence, message) -> None:
    with pytest.raises(ValueError, match=r"^incidence must lie in \(-90, 90\) deg from the "):
        il.simulate_batch(il.PAPER_ROD, angle=0.3, speed=2.0, incidence=incidence, mu=0.2)
    with pytest.raises(ValueError, match=message):
        il.simulate_batch(il.PAPER_ROD, angle=0.3, speed=2.0, incidence=incidence, mu=0.2)


def test_a_batch_of_drops_refuses_a_negative_speed() -> None:
    """simulate_drops read speed=-1 as vy = +1 m/s and refused nothing."""
    with pytest.raises(ValueError, match=r"speed\[0\] = -1\.0 m/s \(1 of 2 cases\)"):
        il.simulate_drops(
            il.FlexibleRod.paper(), speed=[-1.0, 2.0], incidence=0.0, angle=0.3, mu=0.2
        )


def test_gravity_none_is_refused() -> None:
    message = r"^gravity must be True \(9\.80665 m/s\^2\), False \(none\) or a value in m/s\^2"
    with pytest.raises(ValueError, match=message):
        il.simulate(il.PAPER_ROD, angle=0.3, velocity=(0.0, -1.0), gravity=None)
    with pytest.raises(ValueError, match=message):
        il.simulate_batch(il.PAPER_ROD, angle=0.3, vy=-1.0, gravity=None)


def test_chattering_under_gravity_says_what_helps() -> None:
    model = il.get_law("ghaednia").build(il.ContactPair(il.PAPER_ROD.material, "aisi-1010"),
                                         il.PAPER_ROD.tip_radius)  # fmt: skip
    text = str(status_error(S.ST_TOO_MANY_EVENTS, model, vn=-1e-4, gravity=9.80665))
    assert text.startswith("too many phase or stick/slip switches (chattering): the contact point")
    assert text.endswith("raise the approach speed, or pass gravity=False")
    assert "gravity" not in str(status_error(S.ST_TOO_MANY_EVENTS, model, vn=-1e-4, gravity=0.0))


def test_a_slow_grazing_slide_names_its_remedies() -> None:
    """The repro: both remedies named work (friction='mindlin' does not, so it is not named)."""
    args = {"angle": 0.3, "mu": 0.3}
    with pytest.raises(ValueError, match="raise the approach speed, or pass gravity=False"):
        il.simulate(il.PAPER_ROD, "copper-ofhc", velocity=(1.0, -1e-4), **args)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert il.simulate(il.PAPER_ROD, "copper-ofhc", velocity=(1.0, -1e-4), gravity=False,
                           **args).e > 0  # fmt: skip
        assert il.simulate(il.PAPER_ROD, "copper-ofhc", velocity=(1.0, -1e-3), **args).e > 0


class _Batch(SimpleNamespace):
    """What ``batch_counts`` reads of a batch: its flags, computed and ok masks, its length."""

    def __len__(self) -> int:
        return len(self.flags)


def _batch(flags: list[int], computed: list[bool]) -> _Batch:
    f, c = np.array(flags), np.array(computed)
    return _Batch(flags=f, computed=c, ok=c & ((f & ~FLAG_LAW_EXTRAPOLATED) == 0))


def test_a_batch_counts_an_advisory_flag_as_marked_not_as_not_ok() -> None:
    assert (
        batch_counts(_batch([FLAG_LAW_EXTRAPOLATED], [True]))
        == "1 case, 1 computed, 1 ok (1 marked: law extrapolated), 0 not ok"
    )
    mixed = _batch([FLAG_LAW_EXTRAPOLATED, FLAG_ENERGY_GAIN, 0, 0], [True, True, True, False])
    assert batch_counts(mixed) == (
        "4 cases, 3 computed, 2 ok (1 marked: law extrapolated), 1 not ok (energy gain: 1)"
    )
    assert batch_counts(_batch([0, 0], [True, True])) == ("2 cases, 2 computed, 2 ok, 0 not ok")
