"""A sliding length no profilometer resolves is refused, as a dent depth is; a sub-micrometre
one warns (below about 1 um, T no longer depends on it)."""

from __future__ import annotations

import pytest

import impactlab as il
from impactlab import ImplausibleInputWarning

KW = {"angle": "20 deg", "v_i": "-1.41 m/s", "mu": 0.2, "delta_p": "22 um", "e": 0.5}


@pytest.mark.parametrize("ls", [1e-310, 1e-12, "1 pm", "-0.5 nm"])
def test_an_unresolvable_sliding_length_is_refused(ls) -> None:
    with pytest.raises(ValueError, match=r"sliding_length = .* is below 1 nm, finer than any"):
        il.invert(**KW, sliding_length=ls)


def test_a_sub_micrometre_sliding_length_warns() -> None:
    with pytest.warns(ImplausibleInputWarning, match="sliding_length = 50 nm is shorter"):
        il.invert(**KW, sliding_length="50 nm")


def test_the_papers_sliding_length_is_accepted_without_a_word(recwarn) -> None:
    r = il.invert(**KW, sliding_length="1400 um")
    assert r.duration > 0.0
    assert not [w for w in recwarn if issubclass(w.category, ImplausibleInputWarning)]
