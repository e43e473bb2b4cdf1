"""The Zarr store of a sweep: layout, per-chunk writes, completion markers and the study hash.

Layout of ``<store>`` (a Zarr v3 group that ``xarray.open_zarr`` reads):

- one coordinate array per grid axis (SI values, ``units`` attribute);
- the sampled inputs as variables along ``sample`` (written with the chunks that cover them);
- fixed inputs as scalar coordinates;
- one array per kept output and ``status`` (int32; -1 = not computed), chunked exactly like the
  work: each work chunk is one Zarr chunk of every array, so no two chunks ever share a file;
- ``.sweep/study.json``: the canonical study; ``.sweep/done/<k>``: the completion marker of chunk
  ``k``, created atomically (write to a temporary name, then rename) after all of the chunk's
  arrays are written. A chunk without a marker is computed again on resume and its files
  overwritten; one with a marker is never touched again.

The root attributes hold the study hash; opening a store with a different study is refused unless
the caller asks to start it fresh.
"""

from __future__ import annotations

import json
import os
import shutil
import socket
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr
import zarr
from zarr.codecs import BloscCodec

from impactlab.sweep.dimensions import SAMPLE_DIM
from impactlab.sweep.engine import SWEEP_STATUS_MESSAGES
from impactlab.sweep.inputs import INPUTS, INTEGER_OUTPUTS, get_input, output_spec
from impactlab.sweep.options import STUDY_FORMAT
from impactlab.sweep.study import Study

_META = ".sweep"


def _alive(pid: int) -> bool:
    """True if a process with this id exists on this host."""
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _compressors() -> Any:
    """Blosc-LZ4 with byte shuffle: 2-3x faster to write than Zarr's default zstd at a similar
    ratio on smooth sweep data (measured: 1.5 vs 3.3 ms per 60k-value chunk), which keeps the
    writes a small fraction of the kernel time."""
    return [BloscCodec(cname="lz4", clevel=5, shuffle="shuffle")]


class StudyMismatchError(ValueError):
    """The store was written by a different study."""


@dataclass(frozen=True)
class StoreMeta:
    """What the store records besides the data (root attributes)."""

    study_hash: str
    outputs: tuple[str, ...]
    integer_outputs: tuple[str, ...]
    status_messages: Mapping[int, str]
    regimes: Mapping[int, str]
    engine: str


def _attrs_units(name: str) -> dict[str, Any]:
    spec = get_input(name)
    d: dict[str, Any] = {"long_name": spec.description}
    if spec.unit:
        d["units"] = spec.unit
    return d


def _create_axes(g: Any, study: Study) -> None:
    """One coordinate array per grid axis."""
    for axis in study.axes:
        arr = axis.array()
        if axis.is_category:
            z = g.create_array(
                axis.name,
                shape=arr.shape,
                chunks=arr.shape,
                dtype=str,
                fill_value="",
                dimension_names=(axis.name,),
                attributes=_attrs_units(axis.name),
            )
            z[:] = np.array(arr, dtype=str)
        else:
            z = g.create_array(
                axis.name,
                shape=arr.shape,
                chunks=arr.shape,
                dtype="float64",
                fill_value=np.nan,
                dimension_names=(axis.name,),
                attributes=_attrs_units(axis.name),
            )
            z[:] = arr


def _create_sampled(g: Any, study: Study) -> list[str]:
    """The sampled inputs along ``sample`` (filled by the chunk writes); returns their names."""
    if study.sample is None:
        return []
    c = study.layout.chunks[-1]
    for name in study.sample.inputs:
        g.create_array(
            name,
            shape=(study.sample.size,),
            chunks=(c,),
            dtype="float64",
            fill_value=np.nan,
            dimension_names=(SAMPLE_DIM,),
            compressors=_compressors(),
            attributes={
                **_attrs_units(name),
                "distribution": json.dumps(study.sample.inputs[name].to_dict()),
            },
        )
    return list(study.sample.inputs)


