"""Building a new sweep store: its arrays, attributes and bookkeeping, written into an empty
directory (``SweepStore.create`` builds it in a temporary sibling and renames it into place, so
a store either exists complete or not at all). Its chunks are written by
:mod:`~impactlab.sweep.chunkfiles`.

Layout (a Zarr v3 group that ``xarray.open_zarr`` reads):

- one coordinate array per grid axis (SI values, ``units`` attribute);
- the sampled inputs as variables along ``sample`` (written with the chunks that cover them);
- fixed inputs as scalar coordinates;
- the resolved material values of the cases that the inputs do not hold (a library material's
  E, nu, S_y, ...: scalars, or arrays along a grid of materials; ``sweep.material_record``);
- one array per kept output and ``status`` (int32; -1 = not computed), chunked exactly like the
  work: each work chunk is one Zarr chunk of every array, so no two chunks ever share a file;
- ``.sweep/study.json`` (the canonical study) and ``.sweep/done/`` (completion markers).
"""

from __future__ import annotations

import json
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import zarr
from zarr.codecs import BloscCodec

from impactlab._version import __version__
from impactlab.flags import ResultFlag, messages
from impactlab.sweep.dimensions import SAMPLE_DIM
from impactlab.sweep.hooks import checkpoint
from impactlab.sweep.inputs import INPUTS, INTEGER_OUTPUTS, get_input, output_spec
from impactlab.sweep.material_record import resolved_material_values
from impactlab.sweep.options import STUDY_FORMAT
from impactlab.sweep.status import SWEEP_STATUS_MESSAGES
from impactlab.sweep.study import Study

#: The bookkeeping sub-group of a store.
META = ".sweep"


@dataclass(frozen=True)
class StoreMeta:
    """What the store records besides the data (root attributes)."""

    study_hash: str
    outputs: tuple[str, ...]
    integer_outputs: tuple[str, ...]
    status_messages: Mapping[int, str]
    regimes: Mapping[int, str]
    engine: str
    #: Each law of the study -> its ``range`` and ``source`` (``study_meta.law_ranges``).
    law_ranges: Mapping[str, Mapping[str, str]] = field(default_factory=dict)


#: Chunk files named ``<array>/c.<i>.<j>...`` (Zarr v3's default chunk-key encoding with the
#: "." separator): every chunk file of an array in its one folder. The "/" separator makes a
#: folder per chunk row and dimension, and creating folders is what made the writes costly when
#: every core computes (docs/sweep.md, "Benchmark"). Stores made before keep their "/".
CHUNK_KEYS: dict[str, Any] = {"chunk_key_encoding": {"name": "default", "separator": "."}}


def compressors() -> Any:
    """Blosc-LZ4 with byte shuffle: 2-3x faster to write than Zarr's default zstd at a similar
    ratio on smooth sweep data (measured: 1.5 vs 3.3 ms per 60k-value chunk), which keeps the
    writes a small fraction of the kernel time."""
    return [BloscCodec(cname="lz4", clevel=5, shuffle="shuffle")]


def _attrs_units(name: str) -> dict[str, Any]:
    spec = get_input(name)
    d: dict[str, Any] = {"long_name": spec.description}
    if spec.unit:
        d["units"] = spec.unit
    return d


def _new_array(g: Any, name: str, value: Any, dims: tuple[str, ...]) -> None:
    """An unchunked coordinate array holding ``value`` (names or SI floats)."""
    text = np.asarray(value).dtype.kind in "OUT"
    shape = np.shape(value)
    z = g.create_array(
        name,
        shape=shape,
        **({"chunks": shape} if shape else {}),
        dtype=str if text else "float64",
        fill_value="" if text else np.nan,
        dimension_names=dims,
        attributes=_attrs_units(name),
        **CHUNK_KEYS,
    )
    z[...] = np.array(value, dtype=str) if text else value


def _create_axes(g: Any, study: Study) -> None:
    """One coordinate array per grid axis."""
    for axis in study.axes:
        _new_array(g, axis.name, axis.array(), (axis.name,))


def defined_arrays(study: Study) -> dict[str, tuple[Any, tuple[str, ...], Any]]:
    """The arrays the study itself defines, written once when the store is built: name ->
    (values, dimension names, attributes or None for a coordinate's own): the grid axes, the
    fixed (and defaulted) inputs as scalars, the resolved material values."""
    out: dict[str, tuple[Any, tuple[str, ...], Any]] = {
        axis.name: (axis.array(), (axis.name,), None) for axis in study.axes
    }
    for name, value in _constants(study):
        out[name] = (value, (), None)
    for name, value, dims, attrs in resolved_material_values(study):
        out[name] = (value, tuple(dims), attrs)
    return out


