"""impactlab.fe against CalculiX: Hertz, force balance, cache, repeatability, plasticity.

Skipped (with the reason) when ccx or gmsh is missing; impactlab's own modules are imported
unconditionally, so a broken import fails. The smoke part is four ccx runs, about 110 s of
CPU: one complete elastic run shared by the elastic checks (and, its output cut, by the check
that a damaged ``.dat`` is refused), one call running the frictional loading twice in
parallel (friction and repeatability), and the paper's pair to 10 delta_c; the long checks
(finer meshes, 1000 delta_c: 3-15 minutes of ccx each) run only with ``IMPACTLAB_FE_LONG=1``,
outside the test suite's time budget.
"""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from impactlab.fe import indent
from impactlab.fe import run as fe_run
from impactlab.fe.ccx import RunOutput
from impactlab.fe.mesh import build_mesh
from impactlab.fe.problem import make_problem
from impactlab.fe.run import DamagedRunsError, assemble
from impactlab.materials import AISI_201, AISI_1010

pytest.importorskip("gmsh", reason="impactlab.fe needs the gmsh package (the fe extra)")
if shutil.which("ccx") is None:
    pytest.skip(
        "CalculiX ccx is not installed (apt-get install calculix-ccx)", allow_module_level=True
    )

#: The long checks: minutes of ccx each, run on request (the suite must stay within 10 minutes).
LONG = pytest.mark.skipif(
    os.environ.get("IMPACTLAB_FE_LONG", "") in ("", "0"),
    reason="long FE run (3-15 minutes of ccx): set IMPACTLAB_FE_LONG=1 to run it",
)

R = 8.8e-3
ELASTIC = {"radius": R, "sphere": "rigid", "flat_hardening": "elastic"}


def hertz(res, problem):
    """Hertz force [N] at the loading points of ``res``."""
    return 4.0 / 3.0 * problem.E_star * np.sqrt(R) * res.loading_delta**1.5


@pytest.fixture(scope="module")
def elastic(tmp_path_factory):
    """A rigid sphere on an elastic flat to delta_c (mesh level 1), its files kept."""
    base = tmp_path_factory.mktemp("fe")
    problem = make_problem(AISI_1010, AISI_1010, delta_max=1e-6, **ELASTIC)
    dc = problem.delta_c
    res = indent(
        AISI_1010, delta_max=dc, cache_dir=base / "cache", keep_files=base / "files", **ELASTIC
    )[0]
    return res, make_problem(AISI_1010, AISI_1010, delta_max=dc, **ELASTIC), base


def test_hertz_level_1(elastic):
    """Level 1 is the coarse mesh: Hertz within 1.5 % from 0.1 delta_c to delta_c (level 3
    reaches 0.5 %: the slow test below)."""
    res, problem, _ = elastic
    assert res.converged, res.status()
    keep = res.loading_delta >= 0.1 * res.delta_c
    err = res.loading_force[keep] / hertz(res, problem)[keep] - 1.0
    assert np.max(np.abs(err)) < 0.015
    a_hertz = np.sqrt(R * res.loading_delta[keep])
    assert np.allclose(res.contact_radius[keep], a_hertz, rtol=0.08)


def test_force_balance_and_elastic_unloading(elastic):
    res, _, _ = elastic
    assert res.force_balance < 1e-6  # the sphere's reaction equals the flat's
    assert res.residual_depth < 0.01 * res.delta_max  # elastic: no dent
    assert np.max(np.abs(res.dent_z)) < 0.01 * res.delta_max
    assert res.increments > 20
    assert res.run_time > 0.0


def test_cache_hit_runs_no_ccx_and_is_equal(elastic, monkeypatch):
    res, _, base = elastic

    def no_run(*args, **kwargs):
        raise AssertionError("a cached run started ccx")

    monkeypatch.setattr(fe_run, "run_ccx", no_run)
    again = indent(AISI_1010, delta_max=res.delta_max, cache_dir=base / "cache", **ELASTIC)[0]
    np.testing.assert_array_equal(again.loading_force, res.loading_force)
    assert again.residual_depth == res.residual_depth


