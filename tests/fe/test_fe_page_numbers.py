"""Numbers of docs/fe.md that the code makes: the elements across the contact radius at each
delta_max (17 at level 1 only up to delta_c, more past it), and the perfectly plastic paper's
run at 1.5 delta_c, whose delta_r the shipped data leave unresolved (nan), not 0."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from impactlab.fe.curves import HARDENED_DIR, load_case
from impactlab.fe.problem import contact_elements, make_problem
from impactlab.materials import AISI_201, AISI_1010

PAGE = Path(__file__).resolve().parents[2] / "docs" / "fe.md"


def _text() -> str:
    return " ".join(PAGE.read_text().split())


@pytest.mark.parametrize("radius", [1e-3, 8.8e-3, 50e-3])
def test_the_elements_across_the_contact_radius(radius: float) -> None:
    dc = make_problem(AISI_1010, AISI_201, radius=radius, delta_max=1e-9).delta_c
    counts = {}
    for m in (0.3, 1.0, 3.0, 10.0, 100.0, 1000.0):
        problem = make_problem(AISI_1010, AISI_201, radius=radius, delta_max=m * dc)
        counts[m] = round(contact_elements(problem.mesh_spec(), problem.delta_max), 1)
    assert counts[0.3] == counts[1.0] == 17.0
    past = [counts[m] for m in (3.0, 10.0, 100.0, 1000.0)]
    assert past == [21.7, 27.2, 38.2, 49.6]
    text = _text()
    assert "17.0 at level 1 for every $\\delta_{max} \\le \\delta_c$" in text
    assert "(21.7, 27.2, 38.2 and 49.6 at 3, 10, 100 and 1000 $\\delta_c$)" in text
    assert "about 17 at level 1 for every" not in text


def test_the_perfectly_plastic_run_at_1_5_delta_c_is_unresolved() -> None:
    plain = load_case("paper-aisi201-on-aisi1010")
    hardened = load_case("paper-aisi201-on-aisi1010-hardening", HARDENED_DIR)

    def at(case: object, ratio: float) -> float:
        (run,) = [r for r in case.runs if math.isclose(r.delta_max / case.delta_c, ratio)]  # type: ignore[attr-defined]
        return float(run.residual_depth / run.delta_max)

    assert math.isnan(at(plain, 1.5))
    assert round(at(hardened, 1.5), 3) == 0.020
    text = _text()
    assert re.search(r"is 0\.020, where the perfectly plastic run's is unresolved \(n/a", text)
    assert "0.020 against 0" not in text


def test_the_unloading_bracket_is_the_shipped_datas_largest() -> None:
    """The unloading increments bracket delta_r by up to 21.2 % of delta_max in the shipped
    data (the page said 20 %): the last increment of ``unloading_path``, 0.212 delta_max to 0."""
    import numpy as np

    from impactlab.fe.curves import load_cases
    from impactlab.fe.problem import unloading_path

    widest = 0.0
    for case in [*load_cases(), load_case("paper-aisi201-on-aisi1010-hardening", HARDENED_DIR)]:
        for run in case.runs:
            if not run.converged or math.isnan(run.residual_depth):
                continue
            f = np.asarray(run.unloading_force)
            k = int(np.argmin(f > 1e-6 * np.max(np.abs(f))))
            d = np.asarray(run.unloading_delta)
            widest = max(widest, float(d[k - 1] - d[k]) / run.delta_max)
    path = np.asarray(unloading_path().path)
    last = float(path[-2, 1] - path[-1, 1])  # delta / delta_max of the last increment
    assert round(widest, 3) == round(last, 3) == round(1.0 - 1000.0 ** (-1 / 29), 3) == 0.212
    text = _text()
    assert "by up to 21.2 % of $\\delta_{max}$" in text and "by up to 20 %" not in text
