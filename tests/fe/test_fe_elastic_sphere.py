"""An elastic sphere cannot yield in the FE, so delta_c is the pair's E* with the flat's S_y and
nu also where the sphere material would yield first (an elastic copper sphere on AISI 1010:
0.772 um; before, the copper's S_y gave 0.020 um, so ``delta_max_over_delta_c`` was 38 times
too large, a ``BeyondCheckedWarning`` fired from 26 of the flat's delta_c on, and the mesh and
loading were scaled to the wrong delta_c). An elastic-plastic copper sphere keeps the copper's.
The shipped cases, whose flats yield first, keep their delta_c. No CalculiX run."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

from impactlab import fe
from impactlab.contact._common import jg_critical
from impactlab.fe import run as fe_run
from impactlab.fe.curves import HARDENED_DIR, ReferenceCase, load_case, load_cases
from impactlab.fe.problem import make_problem
from impactlab.fe.run import BeyondCheckedWarning
from impactlab.materials import AISI_1010, COPPER_OFHC, ContactPair

R = 8.8e-3
PAGE = Path(__file__).resolve().parents[2] / "docs" / "fe.md"


def test_an_elastic_spheres_delta_c_is_the_flats_first_yield() -> None:
    p = make_problem(AISI_1010, COPPER_OFHC, radius=R, delta_max=5e-6, sphere="elastic")
    pair = ContactPair(COPPER_OFHC, AISI_1010)
    assert pair.yield_strength == COPPER_OFHC.yield_strength  # the copper yields first
    flat_dc, _ = jg_critical(pair.E_star, R, AISI_1010.yield_strength, AISI_1010.nu)
    assert p.pair.E_star == pair.E_star
    assert p.pair.yield_strength == AISI_1010.yield_strength and p.pair.nu == AISI_1010.nu
    assert p.delta_c == pytest.approx(flat_dc, rel=1e-12)
    assert p.delta_c == pytest.approx(0.7724e-6, rel=1e-4)
    assert p.delta_max / p.delta_c == pytest.approx(6.47, rel=1e-3)  # before: 246
    plastic = make_problem(AISI_1010, COPPER_OFHC, radius=R, delta_max=5e-6)
    assert plastic.delta_c == pytest.approx(0.02029e-6, rel=1e-3)  # the copper can yield
    text = " ".join(PAGE.read_text().split())
    assert "an elastic copper sphere on AISI 1010 at R = 8.8 mm: 0.772 um" in text
    assert "copper's $S_y$ would give 0.020 um" in text


def test_no_beyond_checked_warning_within_the_flats_checked_range(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    class NoCcxError(Exception):
        pass

    def stop() -> str:
        raise NoCcxError

    monkeypatch.setattr(fe_run, "find_ccx", stop)
    with warnings.catch_warnings():
        warnings.simplefilter("error", BeyondCheckedWarning)
        with pytest.raises(NoCcxError):  # 100 of the flat's delta_c: before, 3800 "copper" delta_c
            fe.indent(AISI_1010, COPPER_OFHC, radius=R, delta_max=77e-6, sphere="elastic")


@pytest.mark.parametrize(
    "case",
    [*load_cases(), load_case("paper-aisi201-on-aisi1010-hardening", HARDENED_DIR)],
    ids=lambda c: c.name,
)
def test_the_shipped_cases_keep_their_delta_c(case: ReferenceCase) -> None:
    for run in case.runs:
        p = make_problem(
            case.flat, case.sphere_material, radius=case.radius, delta_max=run.delta_max,
            sphere=case.sphere, mu=case.mu, mesh_level=case.mesh_level,
        )  # fmt: skip
        assert p.delta_c == case.delta_c