@pytest.fixture(scope="module")
def frictional(elastic):
    """The elastic fixture's problem with Coulomb friction (mu = 0.5), stopped at delta_c
    (``unload=False``), twice in one call: two ccx processes in parallel."""
    _, problem, _ = elastic
    return indent(
        AISI_1010,
        delta_max=[problem.delta_max, problem.delta_max],
        mu=0.5,
        unload=False,
        use_cache=False,
        workers=2,
        **ELASTIC,
    )


def test_repeatable_in_parallel(frictional):
    """The same run twice in one call, in two ccx processes at the same time: bit for bit."""
    a, b = frictional
    assert a.converged and b.converged, (a.status(), b.status())
    np.testing.assert_array_equal(a.loading_delta, b.loading_delta)
    np.testing.assert_array_equal(a.loading_force, b.loading_force)
    np.testing.assert_array_equal(a.contact_radius, b.contact_radius)
    for r in (a, b):  # nothing of an unloading that did not run
        assert r.unloading_force.size == 0 and r.dent_z.size == 0
        assert np.isnan(r.residual_depth)
        assert r.max_force == r.loading_force[-1]


def test_truncated_run_is_marked_not_converged(elastic):
    """A run that stops early is marked, with its last converged point, never truncated
    silently."""
    _, problem, base = elastic
    files = Path(base / "files" / "run0")
    dat = (files / "job.dat").read_text()
    cut = dat[: dat.index("and time  0.1000000E+01")]
    cut = cut[: cut.rindex("\n total force")]
    mesh = build_mesh(problem.mesh_spec())
    deck = problem.deck_spec(problem.mesh_spec())
    out = RunOutput(cut, (files / "job.sta").read_text(), 201, "*ERROR: too many cutbacks", 1.0)
    bad = assemble(problem, mesh, deck, out)
    assert not bad.converged
    assert bad.last_converged_delta < problem.delta_max
    assert np.isnan(bad.residual_depth)
    assert "NOT CONVERGED" in bad.status() and "too many cutbacks" in bad.status()
    # the same output read as a loading-only run: not converged either (it stops before 1.0)
    loading_only = make_problem(
        AISI_1010, AISI_1010, delta_max=problem.delta_max, unload=False, **ELASTIC
    )
    deck = loading_only.deck_spec(loading_only.mesh_spec())
    bad = assemble(loading_only, mesh, deck, out)
    assert not bad.converged and bad.last_converged_delta < problem.delta_max
    assert "NOT CONVERGED" in bad.status()


def _replaying_ccx(folder: Path, files: Path, cut_at: int | None) -> str:
    """A stand-in ``ccx`` that answers ``-v`` with CalculiX's own and, for a run, puts the
    real run's ``job.dat`` and ``job.sta`` from ``files`` in its place (the same problem's
    deck), the ``.dat`` cut at a line's end ``cut_at`` lines into its last surface block."""
    exe = folder / "ccx"
    cut = (
        ""
        if cut_at is None
        else f"{sys.executable} - <<'PY'\n"
        "lines = open('job.dat').read().split('\\n')\n"
        "last = [i for i, l in enumerate(lines) if 'for set NFSURF and time' in l][-1]\n"
        f"open('job.dat', 'w').write('\\n'.join(lines[: last + {cut_at}]) + '\\n')\n"
        "PY\n"
    )
    exe.write_text(
        "#!/bin/sh\n"
        f'if [ "$1" = "-v" ]; then exec {shutil.which("ccx")} -v; fi\n'
        f"cp {files}/job.dat {files}/job.sta .\n{cut}exit 0\n"
    )
    exe.chmod(0o755)
    return str(exe)


