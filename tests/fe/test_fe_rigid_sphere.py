"""A rigid sphere's delta_c is the flat's against a rigid sphere, whatever sphere material is
given (the material is not used at all); ``impactlab fe indent`` says so in the line above its
tables and records ``sphere_material_used: false`` in its JSON ``case``, and docs/fe.md says
so (before, the page called it "the pair's", 0.436 um for the paper's pair where the runs used
0.109 um, and the CLI showed the sphere's material as if used). No CalculiX run."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab import fe
from impactlab.contact import get_law
from impactlab.fe.problem import make_problem
from impactlab.materials import AISI_201, AISI_1010, ContactPair, Material

CliMain = Callable[..., tuple[int, str, str]]
R = 8.8e-3
PAGE = Path(__file__).resolve().parents[2] / "docs" / "fe.md"


def test_a_rigid_spheres_delta_c_is_the_flats_against_a_rigid_sphere() -> None:
    soft = Material("soft ball", 70e9, 0.33, 100e6)
    rigid = [
        make_problem(AISI_1010, m, radius=R, delta_max=1e-6, sphere="rigid").delta_c
        for m in (AISI_201, AISI_1010, soft)
    ]
    assert rigid[0] == rigid[1] == rigid[2]
    assert rigid[0] == pytest.approx(0.10906e-6, rel=1e-4)
    own = get_law("hertz").build(ContactPair(AISI_201, AISI_1010), radius=R)
    assert own.critical_interference == pytest.approx(0.436e-6, rel=1e-3)  # the pair's: not used
    text = " ".join(PAGE.read_text().split())
    assert "with a rigid sphere, the flat's against a rigid sphere" in text
    assert "0.109 um for AISI 1010 at R = 8.8 mm" in text


def _run() -> fe.IndentationResult:
    d = np.array([0.0, 0.5e-6, 1e-6])
    return fe.IndentationResult(
        1e-6, d, 10.0 * d / 1e-6, np.array([0.0, 60e-6, 97.8e-6]), d[::-1], 10.0 * d[::-1],
        7.4e-8, np.array([0.0, 1e-4]), np.array([-7.4e-8, 3.1e-9]), 0.10906e-6,
        True, 0.0, "", 20, 0, 60, 53.0, 2128, 1e-7, {},
    )  # fmt: skip


@pytest.mark.parametrize("sphere", ["rigid", "elastic"])
def test_the_command_says_whether_the_sphere_material_is_used(
    cli_main: CliMain, monkeypatch: pytest.MonkeyPatch, sphere: str
) -> None:
    def indent(flat: Any, body: Any, **kwargs: Any) -> list[fe.IndentationResult]:
        return [_run()]

    monkeypatch.setattr(fe, "indent", indent)
    monkeypatch.setattr(fe, "find_ccx", lambda: "ccx")
    code, out, err = cli_main("fe", "indent", "--max", "1 um", "--sphere", sphere)
    assert code == 0, err
    head = " ".join(out.split())  # the console wraps the line
    if sphere == "rigid":
        assert head.startswith(
            f"rigid sphere (R = 8.8 mm; its material {AISI_201.name} not used: delta_c is the "
            f"flat's against a rigid sphere) on {AISI_1010.name}, mu = 0"
        )
    else:
        assert head.startswith(f"{AISI_201.name} sphere (elastic, R = 8.8 mm) on ")
    code, out, err = cli_main("fe", "indent", "--max", "1 um", "--sphere", sphere, "--json")
    assert code == 0, err
    case = json.loads(out)["case"]
    assert case["sphere_material_used"] is (sphere != "rigid")
    assert case["sphere_material"]["name"] == AISI_201.name  # recorded as given
