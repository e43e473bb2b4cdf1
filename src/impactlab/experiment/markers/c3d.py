"""C3D marker files (https://www.c3d.org): 3D points in metres, occlusions masked.

The file is read with ``ezc3d``; when ezc3d is missing or fails on the file, the pure-Python
``c3d`` package is tried. Point units come from the ``POINT:UNITS`` parameter (e.g. "mm") unless
``units=`` overrides them; samples with a negative residual (the C3D convention for an invalid
point), non-finite coordinates or all three coordinates exactly zero (how BTK and several
exporters write a missing marker, whatever its residual) are masked (NaN), never used. A file
whose data section is shorter than its header announces (a truncated file) is refused: both
readers would otherwise silently return the frames that happen to be there.
"""

from __future__ import annotations

import math
import struct
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.markers.tracks import (
    MarkerTracks,
    check_rate_agrees,
    duplicate_labels,
    length_factor,
    rate_argument,
)

__all__ = ["read_c3d"]


def _header_words(path: Path, raw: bytes) -> tuple[tuple[int, ...], bool]:
    """(the header's first 12 words, whether the data are floats) of the C3D file's bytes
    ``raw``; FileFormatError for a file without a C3D header or parameter section.

    The byte order comes from the processor type in the parameter section (84 Intel, 85 DEC:
    little endian; 86 MIPS: big); the data are floats when the header's scale factor (words
    7-8, a float in the processor's format) is negative."""
    if len(raw) < 512 or raw[1] != 0x50:
        raise FileFormatError(path, "not a C3D file (bad header: no 0x50 signature)")
    pblock = raw[0]
    off = (pblock - 1) * 512
    if pblock < 2 or len(raw) < off + 4:
        raise FileFormatError(path, "truncated C3D file: the parameter section is missing")
    proc = raw[off + 3]
    end = ">" if proc == 86 else "<"
    words = struct.unpack(end + "12H", raw[:24])
    # the sign bit of the scale: IEEE little endian in byte 15, big endian in byte 12; a DEC
    # (VAX) float has it in the top bit of its first 16-bit word, byte 13
    sign_byte = {84: 15, 85: 13, 86: 12}.get(proc, 15)
    return words, bool(raw[sign_byte] & 0x80)


