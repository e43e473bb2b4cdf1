"""The library's rate laws (fitted for low-carbon steel) never run on another flat: those rows
say why; a rate law of one's own forms the rate rows, on any flat. A sphere's drop runs the
rigid configuration only."""

from __future__ import annotations

import pytest

from impactlab.calibrate.measurements import Measurements
from impactlab.contact.rate import RateLaw
from impactlab.explain import configurations, explain

AL_DROP = {
    "label": "al", "flat_material": "al-6061-t6", "angle": "20 deg", "vy": -1.41, "mu": 0.2,
    "e": 0.5, "e_sigma": 0.03, "delta_p": "30 um", "delta_p_sigma": "3 um",
}  # fmt: skip
OWN = "cowper-symonds(D=6500 1/s, q=4)"


def _rows(x, drop):
    return x.summary[x.summary["drop"] == drop].set_index("configuration")


def test_an_aluminium_flat_runs_no_library_rate_row_and_says_why() -> None:
    x = explain(Measurements.from_records([AL_DROP]))
    s = _rows(x, "al")
    rate_rows = [n for n in s.index if "rate-dependent" in n]
    assert len(rate_rows) == 2
    for name in rate_rows:
        assert not s.loc[name, "ok"]
        assert s.loc[name, "status"].startswith("not run: the ")
        assert "fitted for low-carbon (mild) steel" in s.loc[name, "status"]
        assert "E = 68.9 GPa" in s.loc[name, "status"]
        assert s.loc[name, "within_2_sigma"] == 0 and s.loc[name, "compared"] == 0
        assert x.result("al", name) is None
    assert any("not run" in n and "(drops: al)" in n for n in x.notes)
    assert s.loc["flexible rod", "ok"] and s.loc["rigid body", "ok"]


def test_the_library_law_by_its_own_constants_does_not_run_on_aluminium() -> None:
    """cowper-symonds(D=40.4 1/s, q=5) is the library's mild-steel law: its row keeps the label
    and is not run on aluminium, as the law by its name."""
    x = explain(Measurements.from_records([AL_DROP]), rate_laws=["cowper-symonds(D=40.4 1/s, q=5)"])
    s = _rows(x, "al")
    name = "flexible rod + rate-dependent flat (cowper-symonds, upper estimate)"
    assert list(s.index) == ["rigid body", "flexible rod", name]
    assert not s.loc[name, "ok"] and x.result("al", name) is None
    assert s.loc[name, "status"].startswith(
        "not run: the cowper-symonds constants are fitted for low-carbon (mild) steel"
    )


def test_a_rate_law_of_ones_own_forms_the_rate_rows() -> None:
    x = explain(Measurements.from_records([AL_DROP]), rate_laws=[OWN])
    s = _rows(x, "al")
    name = "flexible rod + rate-dependent flat (cowper-symonds (D = 6500 1/s, q = 4))"
    assert list(s.index) == ["rigid body", "flexible rod", name]
    assert s.loc[name, "ok"] and s.loc[name, "rate_factor"] > 1.0
    assert x.result("al", name).rate == "cowper-symonds (D = 6500 1/s, q = 4)"
    law = RateLaw.custom("cowper-symonds", D="6500 1/s", q=4)
    assert configurations([law])[2].name == name


def test_rate_laws_are_read_or_refused_by_name() -> None:
    assert len(configurations(None)) == 4 and len(configurations([])) == 2
    assert len(configurations(["none"])) == 2
    with pytest.raises(ValueError, match="rate_laws must be one of"):
        configurations(["cowper"])
    with pytest.raises(ValueError, match="given twice"):
        configurations([OWN, "cowper-symonds (D = 6500 1/s, q = 4)"])
    with pytest.raises(ValueError, match="give 'none' alone"):
        configurations(["none", OWN])


def test_a_sphere_runs_the_rigid_configuration_only() -> None:
    sphere = {"label": "s", "body": "sphere", "radius": "5 mm", "vy": -1.0, "mu": 0.2,
              "e": 0.9, "e_sigma": 0.03}  # fmt: skip
    x = explain(Measurements.from_records([sphere, AL_DROP]))
    s = _rows(x, "s")
    assert s.loc["rigid body", "ok"] and s.loc["rigid body", "compared"] == 1
    for name in s.index[1:]:
        assert s.loc[name, "status"].startswith("not run: the drop is a sphere's")
    assert _rows(x, "al").loc["flexible rod", "ok"]  # the rod beside it still runs


def test_a_drop_without_mu_is_refused() -> None:
    no_mu = {k: v for k, v in AL_DROP.items() if k != "mu"}
    with pytest.raises(
        ValueError, match=r"^drop 1 \(al\) gives no mu: explain runs every drop with its"
    ):
        explain(Measurements.from_records([no_mu]))
