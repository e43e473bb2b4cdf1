"""A batch of drops says what a batch of impacts says: the flags of a computed case that is not
ok (one text for both, ``BatchStatus.messages``), a keyword it does not take with the nearest
name or what to use instead, and a drop's history lists its columns in ``dir()`` and names the
nearest one, as an impact's history does."""

from __future__ import annotations

import inspect
import math
from typing import Any

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics.batch_result import BatchResult
from impactlab.dynamics.drop_batch import DropBatchResult
from impactlab.dynamics.drop_history import DROP_HISTORY_COLUMNS, DropHistory
from impactlab.dynamics.history import History
from impactlab.dynamics.kernels.layout import HISTORY_FIELDS
from impactlab.flags import ADVISORY_FLAGS, ResultFlag, messages

ROD = il.Rod.paper()


def _named(flags: int) -> str:
    """The message of a computed case that is not ok with these flags, as a batch words it."""
    bits = [f for f in ResultFlag if f.value and flags & f]
    names = [messages(f)[0].split(":")[0] for f in bits if not f & ADVISORY_FLAGS]
    advisory = [messages(f)[0].split(":")[0] for f in bits if f & ADVISORY_FLAGS]
    more = f"; advisory: {', '.join(advisory)}" if advisory else ""
    return f"computed, not ok (flags {flags}): {', '.join(names)}{more}"


def _words(batch: Any) -> None:
    """Each message of ``batch``: a not-ok computed case names its flags, an ok one says ok."""
    for i, text in enumerate(batch.messages):
        f = int(batch.flags[i])
        if batch.computed[i] and not batch.ok[i]:
            assert f & ~ADVISORY_FLAGS and text == _named(f)
        elif batch.ok[i]:
            assert text == "ok"


def test_a_drop_that_is_not_ok_names_its_flags() -> None:
    drops = il.simulate_drops(ROD, angle="20 deg", vy=[-0.04, -1.41], mu=0.2)
    assert drops.ok.tolist() == [False, True] and drops.computed.all()
    assert int(drops.flags[0]) & ResultFlag.GRAVITY_DOMINATED
    text = drops.messages[0]
    assert text.startswith(f"computed, not ok (flags {int(drops.flags[0])}): ")
    assert messages(ResultFlag.GRAVITY_DOMINATED)[0].split(":")[0] in text
    assert drops.messages[1] == "ok"  # flagged (law extrapolated) but ok
    _words(drops)


def test_impacts_and_drops_word_their_flags_alike() -> None:
    """One text for both: BatchStatus.messages, overridden by neither batch."""
    assert "messages" not in vars(BatchResult) and "messages" not in vars(DropBatchResult)
    b = il.simulate_batch(ROD, mu=0.2, angle=math.radians(5), vy=[-1.41, -0.04])
    d = il.simulate_drops(ROD, mu=0.2, angle=math.radians(20), vy=[-1.41, -0.04])
    assert not b.ok.all() and not d.ok.all()
    _words(b)
    _words(d)
    refused = il.simulate_drops(ROD, mu=[0.2, -1.0], angle=0.35, vy=-1.41)
    assert refused.messages[1].startswith("invalid input: ")  # a failed case keeps its reason


@pytest.mark.parametrize(
    ("keyword", "words"),
    [
        ("history", "a drop batch keeps no history"),
        ("constant_angle", "a drop follows the rod's rotation"),
        ("partial_slip_cells", "compiled cells per end"),
        ("theta", "the rod's angle to the flat is angle="),
        ("angel", "(did you mean 'angle'?)"),
    ],
)
def test_a_keyword_simulate_drops_does_not_take_is_explained(keyword: str, words: str) -> None:
    extra: dict[str, Any] = {"angle": 0.35, keyword: True}
    with pytest.raises(TypeError) as info:
        il.simulate_drops(ROD, mu=0.2, vy=-1.41, **extra)
    text = str(info.value)
    assert text.startswith(f"simulate_drops() got unexpected keyword argument(s) {keyword}")
    assert words in text and "it takes angle, body, flat, friction," in text
    if keyword == "history":
        assert "impactlab.simulate_drop(" in text and "impactlab.simulate(FlexibleRod" in text


def test_simulate_drops_keeps_its_signature_and_docstring() -> None:
    params = inspect.signature(il.simulate_drops).parameters
    assert "stop" in params and "time_limit" in params and "history" not in params
    assert (il.simulate_drops.__doc__ or "").startswith("Many drops of ``body``")


def test_simulate_names_the_nearest_keyword_as_a_batch_does() -> None:
    for body in (ROD, il.FlexibleRod.paper()):
        with pytest.raises(TypeError) as info:
            il.simulate(body, angle=0.3, mue=0.2, velocity=(0.0, -1.41))
        text = str(info.value)
        assert text.startswith("simulate() got unexpected keyword argument(s) mue (did you mean")
        assert "'mu'?); it takes angle, " in text
        assert text.endswith("(rate, stop, time_limit: a FlexibleRod's drop)")


def test_dir_of_a_drops_history_lists_its_columns() -> None:
    h = DropHistory(np.zeros((3, len(DROP_HISTORY_COLUMNS))))
    shown = dir(h)
    assert set(DROP_HISTORY_COLUMNS) <= set(shown)
    assert {"to_dataframe", "tip_x", "normal_force"} <= set(shown) and "fn0" not in shown
    with pytest.raises(AttributeError, match=r"did you mean 'normal_force_0'\?\); columns: t,"):
        _ = h.normal_forc_0
    with pytest.raises(AttributeError, match=r"^'DropHistory' object has no attribute 'zzz'; "):
        _ = h.zzz
    with pytest.raises(KeyError, match=r"did you mean 'penetration_0'\?"):
        _ = h["penetraton_0"]


def test_both_histories_share_the_words() -> None:
    h = History(np.zeros((2, len(HISTORY_FIELDS))))
    assert set(HISTORY_FIELDS) <= set(dir(h))
    with pytest.raises(AttributeError, match=r"^'History' object has no attribute 'normal_forc' "):
        _ = h.normal_forc