def create_defined_array(g: Any, name: str, entry: tuple[Any, tuple[str, ...], Any]) -> None:
    """Create the study-defined array ``name`` (an entry of ``defined_arrays``) in ``g``."""
    value, dims, attrs = entry
    if attrs is None:
        _new_array(g, name, value, dims)
    else:
        _material_array(g, name, value, dims, attrs)


def _create_sampled(g: Any, study: Study) -> list[str]:
    """The sampled inputs along ``sample`` (filled by the chunk writes); returns their names."""
    if study.sample is None:
        return []
    for name in study.sample.inputs:
        create_sampled_array(g, name, study)
    return list(study.sample.inputs)


def create_sampled_array(g: Any, name: str, study: Study) -> None:
    """The array of the sampled input ``name`` along ``sample`` in the group ``g`` (filled by
    the chunk writes, chunked like the work's last dimension)."""
    assert study.sample is not None
    g.create_array(
        name,
        shape=(study.sample.size,),
        chunks=(study.layout.chunks[-1],),
        dtype="float64",
        fill_value=np.nan,
        dimension_names=(SAMPLE_DIM,),
        compressors=compressors(),
        **CHUNK_KEYS,
        attributes={
            **_attrs_units(name),
            "distribution": json.dumps(study.sample.inputs[name].to_dict()),
        },
    )


def _constants(study: Study) -> list[tuple[str, Any]]:
    """(name, value) of the fixed (and defaulted) inputs, by name; vx and vy not where speed
    and incidence give the velocity (their defaults would read as the cases' values)."""
    varying = set(study.varying())
    by_speed = "speed" in varying or study.value_of("speed") is not None
    derived = {"vx", "vy"} if by_speed else set()
    constants = {n: study.value_of(n) for n in INPUTS if n not in varying | derived}
    return sorted((n, v) for n, v in constants.items() if v is not None)


def _create_constants(g: Any, study: Study) -> list[str]:
    """The fixed (and defaulted) inputs as scalar arrays; returns their names."""
    names = []
    for name, value in _constants(study):
        _new_array(g, name, value, ())
        names.append(name)
    return names


def _material_array(g: Any, name: str, value: Any, dims: Any, attrs: Any) -> None:
    """One resolved material value (a scalar, or an array along a grid of materials)."""
    shape = np.shape(value)
    z = g.create_array(
        name,
        shape=shape,
        **({"chunks": shape} if shape else {}),
        dtype="float64",
        fill_value=np.nan,
        dimension_names=dims,
        attributes=attrs,
        **CHUNK_KEYS,
    )
    z[...] = value


def _create_material_values(g: Any, study: Study) -> list[str]:
    """The resolved material values of the cases that the study's inputs do not hold
    (``sweep.material_record``); returns their names."""
    names = []
    for name, value, dims, attrs in resolved_material_values(study):
        _material_array(g, name, value, dims, attrs)
        names.append(name)
    return names


def _create_output(g: Any, name: str, meta: StoreMeta, study: Study) -> None:
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
        if name == "flags":
            attrs.update(flag_attrs())
    else:
        dtype, fill = "float64", np.nan
    _chunked(g, name, study, dtype, fill, attrs)


#: The stored word for status 0: the engine ran the case to its end (whether its result is ok,
#: the flags say); ``summary.FINISHED`` labels it so in the counts of any store.
FINISHED = "finished"


def _status_messages(meta: StoreMeta) -> dict[int, str]:
    """The status codes of the engine and of the sweep's own refusals, with their meaning."""
    engine = {int(k): v for k, v in meta.status_messages.items()}
    return {**engine, 0: FINISHED, **SWEEP_STATUS_MESSAGES}


def create_result_array(g: Any, name: str, meta: StoreMeta, study: Study) -> None:
    """The array of one kept output, or ``status`` (int32, -1 = not computed), in the group
    ``g``: chunked like the work, written chunk by chunk."""
    if name != "status":
        _create_output(g, name, meta, study)
        return
    status_attrs = {
        "long_name": "case status (0: finished, the flags say if ok; see 'messages')",
        "units": "1",
        "messages": {str(k): v for k, v in sorted(_status_messages(meta).items())},
    }
    _chunked(g, "status", study, "int32", -1, status_attrs)


