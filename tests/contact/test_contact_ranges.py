"""The laws' ranges (impactlab.contact.ranges): the verified range measured against FE for the
pair's E*/S_y, the stand-in outside the FE cases' span; and the reference registry: every law
has a range with a source and a status, every DOI is well-formed."""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np
import pytest

from impactlab.contact import Law, get_law, law_names
from impactlab.contact import kernels as k
from impactlab.contact.base import ContactModel
from impactlab.contact.range_note import range_note
from impactlab.contact.ranges import (
    RANGES,
    STATUSES,
    LawRange,
    critical_interference,
    delta_ratio,
    extrapolation,
    extrapolation_flags,
    law_extrapolated,
    law_range,
    range_limit,
    range_status,
    smallest_verified,
)
from impactlab.contact.verified_ranges import (
    BEYOND_FE,
    VerifiedCase,
    e_star_over_sy_span,
    verified_cases,
    verified_laws,
    verified_upper,
)
from impactlab.flags import FLAG_LAW_EXTRAPOLATED
from impactlab.materials import AISI_201, AISI_1010, ContactPair, Material
from impactlab.references import DOI_PATTERN, REFERENCES, Reference


def test_every_law_has_a_range_with_a_source() -> None:
    assert set(RANGES) == set(Law)
    for name in law_names():
        r = law_range(name)
        assert r.law == name and r.status in STATUSES
        assert r.source and r.reference_keys and r.delta_ratio_max > 0.0
        assert all(key in REFERENCES for key in r.reference_keys)
        assert r.confirmed == (r.status == "confirmed")
        d = get_law(name).describe()
        assert d["fitted_range"] == r.describe() and d["calibrated_range"] == r.text


def test_no_range_is_claimed_confirmed_without_a_source_read() -> None:
    """What this project could read: no FEM range was found, so none is 'confirmed'; the FEM
    laws carry the labelled stand-in, their smallest verified range over the FE cases (read
    from the verified-ranges data), the analytical laws their first yield."""
    for name in ("ghaednia", "jackson-green", "kogut-komvopoulos"):
        r = law_range(name)
        least = min(c.upper for c in verified_cases(name))
        assert r.status == "provisional" and r.delta_ratio_max == least == smallest_verified(name)
        assert "provisional" in r.text and "not" in r.source
        assert f"delta <= {least:g} delta_c, the smallest verified range" in r.text
        assert r.describe()["delta_ref"].startswith("delta_c")  # the unit of delta_ratio_max
    for name in ("brake", "thornton"):
        assert law_range(name).status == "analytical"
        assert law_range(name).delta_ratio_max == 1.0 and "first yield" in law_range(name).source
    assert law_range("hertz").status == "theory" and law_range("hertz").delta_ratio_max == 1.0


def test_range_validation_and_lookup() -> None:
    with pytest.raises(ValueError, match="unknown contact law 'nope'"):
        law_range("nope")
    with pytest.raises(ValueError, match="status must be one of"):
        LawRange(Law.HERTZ, 1.0, "d", "guessed", "s", ("johnson-1985",))
    with pytest.raises(ValueError, match="delta_ratio_max must be > 0"):
        LawRange(Law.HERTZ, 0.0, "d", "theory", "s", ("johnson-1985",))
    with pytest.raises(ValueError, match="unknown reference key"):
        LawRange(Law.HERTZ, 1.0, "d", "theory", "s", ("nobody-2099",))


def test_critical_interference_per_law(paper_models: dict[str, ContactModel]) -> None:
    """The reference interference is the law's own yield (p[P_DY]); Hertz: JG delta_c."""
    jg = paper_models["ghaednia"].details["delta_c"]
    assert paper_models["hertz"].critical_interference == pytest.approx(jg, rel=1e-14)
    for name, model in paper_models.items():
        if name != "hertz":
            assert model.critical_interference == model.yield_onset[0]
    # vectorised over rows of parameters, the same numbers
    p = np.stack([paper_models["hertz"].params] * 3)
    np.testing.assert_allclose(critical_interference(k.HERTZ, p), jg, rtol=1e-14)


def test_calibrated_max_follows_the_range(paper_models: dict[str, ContactModel]) -> None:
    for model in paper_models.values():
        ratio = range_limit(model.law_id, model.params[: k.NPARAM])
        expected = min(ratio * model.critical_interference, model.max_interference)
        if math.isinf(ratio):  # no fitted range: no calibrated end either
            expected = math.inf
        assert model.calibrated_max_interference == pytest.approx(expected, rel=1e-14)


