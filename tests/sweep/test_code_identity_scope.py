"""The code identity of a store (``impactlab._code_identity``) covers the code that computes
a stored number and leaves out the modules that only present a result: editing those keeps a
store resumable, and none of their code runs while a sweep computes its cases."""

from __future__ import annotations

import shutil
import sys
import threading
from pathlib import Path

import pytest

import impactlab
from impactlab._code_identity import PRESENTATION, RESULT_SOURCES, result_files
from impactlab._compiled_cache import source_hash
from impactlab.sweep import Study, run_sweep

PACKAGE = Path(impactlab.__file__).resolve().parent


@pytest.fixture
def copy(tmp_path) -> Path:
    """The package's files of ``RESULT_SOURCES`` and ``PRESENTATION``, copied."""
    root = tmp_path / "pkg"
    for name in (*result_files(PACKAGE), *PRESENTATION):
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(PACKAGE / name, root / name)
    return root


def _hash(root: Path) -> str:
    return source_hash(root, result_files(root))


def test_every_left_out_module_is_a_module_of_the_folders_hashed() -> None:
    folders = [n for n in RESULT_SOURCES if (PACKAGE / n).is_dir()]
    for name in PRESENTATION:
        assert (PACKAGE / name).is_file(), name
        assert any(name.startswith(f"{f}/") for f in folders), name
        assert name not in result_files(PACKAGE)


@pytest.mark.parametrize("name", PRESENTATION)
def test_editing_a_presentation_module_keeps_the_identity(copy, name) -> None:
    before = _hash(copy)
    with (copy / name).open("a") as f:
        f.write("\n# a comment\n")
    assert _hash(copy) == before


@pytest.mark.parametrize("name", ["dynamics/batch.py", "bodies/rod.py", "materials/core.py"])
def test_editing_code_that_computes_changes_the_identity(copy, name) -> None:
    before = _hash(copy)
    with (copy / name).open("a") as f:
        f.write("\n# a comment\n")
    assert _hash(copy) != before


def test_no_presentation_code_runs_while_a_sweep_computes(tmp_path, engine) -> None:
    """The rigid, partial-slip and flexible-rod engines' sweeps, traced: no function of a
    module left out of the identity is called."""
    studies = [
        Study(
            name="rigid",
            grid={"friction": ["coulomb", "mindlin", "partial_slip"]},
            fixed={"angle": "30 deg", "mu": 0.3, "vy": -1.41, "law": "hertz"},
        ),
        Study(
            name="flexible",
            grid={"friction": ["coulomb", "partial_slip"]},
            fixed={"body": "flexible_rod", "angle": "30 deg", "mu": 0.3, "vy": -1.41},
            outputs=["e", "dent_depth", "max_force"],
        ),
    ]
    left_out = {str(PACKAGE / n) for n in PRESENTATION}
    called: set[str] = set()

    def trace(frame, event, arg):
        if event == "call" and frame.f_code.co_filename in left_out:
            called.add(frame.f_code.co_filename)

    threading.setprofile(trace)
    sys.setprofile(trace)
    try:
        for i, study in enumerate(studies):
            res = run_sweep(study, tmp_path / f"{i}.zarr", quiet=True)
            assert (res.dataset["status"].values == 0).all()
    finally:
        sys.setprofile(None)
        threading.setprofile(None)  # type: ignore[arg-type]
    assert called == set()
