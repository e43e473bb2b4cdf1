"""A sweep's Dataset as a file: NetCDF-4 (``.nc``, ``.nc4``: every variable and attribute) or a
CSV table (``.csv``: one row per case, every input and output a column, its unit in the
header, ``e_energy``, ``delta_p [m]``, ``angle [rad]``, in a fixed order). ``export_file``
chooses by the suffix and refuses any other. Each takes the Dataset, a store's path (opened with
``open_sweep``) or ``run_sweep``'s result. An existing file is replaced only when a sweep
export wrote it (recognised by its header or attributes), never a user's. Both read a store a
part at a time: their memory does not grow with the number of cases."""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from impactlab._validation import MissingExtraError
from impactlab.sweep.filewrite import library_write_error, write_atomic
from impactlab.sweep.inputs import INPUTS
from impactlab.sweep.slabs import slabs, store_chunks

if TYPE_CHECKING:
    from impactlab.sweep.run_result import SweepResult

__all__ = [
    "CSV_BLOCK_CASES",
    "EXPORT_SUFFIXES",
    "NETCDF_CHUNK_CACHE_BYTES",
    "NETCDF_COMPLEVEL",
    "as_dataset",
    "check_replaceable",
    "export_csv",
    "export_file",
    "export_netcdf",
    "exported",
]

#: The suffixes of the files a sweep exports to, and their format.
EXPORT_SUFFIXES = {".csv": "CSV", ".nc": "NetCDF-4", ".nc4": "NetCDF-4"}

#: Cases per block of a CSV export: its memory holds one block's table (about 1.5 kB a case,
#: so about 100 MB) whatever the size of the store.
CSV_BLOCK_CASES = 65_536

#: The zlib level (1-9) of a NetCDF export's numeric arrays.
NETCDF_COMPLEVEL = 4

#: The HDF5 chunk cache of each array a NetCDF export writes (bytes; the library's default,
#: 64 MiB an array, would hold a store of a few million cases whole until the file closes).
NETCDF_CHUNK_CACHE_BYTES = 4 * 2**20


def check_suffix(
    path: str | Path, name: str, formats: tuple[str, ...] = ("CSV", "NetCDF-4")
) -> str:
    """The format of ``path`` by its suffix (:data:`EXPORT_SUFFIXES`, among ``formats``);
    ValueError naming ``name`` (how the user gave the path) and the suffixes allowed."""
    p = Path(path)
    if p.name.lower() in EXPORT_SUFFIXES:  # ".csv": a suffix only, which Path reads as a name
        raise ValueError(
            f"{name} {str(p)!r} needs a name before its suffix, e.g. "
            f"{str(p.with_name('out' + p.name))!r}"
        )
    kind = EXPORT_SUFFIXES.get(p.suffix.lower())
    if kind not in formats:
        allowed = ", ".join(
            " or ".join(s for s, k in EXPORT_SUFFIXES.items() if k == f) + f" ({f})"
            for f in formats
        )
        raise ValueError(f"{name} {str(p)!r} must end in {allowed}")
    return str(kind)


#: The columns every CSV table of a sweep has (its category inputs and the status).
_CSV_MARK = ("status", "body", "body_material", "flat_material", "law", "friction")
#: The attributes every NetCDF file of a sweep has (a store's root attributes).
_NETCDF_MARK = ("sweep_format", "study_hash")


def exported(path: str | Path) -> bool:
    """Whether the file ``path`` is one a sweep export wrote: a CSV table whose header holds the
    columns :data:`_CSV_MARK`, a NetCDF file with the attributes :data:`_NETCDF_MARK`. An empty
    file counts as one (nothing to lose); a file that cannot be read does not."""
    p = Path(path)
    try:
        if p.stat().st_size == 0:
            return True
        if p.suffix.lower() == ".csv":
            with p.open(encoding="utf-8", newline="") as fh:
                head = fh.readline(1 << 16).rstrip("\r\n").split(",")
            return set(_CSV_MARK) <= {c.partition(" [")[0] for c in head}
        import netCDF4

        with netCDF4.Dataset(p) as nc:
            return set(_NETCDF_MARK) <= set(nc.ncattrs())
    except (OSError, ValueError, ImportError):
        return False


