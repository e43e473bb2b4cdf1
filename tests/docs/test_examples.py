"""The worked examples in examples/*.py run as the documentation says: each in a fresh
subprocess (sharing this test run's numba cache, warmed once, and with MPLBACKEND=Agg), writing
only into the folder it is given, and printing its key numbers."""

from __future__ import annotations

import importlib
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"

# script -> (modules it needs, regular expressions its output must contain, files it must write)
CASES: dict[str, tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]] = {
    "simulate_impact.py": (
        ("impactlab.dynamics",),
        (
            r"ghaednia\s+coulomb\s+slip\s+0\.42\d",
            r"brake\s+mindlin\s+\w+\s+0\.4\d",
            r"ghaednia/coulomb: e = 0\.42\d\d, delta_p = 6\d\.\d\d um",
        ),
        ("force_time.png",),
    ),
    "invert_dent.py": (
        ("impactlab.analytic", "impactlab.paper.data"),
        (
            r"\s20\s+0\.263\s+4\.106 ± 0\.\d+\s+4\.30",
            r"\s45\s+0\.221\s+1\.382 ± 0\.\d+\s+1\.40",
            r"T = 4\.106 ms \(paper's method\), 4\.049 ms \(gravity",
        ),
        ("inversion.json",),
    ),
    "analyze_experiment.py": (
        ("impactlab.experiment", "impactlab.testing", "ezc3d", "SurfaceTopography"),
        (
            r"e\s+0\.5\d+ ± 0\.0\d+\s+0\.5",
            r"T = 4\.\d\d\d ms ± 0\.\d+, F = \d\d\.\d\d N",
            r"results: dent\.png, kinematics\.png, results\.json",
        ),
        ("drop.c3d", "dent.x3p", "markers.toml", "results/results.json"),
    ),
    "sweep_study.py": (
        ("impactlab.sweep", "zarr"),
        (
            r"sweep: 1089 cases in \d+ chunks",
            r"resume: \d+ chunks already done, 0 computed",
            r"e at 20 deg, mu = 0\.2: 0\.42\d\d",
        ),
        ("regime-map.zarr", "regime_map.png", "regime-map.nc"),
    ),
    "reproduce_paper.py": (
        ("impactlab.paper", "impactlab.paper.reproduction"),
        (
            r"20 deg: T = 4\.106 ms, published 4\.30 ms \(-4\.5%\)",
            r"45 deg: T = 1\.382 ms, published 1\.40 ms",
            r"simulations: 18\b",
        ),
        ("reproduction/report.html", "reproduction/table2.csv", "reproduction/fig5_alpha.png"),
    ),
}


#: The optional extras (``pyproject.toml``'s optional-dependencies) an example may skip for;
#: impactlab's own modules and its required dependencies are imported plainly: a failure fails.
OPTIONAL = frozenset({"SurfaceTopography", "netCDF4", "gmsh"})


def _missing(modules: tuple[str, ...]) -> str | None:
    for name in modules:
        if name not in OPTIONAL:
            importlib.import_module(name)
            continue
        try:
            importlib.import_module(name)
        except ImportError as exc:
            return f"{name} (an optional extra) is not importable ({exc})"
    return None


def test_only_optional_extras_may_skip_an_example(monkeypatch: pytest.MonkeyPatch) -> None:
    with pytest.raises(ImportError):
        _missing(("impactlab.no_such_module",))
    monkeypatch.setattr(sys.modules[__name__], "OPTIONAL", frozenset({"no_such_extra"}))
    reason = _missing(("no_such_extra",))
    assert reason is not None and reason.startswith("no_such_extra (an optional extra)")


def test_every_example_is_tested() -> None:
    assert sorted(p.name for p in EXAMPLES.glob("*.py")) == sorted(CASES)


@pytest.mark.parametrize("script", sorted(CASES))
def test_example_docstring_says_what_it_shows(script: str) -> None:
    text = (EXAMPLES / script).read_text()
    assert text.startswith('"""') and "What it shows" in text
    tutorial = re.search(r"Tutorial: (docs/tutorials/\w+\.md)", text)
    assert tutorial is not None and (ROOT / tutorial.group(1)).exists()


@pytest.mark.parametrize("script", sorted(CASES))
def test_example_runs(script: str, tmp_path: Path, request: pytest.FixtureRequest) -> None:
    modules, patterns, files = CASES[script]
    reason = _missing(modules)
    if reason is not None:
        pytest.skip(f"{script} needs {reason}")
    request.getfixturevalue("warm_engine")
    out = tmp_path / "out"
    cwd = tmp_path / "cwd"
    cwd.mkdir()
    env = dict(os.environ)
    env["MPLBACKEND"] = "Agg"
    env.pop("IMPACTLAB_EXAMPLE_OUT", None)
    # NUMBA_CACHE_DIR: inherited, so the subprocess loads what warm_engine compiled. The
    # time limit only stops a hung script: the reproduction takes 1-2 minutes on an idle
    # 2-core machine and several times that on a busy one.
    proc = subprocess.run(
        [sys.executable, str(EXAMPLES / script), str(out)],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=1200,
    )
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    for pat in patterns:
        assert re.search(pat, proc.stdout), (pat, proc.stdout)
    for name in files:
        assert (out / name).exists(), (name, sorted(p.name for p in out.iterdir()))
    assert list(cwd.iterdir()) == []  # nothing written outside the given folder


def test_example_output_folder_from_environment(tmp_path: Path) -> None:
    env = dict(os.environ, MPLBACKEND="Agg", IMPACTLAB_EXAMPLE_OUT=str(tmp_path / "env-out"))
    proc = subprocess.run(
        [sys.executable, str(EXAMPLES / "invert_dent.py")],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "env-out" / "inversion.json").exists()
