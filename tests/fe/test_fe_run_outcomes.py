"""What ``indent`` keeps of a run: a run that ccx could not finish is cached like a finished one
(ccx stops there again on the same inputs; before, each identical call ran ccx again for
minutes), read back as it was, its warning saying where it comes from; a ccx output with a nan or
inf is refused naming the file and the line, and nothing of it is cached (read before as a
converged run whose force balance or delta_r was nan). Stand-ins replace ccx."""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab.fe import run as fe_run
from impactlab.fe.ccx import NonFiniteOutputError, parse_dat
from impactlab.fe.problem import Problem, make_problem
from impactlab.fe.result import IndentationResult
from impactlab.fe.run import DamagedRunsError, NotConvergedWarning, indent
from impactlab.materials import AISI_1010

R = 8.8e-3
ELASTIC: dict[str, Any] = {"radius": R, "sphere": "rigid", "flat_hardening": "elastic"}
STOPPED = "ccx exit status 201: *ERROR: increment size smaller than minimum"


def _stopped(problem: Problem) -> IndentationResult:
    """A run that ccx stopped at half its maximum."""
    d = np.array([0.25, 0.5]) * problem.delta_max
    return IndentationResult(
        delta_max=problem.delta_max,
        loading_delta=d,
        loading_force=np.array([1.0, 3.0]),
        contact_radius=np.sqrt(R * d),
        unloading_delta=np.empty(0),
        unloading_force=np.empty(0),
        residual_depth=float("nan"),
        dent_r=np.empty(0),
        dent_z=np.empty(0),
        delta_c=problem.delta_c,
        converged=False,
        last_converged_delta=float(d[-1]),
        message=STOPPED,
        increments=2,
        cutbacks=5,
        iterations=80,
        run_time=120.0,
        n_elements=10,
        force_balance=0.0,
        inputs=problem.key_data(),
    )


def test_a_run_that_did_not_converge_is_read_from_the_cache(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    made: list[float] = []

    def solve(problem: Problem, mesh: Any, exe: str, keep: Path | None) -> IndentationResult:
        made.append(problem.delta_max)
        return _stopped(problem)

    monkeypatch.setattr(fe_run, "find_ccx", lambda: "ccx")
    monkeypatch.setattr(fe_run, "ccx_version", lambda exe: "stand-in")
    monkeypatch.setattr(fe_run, "build_mesh", lambda spec: None)
    monkeypatch.setattr(fe_run, "_solve", solve)
    kwargs: dict[str, Any] = {"radius": R, "sphere": "rigid", "cache_dir": tmp_path}
    with pytest.warns(NotConvergedWarning):
        (first,) = indent(AISI_1010, delta_max=1e-6, **kwargs)
    assert made == [1e-6] and first.message == STOPPED
    assert len(list(tmp_path.glob("*.npz"))) == 1
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        (again,) = indent(AISI_1010, delta_max=1e-6, **kwargs)
    assert made == [1e-6]  # not run again
    assert not again.converged and again.last_converged_delta == first.last_converged_delta
    np.testing.assert_array_equal(again.loading_force, first.loading_force)
    assert again.message == STOPPED  # as it was (the shipped data record it)
    (w,) = [w for w in caught if issubclass(w.category, NotConvergedWarning)]
    text = str(w.message)
    assert text.startswith(f"{again.status()}; read from the FE cache ({tmp_path}")
    assert text.endswith("use_cache=False (impactlab fe indent --no-cache) runs it again")
    with pytest.warns(NotConvergedWarning):
        (fresh,) = indent(AISI_1010, delta_max=1e-6, use_cache=False, **kwargs)
    assert made == [1e-6, 1e-6] and fresh.message == STOPPED


ROW = "         5 -8.622471E-08 -2.359894E-02  0.000000E+00\n"


@pytest.mark.parametrize("value", ["nan", "-inf", "NaN"])
def test_a_non_finite_number_is_refused_naming_the_line(value: str) -> None:
    head = " displacements (vx,vy,vz) for set NFSURF and time  0.1000000E+01\n\n"
    with pytest.raises(NonFiniteOutputError) as err:
        parse_dat(head + ROW + ROW.replace("-2.359894E-02", value), "run0/job.dat")
    text = str(err.value)
    assert text.startswith(f"run0/job.dat, line 4: {value!r} where ccx prints a finite number")
    assert "diverged" in text and "nothing of it is kept or cached" in text and "\n" not in text


def _totals(t: float, force: str) -> str:
    return "".join(
        f"\n total force (fx,fy,fz) for set {s} and time  {t:.7E}\n\n"
        f"        2.847133E-08 {force} -7.978350E-25\n"
        for s in ("NTOP", "NBOT")
    )


@pytest.mark.parametrize("where", ["force", "displacement"])
def test_a_run_with_a_nan_is_refused_and_not_cached(
    where: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A loading-only run that ccx finished, with a nan in its last force row or in its last
    surface displacements: before, converged with a nan force balance (or contact radius),
    and cached."""
    pytest.importorskip("gmsh", reason="impactlab.fe needs the gmsh package (the fe extra)")
    problem = make_problem(AISI_1010, AISI_1010, delta_max=1e-7, unload=False, **ELASTIC)
    mesh = fe_run.build_mesh(problem.mesh_spec())
    rows = [f"{int(i) + 1:10d}  0.000000E+00 -1.000000E-06  0.000000E+00\n" for i in
            mesh.flat_surface_nodes]  # fmt: skip
    last = list(rows)
    if where == "displacement":
        last[-1] = last[-1].replace("-1.000000E-06", "nan")
    head = " displacements (vx,vy,vz) for set NFSURF and time  {:.7E}\n\n"
    force = "nan" if where == "force" else "-6.197790E-05"
    dat = (
        _totals(0.5, "-3.1E-05") + "\n" + head.format(0.5) + "".join(rows) + "\n"
        + _totals(1.0, force) + "\n" + head.format(1.0) + "".join(last) + "\n"
    )  # fmt: skip
    (tmp_path / "fake.dat").write_text(dat)
    exe = tmp_path / "ccx"
    exe.write_text(
        "#!/bin/sh\n"
        'if [ "$1" = "-v" ]; then echo "This is Version 2.23"; exit 0; fi\n'
        f"cp {tmp_path / 'fake.dat'} job.dat\n: > job.sta\n"
    )
    exe.chmod(0o755)
    monkeypatch.setenv("IMPACTLAB_CCX", str(exe))
    cache = tmp_path / "cache"
    with pytest.raises(DamagedRunsError) as err:
        indent(AISI_1010, delta_max=1e-7, unload=False, cache_dir=cache, **ELASTIC)
    assert isinstance(err.value.damaged[0], NonFiniteOutputError)
    text = str(err.value)
    assert text.startswith("ccx's job.dat for delta_max = 0.1 um, line ")
    assert "'nan' where ccx prints a finite number" in text
    assert not list(cache.glob("*.npz"))  # nothing cached
