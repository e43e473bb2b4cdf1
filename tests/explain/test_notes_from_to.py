"""Notes whose differing numbers stand in a "from A to B" phrase (a mode caveat per drop) stay
apart instead of reading as a chain of values; other differing numbers still merge as ranges."""

from __future__ import annotations

from impactlab.explain.notes import grouped

HEAD = "not converged in modes: with twice the modes, (32, 56) for (16, 28),"
A = f"{HEAD} e moves from 0.3518 to 0.3254 (1.32 sigma), more than 0.5 sigma"
B = f"{HEAD} e moves from 0.3611 to 0.3302 (1.55 sigma), more than 0.5 sigma"


def test_two_mode_caveats_stay_apart() -> None:
    assert grouped([(A, "a"), (B, "b")]) == [(A, ["a"]), (B, ["b"])]
    assert grouped([(A, "a"), (A, "b"), (B, "c")]) == [(A, ["a", "b"]), (B, ["c"])]
    # one number in the phrase differing is a chain too: "from 0.3518 to 0.3611 to 0.3254"
    c = A.replace("0.3518", "0.3611")
    assert grouped([(A, "a"), (c, "b")]) == [(A, ["a"]), (c, ["b"])]
    # a number outside such a phrase still merges as a range
    d = A.replace("(1.32 sigma)", "(1.4 sigma)")
    assert grouped([(A, "a"), (d, "b")]) == [(A.replace("1.32", "1.32 to 1.4"), ["a", "b"])]
    counts = [(f"{HEAD.replace('16', n)} ok", w) for n, w in (("16", "a"), ("12", "b"))]
    assert grouped(counts)[0][1] == ["a", "b"]


def test_to_inside_a_word_is_no_phrase() -> None:
    lines = [("tolerance 2 mm, photo 3", "a"), ("tolerance 4 mm, photo 3", "b")]
    assert grouped(lines) == [("tolerance 2 to 4 mm, photo 3", ["a", "b"])]