def flag_attrs() -> dict[str, Any]:
    """CF flag attributes of the ``flags`` output: each bit, its name and its explanation."""
    bits = [f for f in ResultFlag if f.value]
    texts = {int(f): messages(f)[0] for f in bits}
    return {
        "flag_masks": [int(f) for f in bits],
        "flag_meanings": " ".join(str(f.name).lower() for f in bits),  # as ResultFlag, CF
        "flag_messages": {str(k): v for k, v in texts.items()},
    }


def _chunked(g: Any, name: str, study: Study, dtype: str, fill: float, attrs: Any) -> None:
    lay = study.layout
    g.create_array(
        name,
        shape=lay.shape,
        chunks=lay.chunks,
        dtype=dtype,
        fill_value=fill,
        dimension_names=lay.dims,
        attributes=attrs,
        compressors=compressors(),
        **CHUNK_KEYS,
    )


def _root_attrs(
    study: Study, meta: StoreMeta, messages: Mapping[int, str], coords: list[str]
) -> Any:
    lay = study.layout
    return {
        "title": study.name,
        "description": study.description,
        "sweep_format": STUDY_FORMAT,
        "impactlab_version": __version__,
        "study_hash": meta.study_hash,
        "study": study.to_json(),
        "mode": study.mode,
        "n_cases": lay.n_cases,
        "n_chunks": lay.n_chunks,
        "chunk_shape": list(lay.chunks),
        "engine": meta.engine,
        "outputs": list(meta.outputs),
        "status_messages": {str(k): v for k, v in sorted(messages.items())},
        "law_ranges": {k: dict(v) for k, v in meta.law_ranges.items()},
        "coordinates": " ".join(coords),
    }


def build_store(path: Path, study: Study, meta: StoreMeta) -> None:
    """Write the arrays, attributes and bookkeeping of ``study``'s store into the empty
    directory ``path``."""
    g = zarr.open_group(str(path), mode="w", zarr_format=3)
    _create_axes(g, study)
    coords = [*_create_sampled(g, study), *_create_constants(g, study)]
    coords += _create_material_values(g, study)
    for name in (*meta.outputs, "status"):
        create_result_array(g, name, meta, study)
    checkpoint("create:arrays")
    g.attrs.update(_root_attrs(study, meta, _status_messages(meta), coords))
    create_meta_group(g, meta)
    (path / META / "done").mkdir(parents=True, exist_ok=True)
    write_study_record(path, study)
    consolidate(path)


def create_meta_group(g: Any, meta: StoreMeta) -> None:
    """The bookkeeping sub-group ``.sweep`` of the group ``g``: data-less, so that Zarr readers
    accept it; its attribute ``engine`` lets the root's attributes be rewritten."""
    g.create_group(
        META,
        attributes={
            "description": "impactlab sweep bookkeeping: "
            "study.json and per-chunk completion markers",
            "engine": meta.engine,  # with study.json: the root's attributes can be rewritten
        },
    )


def rewrite_root(path: Path, study: Study, meta: StoreMeta) -> None:
    """Write the root ``zarr.json`` of the store at ``path`` again (gone or unreadable): a Zarr
    group with the attributes ``build_store`` gave it, over the arrays that are there, and the
    consolidated metadata. The caller holds the lock and has checked that the store holds
    ``study`` computed by ``meta.engine``."""
    (path / "zarr.json").unlink(missing_ok=True)
    g = zarr.open_group(str(path), mode="a", zarr_format=3)
    coords = list(study.sample.inputs) if study.sample is not None else []
    coords += [name for name, _ in _constants(study)]
    coords += [name for name, *_ in resolved_material_values(study)]
    g.attrs.update(_root_attrs(study, meta, _status_messages(meta), coords))
    consolidate(path)


def write_study_record(path: Path, study: Study) -> None:
    """Write ``.sweep/study.json`` (the canonical study) of the store at ``path``."""
    text = json.dumps(study.to_dict(), indent=1, sort_keys=True) + "\n"
    (path / META / "study.json").write_text(text)


def consolidate(path: Path) -> None:
    """Write the store's consolidated metadata, so that ``xarray.open_zarr(path)`` opens it
    without a warning (the arrays and attributes are final once built; the chunk bookkeeping
    is plain files). zarr's notes while it walks the store are silenced here: that
    consolidated metadata is not yet part of the Zarr 3 specification (impactlab reads its
    stores without it) and that the bookkeeping files are not Zarr nodes."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        zarr.consolidate_metadata(str(path))
