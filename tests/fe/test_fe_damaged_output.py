"""A damaged ccx output or FE cache file: never a traceback, never numbers read wrong.

``parse_dat`` refuses a ``.dat`` text whose rows have the wrong width, whose numbers are cut
short (``2.359`` for ``2.359894E-02``) or that ends inside a line, in one line naming the
file, the line and the fault; ``assemble`` refuses a ``.dat`` cut at a line's end that stops
before the time at which the ``.sta`` file records the run finishing (not a run that stopped).
``indent`` keeps and caches the runs that ended and names the damaged one. A cache file that
cannot be read back is a cache miss: a warning names it, the run is made again and written
over it. No ccx or gmsh: ``indent``'s run, mesh and ccx look-ups are replaced by stand-ins.
"""

from __future__ import annotations

import json
import warnings
from pathlib import Path
from types import SimpleNamespace
from typing import Any, cast

import numpy as np
import pytest

from impactlab.fe import cache
from impactlab.fe import run as fe_run
from impactlab.fe.ccx import DamagedOutputError, RunOutput, parse_dat
from impactlab.fe.problem import Problem, make_problem
from impactlab.fe.result import IndentationResult
from impactlab.fe.run import DamagedRunsError, assemble, indent
from impactlab.materials import AISI_1010

R = 8.8e-3
HEAD = " displacements (vx,vy,vz) for set NFSURF and time  0.2500000E-01\n\n"
ROWS = (
    "         1  0.000000E+00 -4.976786E-06  0.000000E+00\n"
    "         5 -8.622471E-08 -2.359894E-02  0.000000E+00\n"
)
TOTAL = "\n total force (fx,fy,fz) for set NTOP and time  0.2500000E-01\n\n"


def test_a_whole_file_is_read() -> None:
    dat = parse_dat(TOTAL + "        2.847133E-08 -6.197790E-05 -7.978350E-25\n\n" + HEAD + ROWS)
    _, ids, u = dat.nodal[("displacements", "NFSURF")][0]
    assert ids.tolist() == [1, 5] and u[1, 1] == pytest.approx(-2.359894e-2)


@pytest.mark.parametrize(
    ("text", "line", "fault"),
    [
        (HEAD + ROWS.replace("0.000000E+00\n", "0.0\n"), 3, "'0.0' is not a whole number"),
        (HEAD + ROWS.replace("E-02  0.000000E+00", "E-0"), 4, "3 values where its block has 4"),
        # cut inside a number: read before as -2.359894 (E-0), 100 times off
        (HEAD + ROWS.replace("-2.359894E-02", "-2.359894E-0"), 4, "'-2.359894E-0' is not"),
        (HEAD + ROWS.replace("         5", "        5x"), 4, "'5x' is not a whole node id"),
        (HEAD + ROWS[:-30], 4, "the file ends inside a line"),
        (HEAD + ROWS + "         7 -1.0E-07\n", 5, "2 values where its block has 4"),
        (TOTAL + "        2.847133E-08\n", 4, "1 values where its block has 3"),
        (TOTAL, 2, "has no rows"),
    ],
)
def test_a_damaged_file_is_refused_naming_the_line(text: str, line: int, fault: str) -> None:
    with pytest.raises(DamagedOutputError) as err:
        parse_dat(text, "run0/job.dat")
    message = str(err.value)
    assert message.startswith(f"run0/job.dat, line {line}: ") and fault in message
    assert "damaged" in message and "\n" not in message


def _problem(unload: bool = True) -> Problem:
    return make_problem(
        AISI_1010, AISI_1010, radius=R, delta_max=1e-6, sphere="rigid", unload=unload
    )


def _totals(times: list[float]) -> str:
    out = ""
    for t in times:
        for nset in ("NTOP", "NBOT"):
            out += (
                f"\n total force (fx,fy,fz) for set {nset} and time  {t:.7E}\n\n"
                "        2.847133E-08 -6.197790E-05 -7.978350E-25\n"
            )
    return out


def _sta(times: list[float]) -> str:
    rows = ["SUMMARY OF JOB INFORMATION", "  STEP      INC     ATT  ITRS     TOT TIME"]
    for i, t in enumerate(times, 1):
        rows.append(f"     {1 if t <= 1 else 2}  {i}  1  4  {t:.6E}  {t:.6E}  0.5E+00")
    return "\n".join(rows) + "\n"


#: A stand-in mesh: the node sets ``assemble`` counts the printed rows against.
MESH = cast(Any, SimpleNamespace(flat_surface_nodes=np.arange(2), sphere_surface_nodes=[]))


def test_a_file_cut_at_a_line_end_is_not_a_run_that_stopped() -> None:
    """ccx ended normally and its .sta file reached the end time 2, but the .dat stops at 1.5:
    refused as damaged (before, reported as NOT CONVERGED although ccx finished)."""
    problem = _problem()
    deck = problem.deck_spec(problem.mesh_spec())
    out = RunOutput(_totals([0.5, 1.0, 1.5]), _sta([0.5, 1.0, 1.5, 2.0]), 0, "", 1.0)
    with pytest.raises(DamagedOutputError, match=r"^run 1's job\.dat, line 24: the file stops"):
        assemble(problem, MESH, deck, out, "run 1's job.dat")
    # a loading-only run's end is 1: its .dat to 0.5 with a .sta to 1.0 is damaged too
    short = _problem(unload=False)
    out = RunOutput(_totals([0.5]), _sta([0.5, 1.0]), 0, "", 1.0)
    with pytest.raises(DamagedOutputError, match=r"job\.sta records the run finishing at time 1;"):
        assemble(short, MESH, short.deck_spec(short.mesh_spec()), out)
    out = RunOutput("", _sta([0.5, 1.0]), 0, "", 1.0)
    with pytest.raises(DamagedOutputError, match="the file has no printed block"):
        assemble(short, MESH, short.deck_spec(short.mesh_spec()), out)


