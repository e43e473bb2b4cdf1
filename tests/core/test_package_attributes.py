"""``import impactlab as il`` gives the subpackages as attributes (``il.sweep``), imported on
first use so that the import stays quick, and its docstring's example runs as written."""

from __future__ import annotations

import subprocess
import sys

import pytest

import impactlab


@pytest.mark.parametrize("name", ["calibrate", "experiment", "fe", "paper", "sweep"])
def test_subpackages_are_attributes(name: str) -> None:
    assert getattr(impactlab, name).__name__ == f"impactlab.{name}"
    assert name in dir(impactlab)


def test_an_unknown_attribute_is_an_attribute_error() -> None:
    with pytest.raises(AttributeError, match="has no attribute 'sweeps'"):
        _ = impactlab.sweeps  # type: ignore[attr-defined]


def test_import_leaves_the_heavy_subpackages_out() -> None:
    code = "import sys, impactlab; print(sorted(m for m in ('impactlab.sweep', "
    code += "'impactlab.calibrate', 'impactlab.fe') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_the_docstrings_example_runs() -> None:
    doc = impactlab.__doc__ or ""
    lines = doc.split("::", 1)[1].split("\n\n")[1]
    namespace: dict[str, object] = {}
    exec(lines.replace("\n    ", "\n").strip(), namespace)
    assert 0.3 < namespace["r"].e < 0.5  # type: ignore[attr-defined]