def _c3d_header_check(path: Path, n_frames_read: int, scale: float | None) -> None:
    """Refuse a C3D file whose data section is shorter than its header announces.

    Reads the 512-byte header directly (C3D spec, 1-based 16-bit words: word 1 byte 2 = 0x50;
    2 = points; 3 = analog samples per 3D frame, all channels together (channels x samples per
    channel); 4, 5 = first and last frame; 9 = the data section's first 512-byte block; word 10,
    the samples per channel, is not needed). A frame holds 4 values per point (x, y, z and the
    residual word) and word 3's analog values, each 4 bytes in a float file (``scale`` < 0, the
    header's sign when the reader gave none) and 2 bytes in an integer one. ``n_frames_read``:
    the frames a reader found (a file of more than 65535 frames counts them in a parameter, not
    in its header; 0 when none was read).
    """
    raw = path.read_bytes()
    words, float_header = _header_words(path, raw)
    n_points, analog_per_frame = words[1], words[2]
    first, last = words[3], words[4]
    data_start = max(int(words[8]), 1)
    header_frames = last - first + 1 if last >= first else 0
    is_float = scale < 0 if scale is not None else float_header
    bytes_per = 4 if is_float else 2
    frame_bytes = (n_points * 4 + analog_per_frame) * bytes_per
    frames = max(header_frames, n_frames_read)
    expected = (data_start - 1) * 512 + frames * frame_bytes
    if len(raw) < expected:
        have = max(0, (len(raw) - (data_start - 1) * 512) // max(frame_bytes, 1))
        analog = f" and {analog_per_frame} analog values" if analog_per_frame else ""
        held = (
            f"about {have} complete frames"
            if len(raw) > (data_start - 1) * 512
            else f"it ends before its data section, which starts at byte {(data_start - 1) * 512}"
        )
        raise FileFormatError(
            path,
            f"truncated C3D file: the header announces {frames} frames of {n_points} points"
            f"{analog} ({expected} bytes) but the file has {len(raw)} bytes ({held})",
        )


def _check_header_first(path: Path) -> None:
    """The truncation check for a file that no reader could read: its FileFormatError when the
    header announces more data than the file holds; nothing when the header itself is not a
    C3D one (the readers' errors say more)."""
    try:
        _c3d_header_check(path, 0, None)
    except FileFormatError as exc:
        if "truncated" in exc.problem:
            raise


def _mask_invalid(xyz: np.ndarray, residual: np.ndarray | None) -> None:
    """Mask (NaN, in place) the points of ``xyz`` (..., 3) that are missing: a negative or
    non-finite ``residual`` (same shape without the last axis; None: no residuals), or all three
    coordinates exactly zero (a gap written as the origin)."""
    bad = np.all(xyz == 0.0, axis=-1)
    if residual is not None:
        bad |= ~(np.isfinite(residual) & (residual >= 0.0))
    xyz[bad] = np.nan


def _read_ezc3d(path: Path) -> dict[str, Any]:
    import ezc3d  # the backends are imported on use: read_c3d falls back when one is missing

    c = ezc3d.c3d(str(path), extract_forceplat_data=False)
    params = c["parameters"]["POINT"]
    pts = np.asarray(c["data"]["points"], dtype=np.float64)  # (4, m, n)
    if pts.ndim != 3 or pts.shape[0] < 3:
        raise ValueError(f"unexpected point array shape {pts.shape}")
    xyz = np.transpose(pts[:3], (2, 1, 0)).copy()  # (n, m, 3)
    res = c["data"]["meta_points"].get("residuals") if "meta_points" in c["data"] else None
    r = np.asarray(res, dtype=np.float64)[0].T if res is not None and np.size(res) else None
    _mask_invalid(xyz, r)  # r: (n, m)
    labels = list(params["LABELS"]["value"]) if "LABELS" in params else []
    units = None
    if "UNITS" in params and params["UNITS"]["value"]:
        units = str(params["UNITS"]["value"][0]).strip() or None
    scale = float(params["SCALE"]["value"][0]) if "SCALE" in params else -1.0
    rate = float(c["header"]["points"]["frame_rate"])
    return {
        "xyz": xyz,
        "labels": labels,
        "units": units,
        "rate": rate,
        "scale": scale,
        "backend": "ezc3d",
    }


def _read_pyc3d(path: Path) -> dict[str, Any]:
    import c3d  # the backends are imported on use: read_c3d falls back when one is missing

    with path.open("rb") as fh, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = c3d.Reader(fh)
        frames = []
        for _i, points, _analog in r.read_frames(copy=True):
            p = np.asarray(points, dtype=np.float64)
            xyz = p[:, :3].copy()
            _mask_invalid(xyz, p[:, 3] if p.shape[1] > 3 else None)
            frames.append(xyz)
        labels = [str(s).strip() for s in r.point_labels]
        try:
            units = r.get("POINT:UNITS").string_value.strip() or None
        except (AttributeError, KeyError):
            units = None
        scale = float(r.point_scale)
        rate = float(r.point_rate)
    xyz_all = np.stack(frames, axis=0) if frames else np.zeros((0, len(labels), 3))
    return {
        "xyz": xyz_all,
        "labels": labels,
        "units": units,
        "rate": rate,
        "scale": scale,
        "backend": "c3d",
    }


def read_c3d(
    path: str | Path,
    *,
    units: str | None = None,
    backend: str = "auto",
    rate: float | str | None = None,
) -> MarkerTracks:
    """Read the 3D points of a C3D file.

    Parameters
    ----------
    path : the .c3d file.
    units : length unit of the stored coordinates; overrides ``POINT:UNITS`` (needed only when the
        file lacks it).
    backend : "auto" (ezc3d, then the pure-Python ``c3d`` package), "ezc3d" or "c3d".
    rate : the frame rate the caller expects (a number in Hz or a string such as "500 Hz"): it
        must agree with the file's point rate (within 1 %; the file's is used), a
        FileFormatError naming both otherwise.

    Returns :class:`MarkerTracks` in metres, time from 0 at the first frame. Raises
    :class:`FileFormatError` naming the file for a missing, corrupt, truncated or empty file.
    """
    rate = rate_argument(rate)
    p = Path(path)
    if not p.is_file():
        raise FileFormatError(p, "file does not exist" if not p.exists() else "not a file")
    if backend not in ("auto", "ezc3d", "c3d"):
        raise ValueError(f"backend must be 'auto', 'ezc3d' or 'c3d', got {backend!r}")
    if p.stat().st_size == 0:
        raise FileFormatError(p, "empty file")
    problems: list[str] = []
    data: dict[str, Any] | None = None
    order = ["ezc3d", "c3d"] if backend == "auto" else [backend]
    for name in order:
        try:
            data = _read_ezc3d(p) if name == "ezc3d" else _read_pyc3d(p)
            break
        except ImportError as exc:
            problems.append(f"{name} is not installed ({exc})")
        except Exception as exc:  # both libraries raise assorted types on bad files
            problems.append(f"{name}: {type(exc).__name__}: {str(exc).strip()[:200]}")
    if data is None:
        _check_header_first(p)  # a file cut short: say so, not that it cannot be read
        raise FileFormatError(p, "not a readable C3D file (" + "; ".join(problems) + ")")
    xyz = data["xyz"]
    # before the count of frames and points: a file cut before its data holds none
    _c3d_header_check(p, xyz.shape[0], data["scale"])
    if xyz.shape[0] == 0 or xyz.shape[1] == 0:
        raise FileFormatError(
            p, f"the C3D file holds no 3D point data ({xyz.shape[0]} frames, {xyz.shape[1]} points)"
        )
    file_rate = data["rate"]
    if not (math.isfinite(file_rate) and file_rate > 0):
        raise FileFormatError(p, f"invalid point rate {file_rate!r} Hz in the C3D header")
    if rate is not None:
        check_rate_agrees(p, rate, file_rate, "the point rate in its header")
    rate = file_rate
    unit = units if units is not None else data["units"]
    if unit is None:
        raise FileFormatError(
            p,
            "the C3D file has no POINT:UNITS parameter; pass units= (e.g. units='mm'; "
            "impactlab analyze --marker-units mm)",
        )
    try:
        fac = length_factor(unit, name="POINT:UNITS" if units is None else "units")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    labels = list(data["labels"])[: xyz.shape[1]]
    labels += [f"P{i + 1}" for i in range(len(labels), xyz.shape[1])]
    labels = [s.strip() or f"P{i + 1}" for i, s in enumerate(labels)]
    twice = duplicate_labels(labels, lambda i: f"point {i + 1}")
    if twice:
        raise FileFormatError(p, f"the POINT:LABELS parameter names {twice}")
    t = np.arange(xyz.shape[0], dtype=np.float64) / rate
    return MarkerTracks(
        t,
        xyz * fac,
        tuple(labels),
        str(p),
        {
            "format": "c3d",
            "backend": data["backend"],
            "units": unit,
            "rate": rate,
            "fallback_notes": problems,
        },
    )
