"""The notes: reasons that differ only in their numbers from drop to drop are one note naming
the drops (a number that differs given as its range), the same reason of several
configurations one note naming them; a drop that gives the rod's inertia runs the rigid rod
alone, with no caveat on it."""

from __future__ import annotations

from pathlib import Path

from impactlab.calibrate.measurements import Measurements
from impactlab.explain import explain
from impactlab.explain.api import INERTIA_NOT_RUN
from impactlab.explain.notes import grouped

CS = "flexible rod + rate-dependent flat (cowper-symonds(D=6500 1/s, q=4))"
CS2 = "flexible rod + rate-dependent flat (cowper-symonds(D=40 1/s, q=5))"


def test_texts_that_differ_only_in_numbers_are_one() -> None:
    lines = [
        ("k = 2.659, E*/S_y = 135.5 (within 5 %); nearest: 'aisi-1010'", "a"),
        ("k = 2.692, E*/S_y = 133.9 (within 5 %); nearest: 'aisi-1010'", "b"),
        ("k = 2.661, E*/S_y = 135.5 (within 5 %); nearest: 'aisi-1010'", "c"),
        ("k = 2.661 and another word", "c"),
    ]
    assert grouped(lines) == [
        ("k = 2.659 to 2.692, E*/S_y = 133.9 to 135.5 (within 5 %); nearest: 'aisi-1010'",
         ["a", "b", "c"]),
        ("k = 2.661 and another word", ["c"]),
    ]  # fmt: skip
    # the numbers of a configuration's name are part of the name: two names stay two
    named = [(f"best: {CS}: over e", "a"), (f"best: {CS2}: over e", "b")]
    assert grouped(named, [CS, CS2]) == [(f"best: {CS}: over e", ["a"]),
                                          (f"best: {CS2}: over e", ["b"])]  # fmt: skip
    assert grouped([("x = -1.5e-3 m", "a"), ("x = 2 m", "b")]) == [("x = -1.5e-3 to 2 m",
                                                                     ["a", "b"])]  # fmt: skip


def test_a_refusal_repeated_per_drop_is_one_note(paper_file: Path) -> None:
    """The tabulated law refuses each drop's rate-raised flat with the drop's own k and
    E*/S_y: one note per rate row, naming the three drops."""
    x = explain(paper_file, law="tabulated")
    rate_notes = [n for n in x.notes if "rate-dependent flat" in n]
    assert len(rate_notes) == 2
    for note in rate_notes:
        assert note.endswith("(drops: 20 deg, 45 deg, 70 deg)")
        assert " to " in note.split("rate factor k = ")[1].split(",")[0]
    s = x.summary.set_index(["drop", "configuration"])["status"]
    assert s.str.contains("rate factor k = ").sum() == 6  # each row keeps its own numbers


def test_an_inertia_column_runs_the_rigid_rod_alone_without_a_caveat() -> None:
    drop = {"label": "i", "angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.5,
            "e_sigma": 0.03, "inertia": "0.0008 kg*m^2"}  # fmt: skip
    x = explain(Measurements.from_records([drop]))
    s = x.summary.set_index("configuration")
    rigid = s.loc["rigid body"]
    assert rigid["ok"] and rigid["status"] == "ok" and rigid["caveat"] == ""
    flexible = s.drop(index="rigid body")
    assert len(flexible) == 3 and (flexible["status"] == INERTIA_NOT_RUN).all()
    assert not flexible["ok"].any()
    assert "'inertia' column" in INERTIA_NOT_RUN and "does not have" in INERTIA_NOT_RUN
    assert not any(o.body_refused for o in x.outcomes.values())
    names = ", ".join(flexible.index)
    assert f"{names}: {INERTIA_NOT_RUN} (drops: i)" in x.notes
    assert not any("refuse" in n for n in x.notes)
    _, rows = x.display_rows()
    assert {r[1]: r[-1] for r in rows}["rigid body"] == "ok"
