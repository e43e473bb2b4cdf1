"""Reading ccx's output right, or refusing it: numbers with a three-digit exponent (Fortran
drops its letter: ``4.286203-101``), nodal blocks with rows missing (a ``.dat`` file cut at a
line's end inside its last block, read before as a converged run with a wrong dent), and an
``IMPACTLAB_CCX`` that is not CalculiX (``/bin/true``: reported before as a run that did not
converge, cached under the version "unknown"). Stand-in ccx scripts replace CalculiX (a real
run's output cut inside its last block: ``tests/fe/test_fe_runs.py``)."""

from __future__ import annotations

import os
import re
import shutil
from pathlib import Path
from typing import Any

import pytest

from impactlab import fe
from impactlab.fe import run as fe_run
from impactlab.fe.ccx import (
    FORTRAN_FLOAT,
    DamagedOutputError,
    NotCalculixError,
    ccx_version,
    fortran_value,
    parse_dat,
)
from impactlab.fe.impact_result import contact_forces
from impactlab.fe.problem import make_problem
from impactlab.fe.run import DamagedRunsError, indent
from impactlab.materials import AISI_1010

R = 8.8e-3
ELASTIC: dict[str, Any] = {"radius": R, "sphere": "rigid", "flat_hardening": "elastic"}


def _block(t: float, rows: list[str], nset: str = "NFSURF") -> str:
    head = f" displacements (vx,vy,vz) for set {nset} and time  {t:.7E}\n\n"
    return head + "".join(rows) + "\n"


ROWS = [
    "         1  0.000000E+00 -4.976786E-06  0.000000E+00\n",
    "         5 -8.622471E-08 -2.359894E-02  0.000000E+00\n",
    "         6 -2.062699E-07 -5.319410E-06  0.000000E+00\n",
]


def test_a_three_digit_exponent_without_its_letter_is_read() -> None:
    """A converged run's last surface block, refused before as damaged (the run lost)."""
    text = (
        " displacements (vx,vy,vz) for set NFSURF and time  0.1000000E+01\n\n"
        "         1  1.486578E-85 -3.113567E-85  4.286203-101\n"
    )
    ((t, ids, u),) = parse_dat(text).nodal[("displacements", "NFSURF")]
    assert t == 1.0 and ids.tolist() == [1]
    assert u[0].tolist() == [1.486578e-85, -3.113567e-85, 4.286203e-101]
    for text_, value in [("1.0+100", 1e100), ("-2.5-123", -2.5e-123), ("1.0D-05", 1e-5)]:
        assert fortran_value(text_) == value
    big = "         1  1.0+100 -1.000000E+00  0.000000E+00\n"
    assert parse_dat(_block(1.0, [big])).nodal[("displacements", "NFSURF")][0][2][0, 0] == 1e100
    # a number cut short is still refused
    with pytest.raises(DamagedOutputError, match=r"'4\.286203-10' is not a whole number"):
        parse_dat(text.replace("-101", "-10"))


def test_contact_forces_read_a_three_digit_exponent() -> None:
    """Read before as 1.0 (the mantissa), or the time's force left out."""
    block = (
        " statistics for slave set SF{k}, master set SSPH and time  0.2000000E-05\n\n"
        "   total surface force (fx,fy,fz) and moment about the origin (mx,my,mz)\n\n"
        "    {fx} {fy}  0.000000E+00  0.0  0.0  0.0\n\n"
    )
    text = block.format(k=0, fx="4.286203-101", fy="-1.000000-100")
    text += block.format(k=1, fx="0.000000E+00", fy="-2.500000E-01")
    t, f = contact_forces(text)
    assert t.tolist() == [2e-6] and f[0] == pytest.approx(0.25 * 180.0, rel=1e-12)
    assert re.fullmatch(FORTRAN_FLOAT, "4.286203-101") and not re.fullmatch(FORTRAN_FLOAT, "1.0-10")


def test_a_block_with_rows_missing_is_refused_naming_the_set_and_counts() -> None:
    whole = _block(0.5, ROWS) + _block(1.0, ROWS)
    assert len(parse_dat(whole).nodal[("displacements", "NFSURF")]) == 2
    cut = _block(0.5, ROWS) + _block(1.0, ROWS[:2])  # cut at a line's end in the last block
    with pytest.raises(DamagedOutputError) as err:
        parse_dat(cut, "run0/job.dat")
    assert str(err.value) == (
        "run0/job.dat, line 7: the block 'displacements (vx,vy,vz)' for set NFSURF at time 1 "
        "has 2 rows where 3 are expected (its block at time 0.5 has 3); the file is damaged "
        "(cut short?)"
    )
    # the set's size, where known, also checks the first block
    with pytest.raises(DamagedOutputError, match=r"has 3 rows where 4 are expected \(the set"):
        parse_dat(whole, "job.dat", {"NFSURF": 4})
    assert parse_dat(whole, "job.dat", {"NFSURF": 3, "NSSURF": 7}).nodal