def _result(problem: Problem, converged: bool = True) -> IndentationResult:
    d = np.array([0.5, 1.0]) * problem.delta_max
    return IndentationResult(
        delta_max=problem.delta_max,
        loading_delta=d,
        loading_force=np.array([1.0, 3.0]),
        contact_radius=np.sqrt(R * d),
        unloading_delta=np.array([problem.delta_max, 0.0]),
        unloading_force=np.array([3.0, 0.0]),
        residual_depth=0.0,
        dent_r=np.array([0.0, 1e-4]),
        dent_z=np.array([0.0, 0.0]),
        delta_c=problem.delta_c,
        converged=converged,
        last_converged_delta=problem.delta_max,
        message="",
        increments=2,
        cutbacks=0,
        iterations=8,
        run_time=0.1,
        n_elements=10,
        force_balance=0.0,
        inputs=problem.key_data(),
    )


@pytest.fixture
def runs(monkeypatch: pytest.MonkeyPatch) -> list[float]:
    """``indent`` without ccx or gmsh: each run returns ``_result``, or raises a
    DamagedOutputError for a delta_max of 2 um; returns the delta_max of every run made."""
    made: list[float] = []

    def solve(problem: Problem, mesh: Any, exe: str, keep: Path | None) -> IndentationResult:
        made.append(problem.delta_max)
        if problem.delta_max == pytest.approx(2e-6):
            raise DamagedOutputError("ccx's job.dat for delta_max = 2 um, line 9: cut")
        return _result(problem)

    monkeypatch.setattr(fe_run, "find_ccx", lambda: "ccx")
    monkeypatch.setattr(fe_run, "ccx_version", lambda exe: "stand-in")
    monkeypatch.setattr(fe_run, "build_mesh", lambda spec: None)
    monkeypatch.setattr(fe_run, "_solve", solve)
    return made


def test_the_runs_that_ended_are_kept_and_the_damaged_one_named(
    runs: list[float], tmp_path: Path
) -> None:
    kwargs: dict[str, Any] = {"radius": R, "sphere": "rigid", "cache_dir": tmp_path, "workers": 1}
    with pytest.raises(DamagedRunsError) as err:
        indent(AISI_1010, delta_max=[1e-6, 2e-6, 3e-6], **kwargs)
    message = str(err.value)
    assert message.startswith("ccx's job.dat for delta_max = 2 um, line 9: cut; the other 2 ")
    assert "(delta_max = 1 um, 3 um) ended: they are cached" in message
    assert "\n" not in message and isinstance(err.value, ValueError)
    assert [r is None for r in err.value.results] == [False, True, False]
    assert len(list(tmp_path.glob("*.npz"))) == 2  # the finished runs are cached
    runs.clear()
    with pytest.raises(DamagedRunsError):  # again: the two from the cache, the third rerun
        indent(AISI_1010, delta_max=[1e-6, 2e-6, 3e-6], **kwargs)
    assert runs == [pytest.approx(2e-6)]


@pytest.mark.parametrize(
    "damage",
    ["empty", "cut", "no converged", "header a list", "array missing", "not an npz"],
)
def test_a_damaged_cache_file_is_a_miss_run_again_and_overwritten(
    damage: str, runs: list[float], tmp_path: Path
) -> None:
    kwargs: dict[str, Any] = {"radius": R, "sphere": "rigid", "cache_dir": tmp_path}
    (first,) = indent(AISI_1010, delta_max=1e-6, **kwargs)
    (path,) = tmp_path.glob("*.npz")
    whole = path.read_bytes()
    values = first.arrays()
    header = {k: v for k, v in values.items() if k not in cache.ARRAYS}
    arrays = {k: values[k] for k in cache.ARRAYS}
    if damage == "empty":
        path.write_bytes(b"")
    elif damage == "cut":
        path.write_bytes(whole[: len(whole) // 2])
    elif damage == "not an npz":
        path.write_bytes(b"\x93NUMPY" + whole[6:40])
    else:
        if damage == "no converged":
            del header["converged"]
        if damage == "array missing":
            del arrays["dent_z"]
        record: Any = [header] if damage == "header a list" else header
        with open(path, "wb") as fh:
            np.savez(fh, header=np.array(json.dumps(record)), **arrays)
    runs.clear()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        (again,) = indent(AISI_1010, delta_max=1e-6, **kwargs)
    assert runs == [pytest.approx(1e-6)]  # run again
    (w,) = [w for w in caught if issubclass(w.category, cache.DamagedCacheWarning)]
    assert str(path) in str(w.message) and "treated as missing" in str(w.message)
    assert again.converged
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert cache.load(tmp_path, path.stem) is not None  # written over: whole again
