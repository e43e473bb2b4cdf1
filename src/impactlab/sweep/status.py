"""Status codes the sweep itself assigns: cases the engine never sees (rejected inputs) and
cases not computed yet. The engine's own codes are small non-negative integers
(``impactlab.dynamics.kernels.status``); these are kept apart.

A chunk without its completion marker (``.sweep/done/<k>``: cut short before it, or the marker
deleted) is computed again on resume; until then its cases read as not computed (status -1),
whatever its files hold, and its outputs read as no result (NaN; -1 for an integer output), in
``open_sweep``, an export, the uncertainty report and ``sweep info`` alike
(:func:`mask_undone`)."""

from __future__ import annotations

import enum
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np
import xarray as xr


class SweepStatus(enum.IntEnum):
    """A sweep status code with the sentence that explains it (``.message``)."""

    message: str

    def __new__(cls, code: int, message: str) -> SweepStatus:
        member = int.__new__(cls, code)
        member._value_ = code
        member.message = message
        return member

    NOT_RUN = (-1, "not computed (chunk missing: the sweep was interrupted)")
    BAD_MATERIAL = (
        101,
        "material rejected (impactlab.materials.Material: e.g. nu outside (-1, 0.5), S_y >= E, "
        "non-positive value)",
    )
    BAD_BODY = (
        102,
        "body rejected (impactlab.bodies: a non-positive length, radius, mass or inertia; a tip "
        "radius above half the length; a diameter wider than twice the tip radius, or mass and "
        "diameter more than 2 % off the density; both mass and density given)",
    )
    BAD_LAW = (103, "contact law rejected its parameters (outside the law's validity)")
    BAD_INPUT = (104, "non-finite kinematic input (angle, vx, vy, spin or mu)")


STATUS_NOT_RUN = int(SweepStatus.NOT_RUN)
STATUS_BAD_MATERIAL = int(SweepStatus.BAD_MATERIAL)
STATUS_BAD_BODY = int(SweepStatus.BAD_BODY)
STATUS_BAD_LAW = int(SweepStatus.BAD_LAW)
STATUS_BAD_INPUT = int(SweepStatus.BAD_INPUT)

#: code -> message of every sweep status code.
SWEEP_STATUS_MESSAGES: dict[int, str] = {int(s): s.message for s in SweepStatus}


def undone_cases(
    region: Sequence[slice], chunks: Sequence[int], shape: Sequence[int], done: Iterable[int]
) -> np.ndarray:
    """True for each case of ``region`` (a block of the case array of ``shape``, chunked by
    ``chunks``, chunk indices in C order) whose chunk is not among ``done``."""
    grid = tuple(-(-n // c) for n, c in zip(shape, chunks, strict=True))
    per_dim = [np.arange(s.start, s.stop) // c for s, c in zip(region, chunks, strict=True)]
    index = np.ravel_multi_index(tuple(np.ix_(*per_dim)), grid) if per_dim else np.zeros(())
    return ~np.isin(index, np.fromiter(done, dtype=np.int64))


def mask_undone(ds: xr.Dataset, done: Iterable[int]) -> xr.Dataset:
    """``ds`` with every case outside the chunks ``done`` (the store's chunking: ``status``'s
    Zarr chunks; indices outside the chunk grid are ignored) read as not computed, lazily,
    block by block for a Dask-backed Dataset: ``status`` -1, and every other variable over the
    cases NaN (-1 for an integer one: ``regime``, ``n_steps``, ``flags``); ``ds`` itself when
    every chunk is done."""
    if "status" not in ds.data_vars:
        return ds
    status = ds["status"]
    shape = tuple(int(n) for n in status.shape)
    chunks = tuple(int(c) for c in status.encoding.get("chunks") or shape)
    grid = [-(-n // c) for n, c in zip(shape, chunks, strict=True)]
    n_chunks = int(np.prod(grid, dtype=np.int64))
    done = sorted(k for k in set(done) if 0 <= k < n_chunks)
    if len(done) >= n_chunks:
        return ds
    masked = {
        str(name): var.copy(data=_masked_data(var.data, chunks, shape, done))
        for name, var in ds.data_vars.items()
        if var.dims == status.dims and var.dtype.kind in "fci"
    }
    return ds.assign(masked)


def _masked_data(data: Any, chunks: Sequence[int], shape: Sequence[int], done: list[int]) -> Any:
    """``data`` (a NumPy or Dask array over the cases) with the cases outside the chunks
    ``done`` set to NaN (floats) or -1 (integers)."""
    fill = np.nan if np.dtype(data.dtype).kind in "fc" else STATUS_NOT_RUN

    def masked(values: np.ndarray, region: Sequence[slice]) -> np.ndarray:
        undone = undone_cases(region, chunks, shape, done)
        return np.where(undone, fill, values).astype(values.dtype)

    def block(values: np.ndarray, block_info: Any = None) -> np.ndarray:
        region = [slice(a, b) for a, b in block_info[0]["array-location"]]
        return masked(values, region)

    if hasattr(data, "map_blocks"):  # dask
        return data.map_blocks(block, dtype=data.dtype)
    return masked(np.asarray(data), [slice(0, n) for n in shape])