def _create_constants(g: Any, study: Study) -> list[str]:
    """The fixed (and defaulted) inputs as scalar arrays; returns their names."""
    varying = set(study.varying())
    constants = {n: study.value_of(n) for n in INPUTS if n not in varying}
    names = []
    for name, value in sorted((n, v) for n, v in constants.items() if v is not None):
        if isinstance(value, str):
            z = g.create_array(
                name,
                shape=(),
                dtype=str,
                fill_value="",
                dimension_names=(),
                attributes=_attrs_units(name),
            )
        else:
            z = g.create_array(
                name,
                shape=(),
                dtype="float64",
                fill_value=np.nan,
                dimension_names=(),
                attributes=_attrs_units(name),
            )
        z[...] = value
        names.append(name)
    return names


def _create_output(
    g: Any,
    name: str,
    meta: StoreMeta,
    shape: tuple[int, ...],
    chunks: tuple[int, ...],
    dims: tuple[str, ...],
) -> None:
    """The array of one kept output, chunked like the work; unit and meaning from the schema."""
    spec = output_spec(name)
    attrs: dict[str, Any] = {"units": spec.unit, "long_name": spec.description}
    fill: float
    if name in meta.integer_outputs:
        dtype, fill = INTEGER_OUTPUTS.get(name, "int32"), -1
        if name == "regime" and meta.regimes:
            attrs["regimes"] = {str(k): v for k, v in meta.regimes.items()}
            attrs["flag_values"] = sorted(meta.regimes)
            attrs["flag_meanings"] = " ".join(
                meta.regimes[k].replace(" ", "_") for k in sorted(meta.regimes)
            )
    else:
        dtype, fill = "float64", np.nan
    g.create_array(
        name,
        shape=shape,
        chunks=chunks,
        dtype=dtype,
        fill_value=fill,
        dimension_names=dims,
        attributes=attrs,
        compressors=_compressors(),
    )


