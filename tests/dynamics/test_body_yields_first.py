"""A softer impacting body: where the body's material yields first
(``materials.body_yields_first``), delta_p (a drop's dent_depth and dents) is the body's
flattening, not a dent in the flat. The values stay; the result says whose deformation it is
(``body_yields_first``, an advisory warning, ``to_dict``), ``dent()`` refuses a flat dent map,
and ``impactlab simulate`` / ``impactlab drop`` print and save accordingly."""

from __future__ import annotations

import contextlib
import io
import json
import math
import shutil
import sys
from pathlib import Path
from typing import Any

import pytest

import impactlab as il
from impactlab.cli import main
from impactlab.flags import ResultFlag

AL = il.get_material("al-6061-t6")
HARD = il.get_material("aisi-52100")
SPHERE: dict[str, Any] = {"law": "jackson-green", "velocity": (0.0, -2.5)}
#: an aluminium rod of the paper's length on the hardened flat: the rod yields first
AL_ROD = il.Rod(length=0.3, tip_radius=0.005, mass=0.3, material=AL)
DROP: dict[str, Any] = {"law": "jackson-green", "angle": math.radians(30), "velocity": (0.0, -1.0)}


@pytest.fixture(scope="module")
def soft_sphere() -> il.ImpactResult:
    return il.simulate(il.Sphere(radius=0.003, material=AL), HARD, **SPHERE)


def test_the_sphere_s_flattening_is_named(soft_sphere: il.ImpactResult) -> None:
    r = soft_sphere
    assert r.body_yields_first is True and r.ok  # advisory: the measures hold
    assert r.delta_p == pytest.approx(1.1298e-5, rel=1e-3)  # the value is kept
    said = [w for w in r.warnings if w.startswith("body yields first: ")]
    assert len(said) == 1 and "'aluminium 6061-T6'" in said[0] and "AISI 52100" in said[0]
    assert "delta_p = 11.3 um is the body's permanent flattening" in said[0]
    assert "not a dent in the flat" in said[0]
    assert ResultFlag(r.flags) == r.flags  # no flag bit of its own
    d = r.to_dict()
    assert d["body_yields_first"] is True and said[0] in d["warnings"] and d["ok"] is True


def test_dent_refuses_a_dent_the_flat_does_not_have(soft_sphere: il.ImpactResult) -> None:
    with pytest.raises(ValueError, match=r"^dent\(\): there is no dent in the flat to map") as e:
        soft_sphere.dent()
    text = str(e.value)
    assert "'aluminium 6061-T6' yields before the flat" in text and "leaves the dent out" in text
    assert "455.7 MPa against 3285 MPa" in text  # C(nu) S_y of each
    from impactlab.dynamics import plotting

    with pytest.raises(ValueError, match="no dent in the flat"):
        plotting.plot_dent(soft_sphere)
    fig = plotting.plot_contact_path(soft_sphere)
    assert fig is not None


def test_the_flat_that_yields_keeps_its_dent() -> None:
    r = il.simulate(il.Rod.paper(), angle="20 deg", velocity=(0.0, -1.41), mu=0.2)
    assert r.body_yields_first is False and r.to_dict()["body_yields_first"] is False
    assert not any(w.startswith("body yields first") for w in r.warnings)
    assert r.dent().max_depth == pytest.approx(r.delta_p, rel=1e-5)


def test_an_elastic_law_leaves_nothing_to_name() -> None:
    r = il.simulate(il.Sphere(radius=0.003, material=AL), HARD, law="hertz", velocity=(0, -2.5))
    assert r.body_yields_first is True and r.delta_p == 0.0
    assert not any(w.startswith("body yields first") for w in r.warnings)
    assert r.dent().max_depth == 0.0  # the flat map of an elastic impact, as before


def test_a_drop_of_a_softer_rod() -> None:
    d = il.simulate_drop(AL_ROD, HARD, **DROP)
    assert d.body_yields_first is True and d.dent_depth > 0.0 and d.ok
    said = [w for w in d.warnings if w.startswith("body yields first: ")]
    assert len(said) == 1 and "dent_depth" in said[0] and "not a dent in the flat" in said[0]
    assert d.to_dict()["body_yields_first"] is True
    with pytest.raises(ValueError, match="no dent in the flat"):
        d.dent()
    no_history = il.simulate_drop(AL_ROD, HARD, history=False, **DROP)
    with pytest.raises(ValueError, match="needs the history"):
        no_history.dent()