def test_extrapolation_flag_is_strictly_beyond_the_range(
    paper_models: dict[str, ContactModel],
) -> None:
    """The paper's pair (E*/S_y = 360, a shipped FE case): Ghaednia's law is verified up to
    1 delta_c (its delta_r / delta_max leaves FE's by more than 0.05 at 1.5 delta_c)."""
    m = paper_models["ghaednia"]
    dc = m.critical_interference
    top = range_limit(m.law_id, m.params)
    assert top == pytest.approx(1.0, rel=1e-12)
    d = np.array([0.5 * dc, top * dc * (1 - 1e-12), top * dc * (1 + 1e-12), 300 * dc, np.nan])
    np.testing.assert_array_equal(law_extrapolated(m, d), [False, False, True, True, False])
    assert law_extrapolated(m, 300 * dc) is True and law_extrapolated(m, 0.9 * dc) is False
    assert m.extrapolated(300 * dc) is True
    flags = extrapolation_flags(m.law_id, m.params, d)
    np.testing.assert_array_equal(flags, [0, 0, 4, 4, 0])
    assert delta_ratio(m.law_id, m.params, 300 * dc) == pytest.approx(300.0)
    assert extrapolation(m.law_id, m.params, 300 * dc) == (
        pytest.approx(300.0),
        pytest.approx(1.0, rel=1e-12),
    )
    assert range_status(m.law_id, m.params) == "verified"
    # an unknown law or no parameters: nothing to say
    assert extrapolation_flags(-1, None, 1.0) == 0
    r, lim = extrapolation(-1, None, 1.0)
    assert math.isnan(r) and math.isinf(lim)


@pytest.mark.parametrize("name", ["brake", "thornton"])
def test_analytical_laws_are_verified_too_and_flagged_past_first_yield_outside_the_span(
    name: str, paper_models: dict[str, ContactModel]
) -> None:
    """Brake and Thornton have no fitted range but a verified one: 1-2 delta_c for the paper's
    pair; a pair outside the FE span keeps the stand-in, their first yield (as Hertz's): a
    plastic impact there is not verified."""
    m = paper_models[name]
    dc = m.critical_interference
    assert 1.0 - 1e-12 <= range_limit(m.law_id, m.params) <= 2.5
    assert law_extrapolated(m, 0.5 * m.max_interference)
    assert extrapolation_flags(m.law_id, m.params, 0.5 * dc) == 0
    soft = _soft_pair_model(name)
    assert range_status(soft.law_id, soft.params) == "unverified"
    assert law_extrapolated(soft, 0.5 * soft.max_interference)
    assert not law_extrapolated(soft, 0.5 * soft.critical_interference)
    assert FLAG_LAW_EXTRAPOLATED == 4


def _soft_pair_model(name: str) -> ContactModel:
    """``name`` built for the paper's sphere on a soft flat (S_y 50 MPa: E*/S_y about 2200,
    beyond the FE cases' 28-1731)."""
    flat = Material("soft steel", 200e9, 0.3, 50e6, 30.0)
    return get_law(name).build(ContactPair(AISI_201, flat), 8.8e-3)


@pytest.mark.parametrize("name", ["ghaednia", "jackson-green", "kogut-komvopoulos"])
@pytest.mark.parametrize("sy", [50e6, 20e6, 10e9])
def test_unverified_pair_is_trusted_no_further_than_every_measured_one(
    name: str, sy: float
) -> None:
    """A pair outside the FE cases' E*/S_y span (soft flats above it, a very hard one below):
    the limit is the law's smallest verified range over the FE cases (in delta_c; the law's own
    delta_y for Kogut-Komvopoulos), not Kogut & Etsion's 110 delta_c: 45 delta_c is flagged."""
    flat = Material("flat", 200e9, 0.3, sy, 30.0)
    m = get_law(name).build(ContactPair(flat, flat), 8.8e-3)
    ratio = m.params[k.P_ESTAR] / m.params[k.P_SY]
    lo, hi = e_star_over_sy_span()
    assert not lo <= ratio <= hi
    assert range_status(m.law_id, m.params) == "unverified"
    dc = (np.pi * 1.295 * np.exp(0.736 * 0.3) * sy / (2 * m.E_star)) ** 2 * m.params[k.P_R]
    least = smallest_verified(name)
    assert least <= 1.0
    limit = range_limit(m.law_id, m.params)
    assert limit * m.critical_interference == pytest.approx(least * dc, rel=1e-9)
    assert not law_extrapolated(m, 0.99 * least * dc) and law_extrapolated(m, 1.01 * least * dc)
    assert law_extrapolated(m, 45 * dc)
    assert f"stand-in limit {limit:.3g} " in str(range_note(m.law_id, m.params))