def check_replaceable(path: str | Path, name: str) -> None:
    """ValueError when ``path`` (given as ``name``) is an existing file that no sweep export
    wrote (:func:`exported`): a user's file is never written over."""
    p = Path(path)
    if p.is_file() and not exported(p):
        raise ValueError(
            f"{name} {str(p)!r} exists and was not written by an impactlab sweep export: it is "
            "left as it is (remove it, or choose another name)"
        )


def as_dataset(ds: Any, name: str = "ds") -> xr.Dataset:
    """``ds`` as a sweep's Dataset: a Dataset as it is, a store's path (str or Path) opened
    with ``open_sweep`` (verified), ``run_sweep``'s result by its ``dataset``; ValueError naming
    ``name`` for anything else."""
    if isinstance(ds, xr.Dataset):
        return ds
    if isinstance(ds, str | Path):
        from impactlab.sweep.store import open_sweep  # the store module writes; read on demand

        return open_sweep(ds)
    inner = getattr(ds, "dataset", None) if hasattr(type(ds), "dataset") else None
    if isinstance(inner, xr.Dataset):
        return inner
    raise ValueError(
        f"{name} must be an xarray.Dataset (open a store with open_sweep(path)) or a sweep "
        f"store's path, got the {type(ds).__name__} {ds!r}"
    )


def export_file(ds: xr.Dataset | str | Path | SweepResult, path: str | Path) -> Path:
    """Write the Dataset (or the store at a path: :func:`as_dataset`) to ``path``: a CSV table
    for ``.csv``, NetCDF-4 for ``.nc``/``.nc4`` (ValueError for any other suffix, or for an
    existing file that no sweep export wrote: :func:`check_replaceable`)."""
    ds = as_dataset(ds)
    if check_suffix(path, "export file") == "CSV":
        return export_csv(ds, path)
    return export_netcdf(ds, path)


def require_netcdf() -> Any:
    """The netCDF4 module; :class:`~impactlab._validation.MissingExtraError` naming the extra
    to install where it is missing (the locked xarray raised a bare ModuleNotFoundError)."""
    try:
        import netCDF4
    except ImportError as exc:
        raise MissingExtraError(
            "NetCDF export needs the netCDF4 package, an optional extra: pip install "
            f"'impactlab[netcdf]' ({exc}); a CSV table needs none: impactlab sweep export "
            "STORE table.csv"
        ) from None
    return netCDF4


def export_netcdf(ds: xr.Dataset | str | Path | SweepResult, path: str | Path) -> Path:
    """Write the Dataset (or the store at a path: :func:`as_dataset`) to NetCDF-4 (strings
    kept; dictionary attributes become JSON text), its numeric arrays compressed (zlib level
    :data:`NETCDF_COMPLEVEL`, shuffled) in chunks of the store's; a store's arrays are read
    chunk by chunk, never whole. Written whole or not at all; ``path`` ends in ``.nc`` or
    ``.nc4``, and is no file that a sweep export did not write (ValueError:
    :func:`check_replaceable`)."""
    check_suffix(path, "NetCDF file", ("NetCDF-4",))
    require_netcdf()
    ds = as_dataset(ds)
    check_replaceable(path, "NetCDF file")
    out = Path(path)

    def attrs(a: Mapping[str, Any]) -> dict[str, Any]:
        return {k: json.dumps(v) if isinstance(v, dict) else v for k, v in a.items()}

    def plain(var: xr.Variable) -> xr.Variable:
        data = var.data
        if var.dtype.kind == "T":  # numpy StringDType -> fixed-width unicode (small: labels)
            data = np.array(var.values.tolist(), dtype=str)
        return xr.Variable(var.dims, data, attrs(var.attrs))

    coords = {str(k): plain(v.variable) for k, v in ds.coords.items()}
    data = {str(k): plain(v.variable) for k, v in ds.data_vars.items()}
    plain_ds = xr.Dataset(data, coords=coords, attrs=attrs(ds.attrs))
    encoding = _nc_encoding(plain_ds, _case_dims(ds), store_chunks(ds))
    write_atomic(out, lambda tmp: _write_netcdf(plain_ds, tmp, encoding))
    return out


