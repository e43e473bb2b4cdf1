"""The hint after an unknown material's name: a stainless steel by ``ss-``/``sst-``/
``stainless-`` is named among the stainless steels, and another grade (a purity, a suffix such
as 304L) is named as such, the nearest grade number of its family first."""

from __future__ import annotations

import pytest

from impactlab.materials import get_material

GRADE = r"another grade or temper: not the same material, its properties differ\)"


def _hint(typed: str) -> str:
    with pytest.raises(ValueError, match=rf"^unknown material '{typed}'") as err:
        get_material(typed)
    return str(err.value).split(";")[0]


@pytest.mark.parametrize("typed", ["ss-316", "sst-316", "stainless-316", "ss316", "ss-316l"])
def test_a_stainless_grade_not_in_the_library_names_the_nearest_stainless(typed: str) -> None:
    """'ss-316' suggested brass-c360; 'sst-316' and 'stainless-316' nothing."""
    assert _hint(typed) == (
        f"unknown material '{typed}' (the library's nearest is 'aisi-304' (AISI 304 stainless "
        "steel, annealed), another grade or temper: not the same material, its properties differ)"
    )


@pytest.mark.parametrize(
    ("typed", "suggested"),
    [
        ("ss-304", "aisi-304"),
        ("sst-304", "aisi-304"),
        ("stainless-304", "aisi-304"),
        ("ss-201", "aisi-201"),
        ("ss-30", "aisi-304"),
        ("ss-3040", "aisi-304"),
    ],
)
def test_a_stainless_grade_in_the_library_is_a_did_you_mean(typed: str, suggested: str) -> None:
    assert _hint(typed) == f"unknown material '{typed}' (did you mean '{suggested}'?)"


@pytest.mark.parametrize(("typed", "nearest"), [("ss-1010", "aisi-304"), ("ss-200", "aisi-201")])
def test_a_stainless_name_never_suggests_another_family(typed: str, nearest: str) -> None:
    """'ss-1010' suggested the low-carbon aisi-1010, 'ss-310' and 'ss-200' brass or 52100."""
    hint = _hint(typed)
    assert f"the library's nearest is '{nearest}' (AISI" in hint and "stainless steel" in hint
    for other in ("ss-310", "ss-52100"):
        assert "'brass-c360'" not in _hint(other) and "'aisi-52100'" not in _hint(other)


@pytest.mark.parametrize(
    ("typed", "nearest"),
    [
        ("aisi-316", "aisi-304"),  # was aisi-201: 316 is nearer 304
        ("aisi-316l", "aisi-304"),
        ("aisi-304l", "aisi-304"),  # the low-carbon 304: was 'did you mean'
        ("aisi-304h", "aisi-304"),
        ("aisi-200", "aisi-201"),  # was aisi-52100
        ("alumina-96", "alumina-99.5"),  # another purity: was 'did you mean'
        ("alumina-99.9", "alumina-99.5"),
        ("aisi-1018", "aisi-1010"),
    ],
)
def test_another_grade_names_the_nearest_grade_of_its_family(typed: str, nearest: str) -> None:
    with pytest.raises(
        ValueError,
        match=rf"^unknown material '{typed}' \(the library's nearest is '{nearest}' "
        rf"\(.*\), {GRADE}",
    ):
        get_material(typed)


@pytest.mark.parametrize(
    ("typed", "suggested"),
    [
        ("aisi-30", "aisi-304"),
        ("aisi-3044", "aisi-304"),
        ("aisi-340", "aisi-304"),
        ("alumina-99", "alumina-99.5"),
        ("alumina-9.95", "alumina-99.5"),
        ("aisi-52100-x", "aisi-52100"),
    ],
)
def test_a_typo_or_a_beginning_keeps_its_did_you_mean(typed: str, suggested: str) -> None:
    assert _hint(typed) == f"unknown material '{typed}' (did you mean '{suggested}'?)"
    assert "did you mean 'al-6061-t6' (aluminium 6061-T6) or 'alumina-99.5'" in _hint("alumin")