@pytest.mark.parametrize("name", ["hertz", "brake", "thornton"])
def test_unverified_pair_of_an_analytical_law_stops_at_the_lower_of_yield_and_smallest(
    name: str,
) -> None:
    """Hertz, Brake and Thornton outside the span: their first yield, or their smallest
    verified range where that is lower (Brake's delta_y is just above delta_c at nu = 0.4)."""
    for nu in (0.2, 0.3, 0.4):
        flat = Material("soft", 200e9, nu, 50e6, 30.0)
        m = get_law(name).build(ContactPair(AISI_201, flat), 8.8e-3)
        own = smallest_verified(name) * critical_interference(k.HERTZ, m.params)
        expected = min(1.0, own / m.critical_interference)
        assert range_limit(m.law_id, m.params) == pytest.approx(expected, rel=1e-12)
        assert range_limit(m.law_id, m.params) <= 1.0


def test_between_cases_the_smaller_verified_range_holds() -> None:
    """E*/S_y between two shipped cases: the smaller of their verified ranges (conservative)."""
    for law in (n for n in verified_laws() if n not in BEYOND_FE):
        cases = verified_cases(law)
        for a, b in itertools.pairwise(cases):
            mid = 0.5 * (a.e_star_over_sy + b.e_star_over_sy)
            assert verified_upper(law, mid) == min(a.upper, b.upper)
            assert verified_upper(law, a.e_star_over_sy) == a.upper
        lo, hi = e_star_over_sy_span()
        assert math.isnan(verified_upper(law, 0.9 * lo)) and math.isnan(
            verified_upper(law, 1.1 * hi)
        )
    assert math.isnan(verified_upper("tabulated", 200.0))
    assert range_status(k.GHAEDNIA) == "provisional"  # without a pair: the stand-in's status


def test_every_doi_in_the_registry_is_well_formed() -> None:
    for ref in REFERENCES.values():
        if ref.doi:
            assert DOI_PATTERN.match(ref.doi), ref
            assert ref.url == f"https://doi.org/{ref.doi}"
        else:  # a handbook or a data sheet: the web address it was read at, or nothing
            assert ref.url == "" or ref.url.startswith(("https://", "http://")), ref
            assert not ref.confirmed
    for law in Law:  # the laws' sources say what was checked
        for ref in law.references:
            assert ref.note, f"{ref.key}: say what was checked"
    with pytest.raises(ValueError, match="malformed DOI"):
        Reference("x", "y", "doi:10.1/x")
    with pytest.raises(ValueError, match="confirmed without a DOI"):
        Reference("x", "y", confirmed=True)


def test_confirmation_status_of_the_law_sources() -> None:
    """Confirmed: the DOIs read in a copy of the publication (JG 2005, KE 2002) or at the DOI
    address (the paper); the others stay unconfirmed and say so."""
    confirmed = {key for key, r in REFERENCES.items() if r.confirmed}
    assert {"jackson-green-2005", "kogut-etsion-2002", "ghaednia-2016-impact"} <= confirmed
    for key in ("ghaednia-2016-contact", "kogut-komvopoulos-2004", "thornton-1997"):
        assert not REFERENCES[key].confirmed and "not confirmed" in REFERENCES[key].note