def _fake_ccx(tmp_path: Path, dat: str, sta: str) -> str:
    """A stand-in ccx that writes ``dat`` and ``sta`` as its job's output and ends normally."""
    (tmp_path / "fake.dat").write_text(dat)
    (tmp_path / "fake.sta").write_text(sta)
    exe = tmp_path / "ccx"
    exe.write_text(
        "#!/bin/sh\n"
        'if [ "$1" = "-v" ]; then echo "This is Version 2.23"; exit 0; fi\n'
        f"cp {tmp_path / 'fake.dat'} job.dat\ncp {tmp_path / 'fake.sta'} job.sta\n"
    )
    exe.chmod(0o755)
    return str(exe)


def _totals(t: float) -> str:
    return "".join(
        f"\n total force (fx,fy,fz) for set {s} and time  {t:.7E}\n\n"
        "        2.847133E-08 -6.197790E-05 -7.978350E-25\n"
        for s in ("NTOP", "NBOT")
    )


def test_a_cut_run_is_refused_and_never_cached(tmp_path: Path, monkeypatch: Any) -> None:
    """Forces printed to the end (time 1, a loading-only run that ccx finished), but every
    surface block holds 3 of the set's nodes: refused, naming the file, the set, the time
    and the counts; no cache file is written."""
    pytest.importorskip("gmsh", reason="impactlab.fe needs the gmsh package (the fe extra)")
    dat = _totals(0.5) + "\n" + _block(0.5, ROWS) + _totals(1.0) + "\n" + _block(1.0, ROWS)
    sta = "  STEP      INC     ATT  ITRS     TOT TIME\n"
    sta += "     1  1  1  4  5.000000E-01  5.000000E-01  0.5E+00\n"
    sta += "     1  2  1  4  1.000000E+00  5.000000E-01  0.5E+00\n"
    monkeypatch.setenv("IMPACTLAB_CCX", _fake_ccx(tmp_path, dat, sta))
    cache = tmp_path / "cache"
    with pytest.raises(DamagedRunsError) as err:
        indent(AISI_1010, delta_max=1e-7, unload=False, cache_dir=cache, **ELASTIC)
    text = str(err.value)
    assert text.startswith("ccx's job.dat for delta_max = 0.1 um, line ")
    assert "for set NFSURF at time 0.5 has 3 rows where " in text and "(the set has " in text
    assert "\n" not in text and not list(cache.glob("*.npz"))


def test_a_missing_surface_block_is_refused(tmp_path: Path, monkeypatch: Any) -> None:
    """The file cut between the forces and the surface block of its last time."""
    pytest.importorskip("gmsh", reason="impactlab.fe needs the gmsh package (the fe extra)")
    problem = make_problem(AISI_1010, AISI_1010, delta_max=1e-7, unload=False, **ELASTIC)
    mesh = fe_run.build_mesh(problem.mesh_spec())
    ids = mesh.flat_surface_nodes
    rows = [f"{int(i) + 1:10d}  0.000000E+00 -1.000000E-06  0.000000E+00\n" for i in ids]
    dat = _totals(0.5) + "\n" + _block(0.5, rows) + _totals(1.0)
    out = fe_run.RunOutput(dat, "", 0, "", 1.0)
    deck = problem.deck_spec(problem.mesh_spec())
    with pytest.raises(DamagedOutputError, match="no displacements of set NFSURF at time 1, whose"):
        fe_run.assemble(problem, mesh, deck, out)


@pytest.mark.parametrize("program", ["/bin/true", "/bin/echo"])
def test_an_executable_that_is_not_calculix_is_refused(
    program: str, tmp_path: Path, monkeypatch: Any, cli_main: Any
) -> None:
    """Before any mesh or run, in one line; the CLI exits with status 2."""
    if not os.access(program, os.X_OK):  # pragma: no cover - a system without it
        pytest.skip(f"{program} is not here")
    with pytest.raises(NotCalculixError) as err:
        ccx_version(program)
    text = str(err.value)
    assert text.startswith(f"{program} is not CalculiX's ccx: `{program} -v` printed no ")
    assert "exit status 0" in text and "IMPACTLAB_CCX" in text and "\n" not in text
    monkeypatch.setenv("IMPACTLAB_CCX", program)
    monkeypatch.setattr(fe_run, "build_mesh", lambda spec: pytest.fail("mesh built"))
    with pytest.raises(NotCalculixError):
        fe.indent(AISI_1010, delta_max=1e-7, cache_dir=tmp_path, **ELASTIC)
    assert not list(tmp_path.iterdir())
    code, _, err_text = cli_main("fe", "indent", "--max", "0.1 um", "--sphere", "rigid")
    assert code == 2 and err_text.count("\n") == 1
    assert f"{program} is not CalculiX's ccx" in err_text


@pytest.mark.skipif(shutil.which("ccx") is None, reason="ccx (CalculiX) is not installed")
def test_calculix_prints_its_version() -> None:
    assert re.fullmatch(r"\d+\.\d+\S*", ccx_version(str(shutil.which("ccx"))))
