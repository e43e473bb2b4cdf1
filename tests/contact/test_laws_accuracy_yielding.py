"""``impactlab laws NAME --accuracy`` for a law of one's own whose curves are of a yielding
sphere: the shipped FE cases (all of a yielding flat) are not its pair, and the message names
the yielding body as the reason where their E*/S_y and nu are the law's."""

from __future__ import annotations

import dataclasses

from typer.testing import CliRunner

from impactlab.cli import app
from impactlab.contact import register_law, unregister_law
from impactlab.contact.indentation_data import shipped_curves


def _accuracy(name: str, **changes: object) -> tuple[int, str]:
    flat = next(c for c in shipped_curves() if c.name == "aisi201-on-al6061t6")
    register_law(name, curves=dataclasses.replace(flat, name=name, **changes))
    try:
        res = CliRunner().invoke(app, ["laws", name, "--accuracy"])
    finally:
        unregister_law(name)
    return res.exit_code, " ".join(res.output.split())


def test_a_yielding_sphere_s_curves_are_told_the_body_differs() -> None:
    code, out = _accuracy("al-sphere", yielding="sphere")
    assert code == 2
    assert (
        "law 'al-sphere' holds for its own pair only (E*/S_y = 207.2, nu = 0.33, a yielding "
        "sphere): the shipped FE case(s) of that E*/S_y and nu ('aisi201-on-al6061t6') are of "
        "a yielding flat, and curves differ once the other body yields" in out
    )
    assert "none of the shipped FE cases has that pair" not in out


def test_another_ratio_is_told_none_has_it() -> None:
    code, out = _accuracy("al-far", yielding="sphere", e_star_over_sy=1000.0)
    assert code == 2
    assert "none of the shipped FE cases has that pair" in out
    assert "matched within 5 %" in out and "all of a yielding flat" in out