def _write_netcdf(ds: xr.Dataset, path: Path, encoding: dict[str, dict[str, Any]]) -> None:
    """``ds.to_netcdf`` with a chunk cache of :data:`NETCDF_CHUNK_CACHE_BYTES` per array (the
    setting is the library's, restored after); the library's failure to write (a full disk)
    as an OSError (:func:`~impactlab.sweep.filewrite.library_write_error`)."""
    nc = require_netcdf()
    size, slots, preemption = nc.get_chunk_cache()
    nc.set_chunk_cache(NETCDF_CHUNK_CACHE_BYTES, slots, preemption)
    try:
        ds.to_netcdf(path, engine="netcdf4", encoding=encoding)
    except RuntimeError as exc:  # "NetCDF: HDF error" (a full disk): no errno of its own
        if not str(exc).startswith("NetCDF:"):
            raise
        raise library_write_error(exc, path, "the NetCDF library") from exc
    finally:
        nc.set_chunk_cache(size, slots, preemption)


def _nc_encoding(
    ds: xr.Dataset, dims: list[str], chunks: tuple[int, ...] | None
) -> dict[str, dict[str, Any]]:
    """The NetCDF-4 encoding of every numeric array of ``ds`` (zlib, shuffled; the case arrays
    in ``chunks``); scalars and strings as they are."""
    enc: dict[str, dict[str, Any]] = {}
    for name, var in ds.variables.items():
        if var.ndim == 0 or var.size == 0 or var.dtype.kind not in "biuf":
            continue
        e: dict[str, Any] = {"zlib": True, "complevel": NETCDF_COMPLEVEL, "shuffle": True}
        if chunks is not None and list(var.dims) == dims:
            e["chunksizes"] = tuple(min(c, n) for c, n in zip(chunks, var.shape, strict=True))
        enc[str(name)] = e
    return enc


def export_csv(ds: xr.Dataset | str | Path | SweepResult, path: str | Path) -> Path:
    """Write the Dataset (or the store at a path: :func:`as_dataset`) as a CSV table
    (``ds.to_dataframe()``): one row per case, a column per dimension, input and output, headed
    ``name [unit]`` (the variable's ``units``: SI but the Brinell hardness in kgf/mm^2; a
    dimensionless one by its name alone), in the order of :func:`_columns`. Written block by
    block (at most :data:`CSV_BLOCK_CASES` cases in memory; the file is that of the whole table
    at once), whole or not at all; ``path`` ends in ``.csv``, and is no file that a sweep
    export did not write (ValueError: :func:`check_replaceable`)."""
    ds = as_dataset(ds)
    check_suffix(path, "CSV file", ("CSV",))
    check_replaceable(path, "CSV file")
    out = Path(path)
    dims = _case_dims(ds)
    # a dimension without coordinate counts 0, 1, ... in every block: its place in the whole
    ds = ds.assign_coords({d: np.arange(ds.sizes[d]) for d in dims if d not in ds.coords})
    shape = tuple(int(ds.sizes[d]) for d in dims)

    def write(tmp: Path) -> None:
        with tmp.open("w", encoding="utf-8", newline="") as fh:
            names: list[str] = []
            for i, slab in enumerate(slabs(shape, CSV_BLOCK_CASES, store_chunks(ds))):
                block = ds.isel(dict(zip(dims, slab, strict=True))).load()
                table = block.to_dataframe(dim_order=dims).reset_index()
                if i == 0:
                    names = _columns(dims, ds.attrs.get("outputs", []), list(map(str, table)))
                table = table[names]
                table.columns = [_header(c, ds[c].attrs.get("units")) for c in names]
                table.to_csv(fh, index=False, header=i == 0)

    write_atomic(out, write)
    return out


def _case_dims(ds: xr.Dataset) -> list[str]:
    """The dimensions of the case array (``status``'s; the Dataset's without one)."""
    return [str(d) for d in (ds["status"].dims if "status" in ds else ds.dims)]


def _columns(dims: list[str], outputs: Any, present: list[str]) -> list[str]:
    """The columns of a CSV table in a fixed order, whatever order the store's variables come
    in: dimensions, outputs (the study's order), ``flags``, ``status``, then the inputs
    (``INPUTS`` order; any other name after them, sorted)."""
    head = [
        c for c in dict.fromkeys([*dims, *map(str, outputs), "flags", "status"]) if c in present
    ]
    rank = {name: i for i, name in enumerate(INPUTS)}
    rest = sorted(set(present) - set(head), key=lambda c: (rank.get(c, len(rank)), c))
    return [*head, *rest]


def _header(name: str, unit: Any) -> str:
    return name if unit in (None, "", "1", "-") else f"{name} [{unit}]"
