"""The closing sentences of "Can physics explain the experiment?" follow the numbers: how the
rate-dependent flat changes the dent (no effect, a large effect, angle by angle), the pile-up
cases, the contacts of the ringing rod, and a section that explains nothing."""

from __future__ import annotations

import pytest
from physics_wording_table import (
    E_COLUMN,
    FLEX,
    LOWER,
    RATE,
    RIGID,
    SCAR_COLUMN,
)
from physics_wording_table import (
    bullet as _bullet,
)
from physics_wording_table import (
    section_text as _text,
)
from physics_wording_table import (
    table_of as _table,
)

from impactlab.paper.physics_report import LARGE_EFFECT

RIGID_DENTS = {20: 62.0513, 45: 111.0656, 70: 225.5506}


def _closing_with_dents(dents: dict[int, float]) -> str:
    """The conclusion with the flexible rod's dents on the rate-dependent flat set (with
    either estimate of the rate constants: the effect is then one)."""
    rows = (RATE, LOWER)
    return _text(_table({(r, a, "delta_p [um]"): d for a, d in dents.items() for r in rows}))[3]


def test_no_change_of_the_dent_is_no_effect() -> None:
    """The dent of the flexible rod on the rate-dependent flat equal to the rigid rod's: no
    effect on the dent (it said "real effects ... 1 / 1 / 1 times")."""
    closing = _closing_with_dents(RIGID_DENTS)
    assert closing.startswith(
        "Rod flexibility and rate sensitivity leave the dent depth within 10 % of the rigid rod's "
        "at every angle (the rigid rod's dent is 1 / 1 / 1 times the flexible rod's on the "
        "rate-dependent flat with the upper estimate, 1 / 1 / 1 with the lower): without damping "
        "(zeta = 0 in every row), they do not explain the dent depth, e,"
    )
    assert "real" not in closing and "large" not in closing
    within = _closing_with_dents({a: d / 1.1 for a, d in RIGID_DENTS.items()})  # the tolerance
    assert "leave the dent depth within 10 % of the rigid rod's at every angle (" in within


def test_a_large_effect_the_other_way_is_large_and_deeper() -> None:
    """Dents three times the rigid rod's: a large effect that deepens the dent (it said only
    "real effects"), judged on the size of the ratio's logarithm."""
    closing = _closing_with_dents({20: 200.0, 45: 300.0, 70: 600.0})
    assert closing.startswith(
        "Rod flexibility and rate sensitivity are real and large effects that make the dent "
        "deeper at every angle (the rigid rod's dent is 0.31 / 0.37 / 0.376 times the flexible "
        "rod's"
    )
    edge = _closing_with_dents({a: d * LARGE_EFFECT for a, d in RIGID_DENTS.items()})
    assert "are real and large effects that make the dent deeper at every angle (" in edge
    small = _closing_with_dents({a: d * 1.2 for a, d in RIGID_DENTS.items()})
    assert "are real effects that make the dent deeper at every angle (" in small


def test_a_mixed_effect_is_said_angle_by_angle() -> None:
    closing = _closing_with_dents({20: 62.0513 / 1.2, 45: 111.0656, 70: 2.0 * 225.5506})
    assert closing.startswith(
        "Rod flexibility and rate sensitivity make the dent shallower at 20 deg and much deeper "
        "at 70 deg, and leave it within 10 % of the rigid rod's at 45 deg (the rigid rod's dent "
        "is 1.2 / 1 / 0.5 times"
    )
    both_ways = _closing_with_dents({20: 10.0, 45: 40.385, 70: 600.0})
    assert both_ways.startswith(
        "Rod flexibility and rate sensitivity make the dent much shallower at 20 and 45 deg and "
        "much deeper at 70 deg (the rigid rod's"
    )


def test_a_pile_up_case_explained_moves_and_needs_no_pile_up() -> None:
    """e and the scar of the 70 deg drop within their tolerances: the bullet is explained and
    no longer ends "the paper points at a pile-up that no contact law models"."""
    changes = {(FLEX, 70, E_COLUMN): 0.06, (FLEX, 70, SCAR_COLUMN): 205.0}
    _, explained, missed, _ = _text(_table(changes))
    pile_up = _bullet(explained, "The 70 deg case: ")
    assert not [b for b in missed if b.startswith("The 70 deg case")]
    assert pile_up.endswith(
        "and its e 0.06 against the measured 0.05; flexibility and rate dependence explain both "
        "(e 0.06, within 0.03; the scar 1.02 times the measured one, within 10 %) with no pile-up."
    )
    assert "points at" not in pile_up