def test_range_note_names_the_status_the_span_and_the_limit() -> None:
    """``range_note``: the one line results show (``law_range``) for each kind of status."""
    lo, hi = e_star_over_sy_span()
    soft = _soft_pair_model("ghaednia")  # its smallest verified range over the FE cases
    assert range_note(soft.law_id, soft.params) == (
        f"unverified: E*/S_y = 2198 outside the FE cases' {lo:.0f}-{hi:.0f}; stand-in limit "
        "1 delta_c"
    )
    paper = get_law("ghaednia").build(ContactPair(AISI_201, AISI_1010), 8.8e-3)
    line = range_note(paper.law_id, paper.params)
    assert line is not None and line.startswith("verified against FE up to 1 delta_c")
    brake = _soft_pair_model("brake")  # unverified: its stand-in, first yield
    lo, hi = e_star_over_sy_span("brake")  # its own cases (not PMMA: no Brinell hardness)
    assert range_note(brake.law_id, brake.params) == (  # in Brake's own delta_y (LawRange)
        f"unverified: E*/S_y = 2198 outside the FE cases' {lo:.0f}-{hi:.0f}; stand-in limit "
        "1 delta_y"
    )
    # a verified range in the docs' (Jackson-Green's) delta_c, and in the law's own reference
    # where that differs (Kogut-Komvopoulos' delta_y = 0.985 delta_c)
    kk = get_law("kogut-komvopoulos").build(ContactPair(AISI_201, AISI_1010), 8.8e-3)
    assert range_note(kk.law_id, kk.params).startswith(  # type: ignore[union-attr]
        "verified against FE up to 0.3 delta_c (Jackson-Green's; = 0.305 delta_y, the law's own; "
    )
    assert range_note(-1, paper.params) is None and range_note(paper.law_id, None) is None
    tab = get_law("tabulated").build(ContactPair(AISI_201, AISI_1010), 8.8e-3)
    line = range_note(tab.law_id, tab.params)  # its curves are its range, FE's or a user's
    assert line is not None and line.startswith("tabulated: interpolated from its curves")
    assert "not verified" not in line


def test_a_law_with_other_parameters_than_the_fe_comparisons_is_not_verified() -> None:
    """The verified ranges were measured with each law's default parameters: a model built
    with others (Thornton's limit pressure halved gives e = 0.62 where the default and FE give
    an elastic bounce) is "unverified", its line naming the parameters; a parameter given at
    its default value changes nothing."""
    pair = ContactPair(AISI_201, AISI_1010)
    th = get_law("thornton").build(pair, 8.8e-3, limit_pressure_ratio=0.5)
    assert range_status(th.law_id, th.params) == "unverified"
    assert range_note(th.law_id, th.params) == (
        "unverified: the law parameters limit_pressure_ratio = 0.5 are not the defaults the FE "
        "comparison used; with the defaults it is verified up to 1 delta_c (E*/S_y = 360.3)"
    )
    default = get_law("thornton").build(pair, 8.8e-3)
    assert range_status(default.law_id, default.params) == "verified"
    jg = get_law("jackson-green").build(pair, 8.8e-3, published_switch=0.0, elastic_decay=0.25)
    assert range_status(jg.law_id, jg.params) == "verified"
    jg = get_law("jackson-green").build(pair, 8.8e-3, elastic_decay=0.3)
    assert "elastic_decay = 0.3 are not the defaults" in str(range_note(jg.law_id, jg.params))


def test_a_parameter_given_at_its_computed_default_leaves_the_default_verified() -> None:
    """Brake's hardness given as the value its default computes from the materials builds the
    default's parameters: neither model is taken as non-default (a default model built later
    in the process read "unverified" when the record was keyed by its parameters alone)."""
    pair = ContactPair(AISI_201, AISI_1010)
    default = get_law("brake").build(pair, 8.8e-3)
    hb = 1.0 / (2.0 / AISI_201.brinell_hardness + 2.0 / AISI_1010.brinell_hardness)
    same = get_law("brake").build(pair, 8.8e-3, hardness=hb)
    assert np.array_equal(same.params, default.params, equal_nan=True)
    assert range_status(default.law_id, default.params) == range_status(same.law_id, same.params)
    assert "not the defaults" not in str(range_note(same.law_id, same.params))


def _beyond_fe_params(law: str, case: VerifiedCase, **changed: float) -> np.ndarray:
    """A parameter vector holding ``case``'s inputs beyond FE (``changed``: some other)."""
    p = np.full(k.NPARAM, np.nan)
    for name, value in case.inputs:
        p[BEYOND_FE[law][name]] = changed.get(name, value)
    return p