def test_a_rate_law_leaves_a_rod_that_yields_first_as_it_is() -> None:
    """A rate-raised flat does not make a softer rod hard (``contact.rate.rate_materials``: it
    raised the rod's S_y above the flat's, and the rod's flattening read as a dent in the flat):
    the rod still yields first, and the drop says so."""
    assert il.materials.body_yields_first(AL, il.AISI_1010)
    static = il.simulate_drop(AL_ROD, il.AISI_1010, **DROP)
    assert static.body_yields_first is True
    rated = il.simulate_drop(AL_ROD, il.AISI_1010, rate="cowper-symonds", **DROP)
    assert rated.rate_factor > 1.0 and rated.body_yields_first is True
    assert rated.dent_depth == static.dent_depth  # the rod's S_y, unchanged, sets it
    assert any(w.startswith("body yields first") for w in rated.warnings)
    with pytest.raises(ValueError, match="body"):
        rated.dent()


def _main(args: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, str, str]:
    old = sys.argv
    sys.argv = ["impactlab", *args]
    code = 0
    try:
        main()
    except SystemExit as exc:
        code = int(exc.code or 0)
    finally:
        sys.argv = old
    out = capsys.readouterr()
    return code, out.out, out.err


SPHERE_CLI = ["simulate", "sphere", "--radius", "3 mm", "--speed", "2.5 m/s", "--incidence",
              "0 deg", "--material", "al-6061-t6", "--flat", "aisi-52100", "--law",
              "jackson-green"]  # fmt: skip


ROD_PLOT = ["simulate", "rod", "--angle", "20 deg", "--vy", "-1.41", "--plot"]


@pytest.fixture(scope="module")
def dent_figures(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The figures of ``impactlab simulate rod ... --plot`` for the paper's 20 deg impact, a
    dent figure among them (run once; each test copies the folder)."""
    figs = tmp_path_factory.mktemp("dent-figures") / "figs"
    old, sys.argv = sys.argv, ["impactlab", *ROD_PLOT, "--out", str(figs)]
    err, code = io.StringIO(), None
    try:
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            main()
    except SystemExit as exc:
        code = exc.code
    finally:
        sys.argv = old
    assert not code, err.getvalue()
    return figs


def test_the_command_says_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], dent_figures: Path
) -> None:
    code, out, err = _main([*SPHERE_CLI, "--json"], capsys)
    assert code == 0, err
    data = json.loads(out)
    assert data["body_yields_first"] is True
    assert data["delta_p"]["value"] == pytest.approx(1.1298e-5, rel=1e-3)
    assert any(w.startswith("body yields first: ") for w in data["warnings"])
    assert "warning: body yields first: " in err
    figs = Path(shutil.copytree(dent_figures, tmp_path / "figs"))
    for ext in ("png", "pdf"):  # an earlier run's dent figure would mislead: it goes
        assert (figs / f"impact_dent.{ext}").is_file()
    code, _, err = _main([*SPHERE_CLI, "--plot", "--out", str(figs)], capsys)
    assert code == 0, err
    assert not list(figs.glob("impact_dent.*"))
    assert (figs / "impact_contact_path.png").is_file()
    assert json.loads((figs / "impact_result.json").read_text())["body_yields_first"] is True


def test_the_drop_command_says_it(capsys: pytest.CaptureFixture[str]) -> None:
    args = ["drop", "--rigid", "--length", "0.3 m", "--tip-radius", "5 mm", "--mass", "0.3 kg",
            "--material", "al-6061-t6", "--flat", "aisi-52100", "--law", "jackson-green",
            "--angle", "30 deg", "--vy", "-1 m/s"]  # fmt: skip
    code, out, err = _main([*args, "--json"], capsys)
    assert code == 0, err
    assert json.loads(out)["body_yields_first"] is True
    assert "warning: body yields first: " in err and "dent_depth" in err


def test_an_impact_without_a_dent_saves_no_dent_figure(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], dent_figures: Path
) -> None:
    """An elastic law's impact wrote a uniform 'dent' map whose colour bar ran over
    rounding noise (+-1e-14 um)."""
    from impactlab.dynamics import plotting

    r = il.simulate(il.Rod.paper(), law="hertz", angle=math.radians(20), velocity=(0.0, -1.41))
    assert r.delta_p == 0.0
    fig = plotting.plot_dent(r)
    assert "none" in fig.axes[0].get_title() and len(fig.axes) == 1  # no colour bar
    names = [p.name for p in plotting.save_figures(r, tmp_path / "api", formats=("png",))]
    assert "impact_dent.png" not in names and "impact_contact_path.png" in names
    figs = Path(shutil.copytree(dent_figures, tmp_path / "figs"))
    assert (figs / "impact_dent.png").is_file()
    code, _, err = _main(["simulate", "rod", "--law", "hertz", "--angle", "20 deg", "--vy",
                          "-1.41", "--plot", "--out", str(figs)], capsys)  # fmt: skip
    assert code == 0, err
    assert not list(figs.glob("impact_dent.*"))