@pytest.mark.parametrize(
    ("changes", "said"),
    [
        (
            {(RATE, 70, E_COLUMN): 0.07},
            "explain e there (0.07, within 0.03) but not the scar, for which the paper points at "
            "a pile-up that no contact law models.",
        ),
        (
            {(FLEX, 70, SCAR_COLUMN): 205.0},
            "explain the scar there (1.02 times the measured one, within 10 %) but not e, for "
            "which the paper points at a pile-up that no contact law models.",
        ),
    ],
)
def test_a_pile_up_case_half_explained_says_which_half(
    changes: dict[tuple[str, int, str], float], said: str
) -> None:
    _, explained, missed, _ = _text(_table(changes))
    assert _bullet(missed, "The 70 deg case: ").endswith(f"flexibility and rate dependence {said}")
    assert not [b for b in explained if b.startswith("The 70 deg case")]


def test_a_flexible_rod_that_touches_once_does_not_ring() -> None:
    """One contact at every angle: the bullet says so and moves to what is not explained (it
    said "The flexible rod rings: 1 / 1 / 1 contacts ... instead of one contact", explained)."""
    _, explained, missed, _ = _text(_table({(FLEX, a, "contacts"): 1 for a in (20, 45, 70)}))
    once = _bullet(missed, "The flexible rod ")
    assert once.startswith(
        "The flexible rod does not touch the flat again: 1 / 1 / 1 contacts over 0.95 / 0.976 / "
        "0.899 ms against the rigid rod's one contact of 0.122 / 0.142 / 0.184 ms; the largest "
        "force falls"
    )
    assert not [b for b in explained if b.startswith("The flexible rod")]
    assert "rings" not in " ".join([*explained, *missed])


def test_the_contacts_bullet_follows_the_counts_and_forces() -> None:
    changes: dict[tuple[str, int, str], float] = {
        (FLEX, 70, "contacts"): 1,
        (RIGID, 70, "contacts"): 2,
    }
    changes |= {(FLEX, a, "F_max [N]"): 20000.0 for a in (20, 45, 70)}
    _, explained, _, _ = _text(_table(changes))
    rings = _bullet(explained, "The flexible rod ")
    assert rings.startswith(
        "The flexible rod rings and touches the flat again at 20 and 45 deg (once at 70 deg): "
        "4 / 4 / 1 contacts over 0.95 / 0.976 / 0.899 ms instead of the rigid rod's 1 / 1 / 2 "
        "contacts over 0.122 / 0.142 / 0.184 ms; the largest force rises from 3809 / 7486 / "
        "16593 N to 20000 / 20000 / 20000 N."
    )


def test_nothing_explained_is_said_so() -> None:
    """One contact and every dent off: nothing is listed as explained, and the section says so
    rather than showing an empty list."""
    changes: dict[tuple[str, int, str], float] = {(FLEX, a, "contacts"): 1 for a in (20, 45, 70)}
    changes |= {(c, a, "delta_p [um]"): 3.0 * 105.0 for c in (FLEX, RATE) for a in (20, 45, 70)}
    intro, explained, missed, _ = _text(_table(changes))
    assert not explained and intro.endswith(
        "where it touches the flat again): nothing at any angle."
    )
    assert len(missed) == 6


def test_a_missing_number_is_not_the_nearest() -> None:
    """A drop of the rate-dependent flat without a dent (NaN): the flexible rod's dent on the
    plain flat is the nearest one there, and the conclusion has nothing to compare there."""
    table = _table({(RATE, 70, "delta_p [um]"): float("nan"), (FLEX, 70, "delta_p [um]"): 106.0})
    _, explained, _, closing = _text(table)
    assert "explain the dent depth at 20 and 70 deg (within 10 %) (at 20 deg only" in _bullet(
        explained, "Dent depths:"
    )
    assert closing.startswith(
        "Rod flexibility and rate sensitivity make the dent much shallower at 20 and 45 deg, and "
        "have no dent to compare at 70 deg with the upper estimate of the rate constants, and "
        "make the dent much shallower at 20 and 45 deg and shallower at 70 deg with the lower "
        "(the rigid rod's dent is 2.71 / 2.75 / nan times"
    )