def test_brakes_range_holds_for_a_cases_own_hardness_and_meyer_index_only() -> None:
    """Brake's law reads the Brinell hardnesses (P0) and the Meyer index, which the FE reference
    does not: a flat of HB 150 at the paper's E*/S_y was "verified up to 2 delta_c" while the
    same measurement gives 1. Its range is a case's own, for that case's inputs only."""
    for case in verified_cases("brake"):
        x = case.e_star_over_sy
        assert verified_upper("brake", x, _beyond_fe_params("brake", case)) == case.upper
        p0 = dict(case.inputs)["P0"]
        assert math.isnan(verified_upper("brake", x, _beyond_fe_params("brake", case, P0=1.2 * p0)))
        n = _beyond_fe_params("brake", case, meyer_index=2.05)
        assert math.isnan(verified_upper("brake", x, n))
        assert math.isnan(verified_upper("brake", x))  # without its parameters: not verified
    a, b = verified_cases("brake")[:2]
    mid = 0.5 * (a.e_star_over_sy + b.e_star_over_sy)
    assert math.isnan(verified_upper("brake", mid, _beyond_fe_params("brake", a)))
    hb150 = dataclasses.replace(AISI_1010, brinell_hardness=150.0, name="AISI 1010, HB 150")
    m = get_law("brake").build(ContactPair(AISI_201, hb150), 8.8e-3)
    assert range_status(m.law_id, m.params) == "unverified"
    assert "brake's P0 is not that of the FE case's pair" in range_note(m.law_id, m.params)
    paper = get_law("brake").build(ContactPair(AISI_201, AISI_1010), 8.8e-3)
    assert range_status(paper.law_id, paper.params) == "verified"


def test_a_beyond_fe_laws_text_holds_at_its_cases_pairs_only() -> None:
    """Brake's description claims no range between its cases' E*/S_y: its verified range is a
    case's own, that case's P0 and Meyer index included; every other pair is held to the
    stand-in. Its rows in ``describe()`` carry those inputs; a law the FE reference fixes
    keeps the smaller of the neighbouring cases' ranges between them."""
    r = law_range("brake")
    assert "between cases the smaller" not in r.text and "outside 81-360" not in r.text
    assert "at these FE cases' pairs only, their P0 and meyer_index included" in r.text
    assert r.text.endswith(
        "any other pair (another E*/S_y, P0 or meyer_index) unverified: delta <= 1 delta_y "
        "(analytical)"
    )
    rows = r.describe()["verified"]
    assert [row["inputs"] for row in rows] == [dict(c.inputs) for c in verified_cases("brake")]
    assert rows[0]["inputs"] == {"P0": 1017440000.0, "meyer_index": 2.2}
    g = law_range("ghaednia")
    assert "(between cases the smaller); E*/S_y outside 28-1731 unverified" in g.text
    assert all("inputs" not in row for row in g.describe()["verified"])


def test_brakes_unverified_line_names_only_the_inputs_that_differ() -> None:
    """At a case's E*/S_y the line names the inputs that are not the case's (P0 alone for
    another hardness, meyer_index alone for another index, both for both); between the cases'
    E*/S_y it says that the pair's E*/S_y is none of theirs."""
    hb150 = dataclasses.replace(AISI_1010, brinell_hardness=150.0, name="AISI 1010, HB 150")
    n23 = dataclasses.replace(AISI_1010, meyer_index=2.3, name="AISI 1010, n 2.3")
    both = dataclasses.replace(hb150, meyer_index=2.3, name="AISI 1010, HB 150, n 2.3")
    law = get_law("brake")
    lines = []
    for flat in (hb150, n23, both):
        m = law.build(ContactPair(AISI_201, flat), 8.8e-3)
        lines.append(str(range_note(m.law_id, m.params)))
    assert lines[0] == (
        "unverified: brake's P0 is not that of the FE case's pair at E*/S_y = 360.3 (the FE "
        "reference does not use it); stand-in limit 1 delta_y"
    )
    assert lines[1].startswith("unverified: brake's meyer_index is not that of the FE case's")
    assert lines[2].startswith("unverified: brake's P0 and meyer_index are not those of the FE")
    soft = dataclasses.replace(AISI_1010, yield_strength=1.3 * AISI_1010.yield_strength, name="s")
    m = law.build(ContactPair(AISI_201, soft), 8.8e-3)
    assert range_status(m.law_id, m.params) == "unverified"
    assert str(range_note(m.law_id, m.params)).startswith(
        "unverified: E*/S_y = 277.2 is not that of an FE case (81, 207, 360); brake is verified "
        "for those cases' own pairs only, their P0 and meyer_index included; stand-in limit"
    )
