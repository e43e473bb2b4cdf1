"""The engines' copies between work arrays (``dynamics.kernels.buffers``): the growing history
buffer keeps its rows, the element copy equals a slice assignment, and no engine source
assigns an array to a slice (numba would compile the shape-mismatch message in every cold
process, about 3.5 s of CPU per array rank)."""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

import impactlab
from impactlab._compiled_cache import ENGINE_SOURCES
from impactlab.dynamics.kernels.buffers import copy_into, grown


@given(rows=st.integers(1, 40), cols=st.integers(1, 9), extra=st.integers(0, 70), data=st.data())
def test_grown_keeps_the_first_rows_and_doubles(rows: int, cols: int, extra: int, data) -> None:
    n = data.draw(st.integers(0, rows))
    hist = np.random.default_rng(rows * 100 + cols).standard_normal((rows, cols))
    new = grown(hist, n, extra)
    assert new.shape == (2 * rows + extra, cols)
    np.testing.assert_array_equal(new[:n], hist[:n])


@given(st.lists(st.floats(allow_nan=False), min_size=0, max_size=50))
def test_copy_into_is_the_slice_assignment(values: list[float]) -> None:
    src = np.array(values, dtype=np.float64)
    dst = np.full(src.size, np.nan)
    copy_into(dst, src)
    assert dst.tobytes() == src.tobytes()
    k = np.arange(3.0 * max(src.size, 1)).reshape(3, -1)
    copy_into(k[0], k[2])  # a row of a 2-d work array, as the drivers copy K[6] to K[0]
    np.testing.assert_array_equal(k[0], k[2])


def _slice_assignments_of_names(path: Path) -> list[str]:
    """``a[...:...] = b`` with ``b`` a bare name or subscript (an array, in the engine's code)."""
    return [
        f"{path.parent.name}/{path.name}:{node.lineno}"
        for node in ast.walk(ast.parse(path.read_text()))
        if isinstance(node, ast.Assign) and isinstance(node.value, (ast.Name, ast.Subscript))
        for target in node.targets
        if isinstance(target, ast.Subscript)
        and any(isinstance(s, ast.Slice) for s in ast.walk(target.slice))
    ]


def test_no_engine_source_assigns_an_array_to_a_slice() -> None:
    package = Path(impactlab.__file__).parent
    files: list[Path] = []
    for name in ENGINE_SOURCES:
        path = package / name
        files.extend(sorted(path.rglob("*.py")) if path.is_dir() else [path])
    found = [hit for f in files for hit in _slice_assignments_of_names(f)]
    assert not found, f"use kernels.buffers.copy_into / grown instead of a slice copy: {found}"
