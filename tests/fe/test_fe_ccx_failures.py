"""How a failed or impossible ccx run is reported: the exit status named when ccx stops without
an ``*ERROR`` line (CalculiX 2.20 leaves spooles with status 255 on a plastic impact), and an
impact with a body that can yield refused before any run on CalculiX 2.20 or older (it stops
before the first increment: docs/fe-dynamic.md). A stand-in ccx (a shell script) replaces
CalculiX, except in the test that asks the installed ccx for its version only."""

from __future__ import annotations

import re
import shutil
import warnings
from pathlib import Path

import pytest

from impactlab.fe import impact_run
from impactlab.fe.ccx import _error_lines, ccx_version, run_ccx
from impactlab.fe.impact_problem import make_impact_problem
from impactlab.fe.impact_run import CCX_DOCS, check_ccx_release, impact
from impactlab.fe.run import NotConvergedWarning
from impactlab.materials import AISI_201, AISI_1010

R = 8.8e-3
SPOOLES = "Using up to 1 cpu(s) for spooles."
DOCS = Path(__file__).resolve().parents[2] / "docs"


def _fake_ccx(tmp_path: Path, version: str, exit_status: int) -> str:
    """A stand-in ccx: ``-v`` prints ``version``, a run prints spooles' line and exits."""
    exe = tmp_path / f"ccx-{version}-{exit_status}"
    exe.write_text(
        "#!/bin/sh\n"
        f'if [ "$1" = "-v" ]; then echo "This is Version {version}"; exit 0; fi\n'
        f'echo "{SPOOLES}"\n'
        f"exit {exit_status}\n"
    )
    exe.chmod(0o755)
    return str(exe)


def test_a_crash_without_an_error_line_names_the_exit_status():
    text = _error_lines(f"STEP 1\n{SPOOLES}\n", 255)
    assert text == (f"ccx exit status 255, no *ERROR message; its last output: STEP 1 {SPOOLES}")
    assert _error_lines("", 255) == "ccx exit status 255, no *ERROR message; its last output: none"
    assert "killed by signal 11 (SIGSEGV)" in _error_lines(SPOOLES, -11)


def test_an_error_line_comes_with_the_exit_status():
    log = (
        "increment 1\n*ERROR: too many cutbacks\nbest solution and residuals are in the frd file\n"
    )
    assert _error_lines(log, 201) == (
        "ccx exit status 201: *ERROR: too many cutbacks best solution and residuals are in the "
        "frd file"
    )
    assert _error_lines(log, 0).startswith("*ERROR: too many cutbacks")  # as before


def test_run_ccx_reports_the_exit_status(tmp_path):
    out = run_ccx("*HEADING\n", tmp_path / "run", _fake_ccx(tmp_path, "2.23", 255))
    assert out.returncode == 255
    assert out.log_tail.startswith("ccx exit status 255, no *ERROR message")
    assert SPOOLES in out.log_tail


def _problem(**kwargs):
    return make_impact_problem(AISI_1010, AISI_201, radius=R, speed=1.0, **kwargs)


@pytest.mark.parametrize(
    ("kwargs", "bodies"),
    [
        ({}, r"the flat \(flat_hardening not 'elastic'\) and the sphere"),
        ({"sphere": "elastic"}, r"in which the flat \(flat_hardening not 'elastic'\) can"),
        ({"flat_hardening": "elastic"}, r"in which the sphere \(sphere='elastic-plastic'\) can"),
    ],
)
@pytest.mark.parametrize("version", ["2.20", "2.19"])
def test_a_plastic_impact_is_refused_on_calculix_2_20(kwargs, bodies, version):
    with pytest.raises(RuntimeError, match=bodies) as info:
        check_ccx_release(version, "/usr/bin/ccx", [_problem(**kwargs)])
    text = str(info.value)
    assert "\n" not in text
    assert f"CalculiX {version} (/usr/bin/ccx)" in text
    assert "a CalculiX newer than 2.20 is needed, set through IMPACTLAB_CCX" in text
    assert CCX_DOCS in text


def test_what_calculix_2_20_runs_and_newer_releases_pass():
    elastic = _problem(sphere="elastic", flat_hardening="elastic")
    assert elastic.plastic_bodies == ()
    check_ccx_release("2.20", "ccx", [elastic])
    for version in ("2.21", "2.23+git3593817", "3.0", "unknown"):
        check_ccx_release(version, "ccx", [_problem()])


def test_the_message_points_at_a_section_that_exists():
    page, anchor = CCX_DOCS.split("#")
    headings = re.findall(r"^#+ (.+)$", (DOCS.parent / page).read_text(), flags=re.M)
    slugs = {re.sub(r"[^a-z0-9 -]", "", h.lower()).strip().replace(" ", "-") for h in headings}
    assert anchor in slugs


def test_impact_refuses_before_any_run(tmp_path, monkeypatch):
    """No mesh and no run: the stand-in would fail the test if it were started."""
    exe = _fake_ccx(tmp_path, "2.20", 255)
    monkeypatch.setenv("IMPACTLAB_CCX", exe)
    monkeypatch.setattr(impact_run, "build_mesh", lambda spec: pytest.fail("mesh built"))
    with pytest.raises(RuntimeError, match=r"newer than 2\.20"):
        impact(AISI_1010, AISI_201, radius=R, speed=1.0, cache_dir=tmp_path / "cache")


def test_impact_warning_names_the_exit_status(tmp_path, monkeypatch):
    """A newer ccx that crashes: the NotConvergedWarning says how it ended."""
    pytest.importorskip("gmsh", reason="impactlab.fe needs the gmsh package (the fe extra)")
    monkeypatch.setenv("IMPACTLAB_CCX", _fake_ccx(tmp_path, "2.23", 255))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        (res,) = impact(AISI_1010, AISI_201, radius=R, speed=1.0, cache_dir=tmp_path / "c")
    assert not res.converged
    assert "ccx exit status 255, no *ERROR message" in res.status()
    assert any(
        issubclass(w.category, NotConvergedWarning) and "exit status 255" in str(w.message)
        for w in caught
    )


@pytest.mark.skipif(shutil.which("ccx") is None, reason="ccx (CalculiX) is not installed")
def test_the_installed_calculix_2_20_is_refused_at_once(tmp_path, monkeypatch):
    monkeypatch.delenv("IMPACTLAB_CCX", raising=False)
    version = ccx_version(str(shutil.which("ccx")))
    if version != "2.20":
        pytest.skip(f"the installed ccx is {version}, not 2.20")
    with pytest.raises(RuntimeError, match=r"CalculiX 2\.20 .*newer than 2\.20"):
        impact(AISI_1010, AISI_201, radius=R, speed=1.0, cache_dir=tmp_path)