def test_a_real_run_cut_inside_its_last_block_is_refused(elastic, tmp_path, monkeypatch):
    """CalculiX's own output (the elastic run's), cut at a line's end 40 lines into its last
    surface block (read before as a converged run): refused, nothing cached; the whole
    output, through the same stand-in, is read as the run itself."""
    res, problem, base = elastic
    files = base / "files" / "run0"
    monkeypatch.setenv("IMPACTLAB_CCX", _replaying_ccx(tmp_path, files, 40))
    with pytest.raises(DamagedRunsError, match=r"set NFSURF at time 2 has 38 rows where 79 are "):
        indent(AISI_1010, delta_max=problem.delta_max, cache_dir=tmp_path / "cut", **ELASTIC)
    assert not list((tmp_path / "cut").glob("*.npz"))
    monkeypatch.setenv("IMPACTLAB_CCX", _replaying_ccx(tmp_path, files, None))
    (whole,) = indent(AISI_1010, delta_max=problem.delta_max, cache_dir=tmp_path / "w", **ELASTIC)
    assert whole.converged and len(list((tmp_path / "w").glob("*.npz"))) == 1
    np.testing.assert_array_equal(whole.loading_force, res.loading_force)
    np.testing.assert_array_equal(whole.dent_z, res.dent_z)


def test_friction_stiffens_the_elastic_loading_slightly(elastic, frictional):
    """Coulomb friction (mu = 0.5) against the frictionless run of the same rigid sphere on
    the elastic flat (same mesh and increments): friction restrains the flat's surface from
    moving inwards under the sphere, so the force at a given interference is a little higher,
    by a few per cent for nu = 0.3 (Spence's finite-friction Hertz problem); never lower.
    Loading only: the frictional unloading (four fifths of a complete run's iterations) is not
    what this checks."""
    res0, _, _ = elastic
    res = frictional[0]
    assert res.converged, res.status()
    np.testing.assert_allclose(res.loading_delta, res0.loading_delta, rtol=1e-12)
    ratio = res.loading_force[1:] / res0.loading_force[1:]
    assert np.all(ratio > 0.999)
    assert 1.0 < ratio[-1] < 1.08
    assert np.all(np.diff(res.loading_force) > 0.0)


def test_paper_pair_plastic_smoke(tmp_path):
    """The paper's pair (both elastic-plastic) to 10 delta_c: a dent, a stiffer-than-Hertz
    flattening, and a contact radius beyond Hertz's."""
    probe = make_problem(AISI_1010, AISI_201, radius=R, delta_max=1e-6)
    res = indent(AISI_1010, AISI_201, radius=R, delta_max=10 * probe.delta_c, cache_dir=tmp_path)[0]
    assert res.converged, res.status()
    assert 0.02 < res.residual_ratio < 0.6
    # delta_r (the final gap) lies between the last unloading point that still carries force
    # and the first one that does not
    carries = res.unloading_force > 1e-6 * res.max_force
    k = int(np.argmin(carries))
    lo, hi = res.unloading_delta[k], res.unloading_delta[k - 1]
    assert lo - 1e-3 * res.delta_max <= res.residual_depth <= hi + 1e-3 * res.delta_max
    f_hertz = 4.0 / 3.0 * probe.E_star * np.sqrt(R) * res.delta_max**1.5
    assert res.max_force < f_hertz
    assert res.contact_radius[-1] > np.sqrt(R * res.delta_max)
    assert res.force_balance < 1e-6


@pytest.mark.slow
@LONG
def test_hertz_level_3_within_half_percent(tmp_path):
    problem = make_problem(AISI_1010, AISI_1010, delta_max=1e-6, **ELASTIC)
    res = indent(AISI_1010, delta_max=problem.delta_c, mesh_level=3, cache_dir=tmp_path, **ELASTIC)[
        0
    ]
    keep = res.loading_delta >= 0.1 * res.delta_c
    err = res.loading_force[keep] / hertz(res, problem)[keep] - 1.0
    assert np.max(np.abs(err)) < 0.005


@pytest.mark.slow
@LONG
def test_mesh_convergence_at_1000_delta_c(tmp_path):
    """Mesh levels 1 and 2 at 1000 delta_c (the paper's pair): force and delta_r within 2 %."""
    probe = make_problem(AISI_1010, AISI_201, radius=R, delta_max=1e-6)
    d = 1000 * probe.delta_c
    a, b = (
        indent(AISI_1010, AISI_201, radius=R, delta_max=d, mesh_level=lvl, cache_dir=tmp_path)[0]
        for lvl in (1, 2)
    )
    assert a.converged and b.converged
    assert abs(a.max_force / b.max_force - 1.0) < 0.02
    assert abs(a.residual_depth / b.residual_depth - 1.0) < 0.02
