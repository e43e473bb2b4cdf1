"""One-line errors of the verification and reproduction helpers: the parameter, its value and
what is allowed, in the parameter's own units."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab import verification as V
from impactlab.paper import reproduce


@pytest.mark.parametrize("bad", [None, 3, 2.5, b"out"])
def test_reproduce_refuses_a_folder_that_is_no_path(bad, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(
        TypeError, match=r"^out_dir must be a path \(str or os.PathLike\), got "
    ) as e:
        reproduce(bad)
    assert "\n" not in str(e.value) and repr(bad) in str(e.value)
    assert list(tmp_path.iterdir()) == []  # nothing written


def test_reproduce_refuses_an_empty_folder_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ValueError, match=r"^out_dir must be a path, got an empty string$"):
        reproduce("")


@settings(deadline=None, max_examples=40)
@given(
    st.one_of(
        st.floats(max_value=0.0, allow_nan=False),
        st.floats(min_value=90.0, allow_nan=False),
        st.just(math.nan),
    )
)
def test_critical_friction_angles_outside_0_90_deg_are_refused_in_degrees(angle):
    with pytest.raises(
        ValueError, match=r"^angles_deg: every angle must lie in \(0, 90\) deg"
    ) as e:
        V.verify_critical_friction(angles_deg=(45.0, angle), iterations=4)
    msg = str(e.value)
    assert "radians" not in msg and "\n" not in msg
    assert msg.split(", got ")[1] == f"{angle:g} deg"  # only the bad one, in degrees


def test_critical_friction_refuses_no_angle_and_words():
    with pytest.raises(ValueError, match=r"^angles_deg: give one or more angles in \(0, 90\) deg"):
        V.verify_critical_friction(angles_deg=())
    with pytest.raises(ValueError, match=r"^angles_deg must be numbers in degrees"):
        V.verify_critical_friction(angles_deg=("ten",))


def test_critical_friction_keeps_angles_inside():
    t = V.verify_critical_friction(angles_deg=(45,), iterations=10)
    assert [r["angle"] for r in t.records] == [45.0]


@pytest.mark.parametrize("flat", ["al-6061-t6", "AISI-1010", "", "polymer"])
def test_hertz_refuses_an_unknown_flat_naming_the_allowed(flat):
    with pytest.raises(ValueError, match=r"^flat: ") as e:
        V.verify_hertz(cases=((0.01, 1.0, flat),))
    msg = str(e.value)
    assert msg.startswith(f"flat: {flat!r} in case ") and "\n" not in msg
    assert msg.endswith("allowed: 'aisi-1010', 'soft'")


def test_hertz_keeps_its_two_flats():
    t = V.verify_hertz(cases=((0.01, 1.0, "aisi-1010"), (0.005, 0.7, "soft")))
    assert t.passed and [r["flat"] for r in t.records][1] == "soft polymer"