class SweepStore:
    """A sweep's Zarr store on the local file system."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)

    # -- paths / markers -------------------------------------------------------------------------

    @property
    def _meta(self) -> Path:
        return self.path / _META

    @property
    def _done_dir(self) -> Path:
        return self._meta / "done"

    def exists(self) -> bool:
        return (self.path / "zarr.json").is_file() and (self._meta / "study.json").is_file()

    def done_chunks(self) -> set[int]:
        """Indices of the chunks whose completion marker exists."""
        if not self._done_dir.is_dir():
            return set()
        out = set()
        for p in self._done_dir.iterdir():
            if p.name.isdigit():
                out.add(int(p.name))
        return out

    def mark_done(self, index: int) -> None:
        """Create chunk ``index``'s completion marker atomically."""
        final = self._done_dir / str(index)
        tmp = self._done_dir / f".{index}.{os.getpid()}.tmp"
        tmp.write_text(f"{index}\n")
        os.replace(tmp, final)

    def attrs(self) -> dict[str, Any]:
        return dict(zarr.open_group(str(self.path), mode="r").attrs)

    def study_hash(self) -> str | None:
        if not (self.path / "zarr.json").is_file():
            return None
        h = self.attrs().get("study_hash")
        return None if h is None else str(h)

    def clean_partial(self) -> int:
        """Remove temporary files left by a killed writer (Zarr's ``*.partial``, our ``*.tmp``)."""
        count = 0
        for root, _, files in os.walk(self.path):
            for f in files:
                if f.endswith(".partial") or (f.endswith(".tmp") and f.startswith(".")):
                    os.unlink(os.path.join(root, f))
                    count += 1
        return count

    # -- creation --------------------------------------------------------------------------------

    def create(self, study: Study, meta: StoreMeta) -> None:
        """Create the store for ``study`` (the path must not hold a store)."""
        if self.path.exists() and any(self.path.iterdir()):
            raise ValueError(
                f"{str(self.path)!r} exists and is not an empty directory; choose another "
                f"--out or remove it"
            )
        lay = study.layout
        g = zarr.open_group(str(self.path), mode="w", zarr_format=3)
        _create_axes(g, study)
        coords = [*_create_sampled(g, study), *_create_constants(g, study)]
        for name in meta.outputs:
            _create_output(g, name, meta, lay.shape, lay.chunks, lay.dims)
        messages = {**{int(k): v for k, v in meta.status_messages.items()}, **SWEEP_STATUS_MESSAGES}
        g.create_array(
            "status",
            shape=lay.shape,
            chunks=lay.chunks,
            dtype="int32",
            fill_value=-1,
            dimension_names=lay.dims,
            compressors=_compressors(),
            attributes={
                "long_name": "case status (0: ok; see 'messages')",
                "units": "1",
                "messages": {str(k): v for k, v in sorted(messages.items())},
            },
        )
        g.attrs.update(
            {
                "title": study.name,
                "description": study.description,
                "sweep_format": STUDY_FORMAT,
                "study_hash": meta.study_hash,
                "study": study.to_json(),
                "mode": study.mode,
                "n_cases": lay.n_cases,
                "n_chunks": lay.n_chunks,
                "chunk_shape": list(lay.chunks),
                "engine": meta.engine,
                "outputs": list(meta.outputs),
                "status_messages": {str(k): v for k, v in sorted(messages.items())},
                "coordinates": " ".join(coords),
            }
        )
        # the bookkeeping lives in a (data-less) sub-group so that Zarr readers accept it
        g.create_group(
            _META,
            attributes={
                "description": "impactlab sweep bookkeeping: "
                "study.json and per-chunk completion markers"
            },
        )
        self._done_dir.mkdir(parents=True, exist_ok=True)
        tmp = self._meta / ".study.json.tmp"
        tmp.write_text(json.dumps(study.to_dict(), indent=1, sort_keys=True) + "\n")
        os.replace(tmp, self._meta / "study.json")

    def _half_created(self) -> bool:
        """True for a store whose creation was interrupted (root metadata of a sweep, but no
        study.json yet, which ``create`` writes last): it holds no results."""
        if not (self.path / "zarr.json").is_file() or (self._meta / "study.json").is_file():
            return False
        try:
            fmt = self.attrs().get("sweep_format")
        except Exception:  # unreadable root metadata of a half-written store
            return (
                not any(p.name.isdigit() for p in self._done_dir.glob("*"))
                if self._done_dir.is_dir()
                else True
            )
        return fmt == STUDY_FORMAT and not self.done_chunks()

    # -- one writer at a time --------------------------------------------------------------------

    @property
    def _lock(self) -> Path:
        return self._meta / "lock"

    def acquire(self) -> None:
        """Mark the store as being written by this process; refuse if another live process on
        this host holds it (a lock left by a killed process is taken over)."""
        me = f"{socket.gethostname()} {os.getpid()}"
        for _ in range(2):
            try:
                fd = os.open(self._lock, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
            except FileExistsError:
                try:
                    host, pid = self._lock.read_text().split()
                except (OSError, ValueError):
                    host, pid = "", "0"
                if host == socket.gethostname() and pid == str(os.getpid()):
                    return  # already ours
                if host == socket.gethostname() and not _alive(int(pid)):
                    self._lock.unlink(missing_ok=True)  # stale: its writer is gone
                    continue
                raise ValueError(
                    f"store {str(self.path)!r} is being written by process {pid} on {host!r}; "
                    f"wait for it, or delete {str(self._lock)!r} if that process is gone"
                ) from None
            with os.fdopen(fd, "w") as fh:
                fh.write(me)
            return

    def release(self) -> None:
        """Remove this process's lock."""
        try:
            if self._lock.read_text().split()[1] == str(os.getpid()):
                self._lock.unlink()
        except (OSError, IndexError):
            pass

    def remove(self) -> None:
        """Delete the store (used to start a changed study fresh, on explicit request)."""
        if self.path.exists():
            if not (self.path / "zarr.json").is_file() and any(self.path.iterdir()):
                raise ValueError(f"refusing to remove {str(self.path)!r}: not a sweep store")
            shutil.rmtree(self.path)

    def prepare(self, study: Study, meta: StoreMeta, *, restart: bool = False) -> set[int]:
        """Create the store, or reopen it for the same study; returns the finished chunks.

        A store written by another study (different hash) is refused with StudyMismatchError
        unless ``restart=True``, which deletes it and starts fresh.
        """
        if self._half_created():
            shutil.rmtree(self.path)  # killed while creating: nothing computed yet
        if self.path.exists() and any(self.path.iterdir()):
            if not self.exists():
                raise ValueError(
                    f"{str(self.path)!r} exists but is not a sweep store; choose another --out"
                )
            old = self.study_hash()
            if old != meta.study_hash or restart:
                if not restart:
                    raise StudyMismatchError(
                        f"store {str(self.path)!r} holds a different study (hash {old}, this "
                        f"study {meta.study_hash}); run with --restart to discard it and start "
                        f"fresh, or choose another --out"
                    )
                self.remove()
            else:
                self.clean_partial()
                return self.done_chunks()
        self.create(study, meta)
        return set()

    # -- writes ----------------------------------------------------------------------------------

    def open_arrays(self, names: Sequence[str]) -> dict[str, Any]:
        g = zarr.open_group(str(self.path), mode="r+")
        return {n: g[n] for n in names}

    def write_chunk(
        self,
        arrays: Mapping[str, Any],
        study: Study,
        index: int,
        outputs: Mapping[str, np.ndarray],
        status: np.ndarray,
    ) -> None:
        """Write chunk ``index``'s outputs and status (1-D, C order over the block), the sampled
        inputs it is the first to cover, then its completion marker."""
        lay = study.layout
        block = lay.block(index)
        bshape = tuple(s.stop - s.start for s in block)
        for name, values in outputs.items():
            z = arrays[name]
            v = np.asarray(values).reshape(bshape)
            if np.dtype(z.dtype).kind == "i" and v.dtype.kind == "f":
                v = np.where(np.isfinite(v), v, z.fill_value)  # NaN -> the "none" code
            z[block] = v.astype(z.dtype, copy=False)
        arrays["status"][block] = np.asarray(status, dtype=np.int32).reshape(bshape)
        if study.sample is not None and all(s.start == 0 for s in block[:-1]):
            sl = block[-1]
            for name in study.sample.inputs:
                arrays[name][sl] = study.sample.draw(name, sl.start, sl.stop)
        self.mark_done(index)

    # -- reading ---------------------------------------------------------------------------------

    def dataset(self) -> xr.Dataset:
        """The store as a lazy xarray Dataset."""
        return open_sweep(self.path)


def open_sweep(path: str | Path) -> xr.Dataset:
    """Open a sweep store (lazy, dask-backed). Status messages: ``ds.attrs['status_messages']``."""
    p = Path(path)
    if not (p / "zarr.json").is_file():
        raise ValueError(f"{str(p)!r} is not a sweep store (no zarr.json)")
    ds = xr.open_zarr(str(p), consolidated=False)
    order = [*ds.attrs.get("outputs", []), "status"]
    names = [v for v in order if v in ds.data_vars] + [v for v in ds.data_vars if v not in order]
    return ds[names]


def export_netcdf(ds: xr.Dataset, path: str | Path) -> Path:
    """Write the Dataset to NetCDF-4 (strings kept; dictionary attributes become JSON text)."""
    out = Path(path)

    def attrs(a: Mapping[str, Any]) -> dict[str, Any]:
        return {k: json.dumps(v) if isinstance(v, dict) else v for k, v in a.items()}

    def plain(var: xr.Variable) -> xr.Variable:
        values = var.values
        if values.dtype.kind == "T":  # numpy StringDType -> fixed-width unicode
            values = np.array(values.tolist(), dtype=str)
        return xr.Variable(var.dims, values, attrs(var.attrs))

    loaded = ds.load()
    coords = {str(k): plain(v.variable) for k, v in loaded.coords.items()}
    data = {str(k): plain(v.variable) for k, v in loaded.data_vars.items()}
    xr.Dataset(data, coords=coords, attrs=attrs(loaded.attrs)).to_netcdf(out, engine="netcdf4")
    return out
