"""The worked examples in examples/*.py run as the documentation says: each in a fresh
subprocess (sharing this test run's numba cache, warmed once, and with MPLBACKEND=Agg), writing
only into the folder it is given, and printing its key numbers. Each example runs once
(``example_run``): the figures that the documentation quotes from the worked analysis are checked
against that same run (the tests that take the ``example`` fixture)."""

from __future__ import annotations

import importlib
import json
import math
import os
import re
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

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


@dataclass(frozen=True)
class ExampleRun:
    """One run of an example script: its process, the folder it was given and its cwd."""

    proc: subprocess.CompletedProcess[str]
    out: Path
    cwd: Path


@pytest.fixture(scope="module")
def example_run(tmp_path_factory: pytest.TempPathFactory) -> Callable[[str], ExampleRun]:
    """``example_run(script)``: the script run as ``python examples/SCRIPT OUT`` in a fresh
    subprocess with an empty cwd, once per module (the tests that read its output share it).
    Called from a test or a function-scoped fixture, after the autouse ``warm_engine``."""
    runs: dict[str, ExampleRun] = {}

    def run(script: str) -> ExampleRun:
        if script not in runs:
            base = tmp_path_factory.mktemp(Path(script).stem)
            out = base / "out"
            cwd = base / "cwd"
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
            runs[script] = ExampleRun(proc, out, cwd)
        return runs[script]

    return run


@pytest.mark.parametrize("script", sorted(CASES))
def test_example_runs(script: str, example_run: Callable[[str], ExampleRun]) -> None:
    modules, patterns, files = CASES[script]
    reason = _missing(modules)
    if reason is not None:
        pytest.skip(f"{script} needs {reason}")
    run = example_run(script)
    proc, out, cwd = run.proc, run.out, run.cwd
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


# -- The figures that the documentation quotes from the worked analysis
# (``examples/analyze_experiment.py``: a synthetic 20 deg drop, its marker file and dent scan)
# are the ones the example prints now: the summary table of docs/tutorials/analyze.md,
# docs/experiment.md and the notebook page, the notebook page's ``T = ..., F = ...`` line and
# result repr, and experiment.md's rounded T and F and their distance from the inversion of the
# true inputs. They read the same run as test_example_runs, so that a change to the marker fits, the
# scan analysis or the inversion cannot leave a page's numbers stale.

#: the pages that quote the example's summary table
PAGES = ("docs/tutorials/analyze.md", "docs/experiment.md", "docs/notebooks/analyze_experiment.md")
#: the figures each of these pages must quote (so that a page that stops matching the pattern
#: below fails instead of passing with nothing checked)
QUOTED = ("e", "mu", "delta_p", "sliding_length", "duration", "mean_force")

# one estimate as ``str(Estimate)`` prints it: value, optional "± sigma", optional unit
_ESTIMATE = r"(-?\d[\d.e+-]*(?: ± \d[\d.e+-]*)?(?: [a-zA-Z/]+\b)?)"
_TF = re.compile(r"T = (\d[\d.]*) ms ± (\d[\d.]*), F = (\d[\d.]*) N ± (\d[\d.]*)")


@pytest.fixture
def example(
    warm_engine: None, example_run: Callable[[str], ExampleRun]
) -> tuple[str, dict[str, Any]]:
    """The worked analysis's printed output and its ``results.json``, from its one run."""
    reason = _missing(CASES["analyze_experiment.py"][0])
    if reason is not None:
        pytest.skip(f"the example reads an X3P scan: {reason}")
    run = example_run("analyze_experiment.py")
    assert run.proc.returncode == 0, run.proc.stdout[-3000:] + run.proc.stderr[-3000:]
    results = json.loads((run.out / "results" / "results.json").read_text())
    return run.proc.stdout, results


def _table(text: str, names: list[str]) -> dict[str, str]:
    """name -> the estimate quoted on a line that starts with the name (a summary table)."""
    found: dict[str, str] = {}
    for name in names:
        m = re.search(rf"^{re.escape(name)}\s+{_ESTIMATE}", text, flags=re.MULTILINE)
        if m is not None:
            found[name] = m.group(1)
    return found


def _code(page: str) -> str:
    """The text of a page's fenced code blocks (where the example's output is quoted)."""
    text = (ROOT / page).read_text(encoding="utf-8")
    return "\n".join(re.findall(r"^```[a-z]*\n(.*?)^```", text, flags=re.MULTILINE | re.DOTALL))


@pytest.mark.parametrize("page", PAGES)
def test_summary_tables_quote_the_examples_output(
    page: str, example: tuple[str, dict[str, Any]]
) -> None:
    printed, results = example
    names = list(results["summary"])
    now = _table(printed, names)
    assert set(now) == set(names), (sorted(set(names) - set(now)), printed)
    quoted = _table(_code(page), names)
    lost = sorted(set(QUOTED) - set(quoted))
    assert not lost, f"{page} no longer quotes {lost}"
    stale = {name: (text, now[name]) for name, text in quoted.items() if text != now[name]}
    assert not stale, f"{page}: quoted -> printed now: {stale}"


def test_notebook_page_quotes_the_examples_t_and_f(example: tuple[str, dict[str, Any]]) -> None:
    printed, results = example
    now = _TF.search(printed)
    assert now is not None, printed
    page = (ROOT / "docs/notebooks/analyze_experiment.md").read_text(encoding="utf-8")
    quoted = _TF.findall(page)
    assert quoted and all(q == now.groups() for q in quoted), (quoted, now.groups())
    # the result's repr: each value with 6 significant digits
    shown = re.search(r"^ExperimentResult\(.*$", page, flags=re.MULTILINE)
    assert shown is not None, "the page no longer shows the result's repr"
    for name in ("sliding_length", "duration", "mean_force"):
        m = re.search(rf"\b{name}=(-?\d[\d.e+-]*)", shown.group(0))
        assert m is not None, name
        assert m.group(1) == f"{results['summary'][name]['value']:.6g}", name


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")  # mu against mu_c
def test_experiment_page_rounds_and_compares_as_printed(
    example: tuple[str, dict[str, Any]],
) -> None:
    """experiment.md: "T = 4.15 ms and F = 69 N", the true inputs' T and F and the distance
    of the measured ones from them in sigma."""
    from impactlab.analytic import invert

    summary = example[1]["summary"]
    T, F = summary["duration"], summary["mean_force"]
    true = invert(
        angle=math.radians(20.0),
        v_i=-1.41,
        e=0.5,
        mu=0.2,
        delta_p=22e-6,
        sliding_length=1400e-6,
    )
    text = " ".join((ROOT / "docs/experiment.md").read_text(encoding="utf-8").split())
    sigma = "\N{GREEK SMALL LETTER SIGMA}"
    claim = (
        f"T = {T['value'] * 1e3:.2f} ms and F = {F['value']:.0f} N are of the order of the "
        f"paper's Table 2 (4.30 ms, 79 N) for its 20° drop; with the true inputs the inversion "
        f"gives T = {true.duration * 1e3:.2f} ms and F = {true.mean_force:.1f} N (the measured "
        f"values differ by {abs(T['value'] - true.duration) / T['sigma']:.1f}{sigma} and "
        f"{abs(F['value'] - true.mean_force) / F['sigma']:.1f}{sigma}"
    )
    assert claim in text, claim
