"""A verdict's repr is one short line: the drop, the first of the ranking (or none), whether it
is consistent with the measurements (p to 2 digits) and its agreements; the reason stays in
``reason``."""

from __future__ import annotations

from impactlab.explain.verdict import Verdict

_REASON = "flexible rod: ranks first by the most values within 2 sigma, ... " * 5


def _named() -> Verdict:
    return Verdict(
        "20 deg", "flexible rod", ("e", "delta_p", "scar_length"), (), _REASON,
        within_2_sigma=1, chi2=129.6117581593463, agreements=1, p_value=6.55751622898518e-28,
        consistent=False, consistency_chi2=129.6117581593463,
        predicted_over=("e", "delta_p", "scar_length"),
    )  # fmt: skip


def test_named_verdict_repr() -> None:
    text = repr(_named())
    assert text == (
        "Verdict(drop '20 deg', first 'flexible rod', inconsistent (p = 6.6e-28), "
        "1 of 3 values within 2 sigma)"
    )
    assert "129.6117" not in text and "ranks first" not in text and len(text) < 200


def test_verdict_repr_without_a_named_row() -> None:
    none = Verdict("45 deg", None, (), (), "no configuration's result is ok: none is named")
    assert repr(none) == "Verdict(drop '45 deg', none named)"
    least = Verdict(
        "45 deg", None, ("e",), ("duration",), _REASON, True, "rigid body", agreements=0,
        p_value=0.25, consistent=True,
    )  # fmt: skip
    assert repr(least) == (
        "Verdict(drop '45 deg', none named: none agrees, least disagreeing 'rigid body', "
        "consistent (p = 0.25), 0 of 2 values within 2 sigma, provisional)"
    )


def test_verdict_fields_and_equality_unchanged() -> None:
    v = _named()
    assert v == _named() and v.reason == _REASON and v.to_dict()["p_value"] == v.p_value
