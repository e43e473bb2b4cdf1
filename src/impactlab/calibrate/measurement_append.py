"""One drop appended to a CSV measurements file as one line, the rest of the file left as
written (its ``#`` comments, its rows, their units and digits).

The new line's values are written in the units of the file's header: a header ``angle [deg]``
gets degrees, ``delta_p [um]`` micrometres, ``e [%]`` percent; a column without a unit gets the
input's unit (SI; a Brinell hardness in kgf/mm^2) or, for an uncertainty, its quantity's column
unit, and an angle in a column without a unit is written with its unit (``"20 deg"``). A column
the file lacks is added at the end of the header, with its unit (``[deg]`` for an angle, SI
otherwise), and every earlier row gets an empty field there (blank: not given, as before). A new
file gets a header in SI units (angles in degrees). Each number is written with 12 significant
digits. The file is written whole or not at all, under an exclusive lock on its folder, so that
concurrent appends (a batch of analyses run in parallel) keep every drop; where the folder cannot
be locked (a network file system without locks), the drop is appended unlocked with a
CalibrationWarning. The drop's label must read back as written (:func:`check_label`).
"""

from __future__ import annotations

import contextlib
import csv
import io
import math
import os
import warnings
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

from impactlab._files import write_bytes_atomic
from impactlab.calibrate.calibration_warning import CalibrationWarning
from impactlab.calibrate.correlations import correlation_column
from impactlab.calibrate.measurement_columns import (
    LABEL_KEYS,
    column_kind,
    is_percent,
    split_header,
)
from impactlab.calibrate.measurement_files import read_text
from impactlab.calibrate.measurement_rows import Row, parse_row
from impactlab.calibrate.measurement_twins import same_drop
from impactlab.calibrate.measurements import Measurements, read_measurements
from impactlab.calibrate.quantities import ANGLES, DROP_CATEGORIES, MEASURABLE
from impactlab.sweep.inputs import INPUTS, UNIT_REQUIRED
from impactlab.units import to_si

__all__ = ["append_record", "check_label", "same_drop"]

_BOM = b"\xef\xbb\xbf"


def append_record(
    path: str | Path, record: Mapping[str, Any], comment: str | None = None
) -> Measurements:
    """Append the drop ``record`` (column -> value, as ``Measurements.from_records`` takes it)
    to the CSV measurements file ``path`` (created if missing) as one line in the file's units,
    after a ``# comment`` line when ``comment`` is given; returns the file's drops, read under
    the lock (the new drop last). ValueError naming the file for one that is not CSV, a file
    that cannot be read as measurements, a label the file has already, a label that would not
    read back as written (:func:`check_label`; a record without one too) and a drop it cannot
    take; a CalibrationWarning when the drop was appended unlocked (:func:`_locked`)."""
    p = Path(path)
    if p.suffix.lower() != ".csv":
        raise ValueError(
            f"measurements file {str(p)!r}: a drop is appended to a CSV file (.csv); for a TOML "
            "file, add a [[drop]] table of experiment_record's columns"
        )
    label = next((record[k] for k in LABEL_KEYS if k in record), None)
    if label is None or (isinstance(label, float) and math.isnan(label)):
        raise ValueError(
            f"{p}: the drop has no label (column 'label'): give it one, so that the file names "
            "it by its label, not by its place"
        )
    check_label(str(label), f"{p}: label")
    row = parse_row(0, record, {})
    with _locked(p) as unlocked:  # read, check, replace and read back as one step
        _append(p, row, comment)
        meas = read_measurements(p)  # the file with this drop last, as it was appended
    if unlocked:
        warnings.warn(
            f"{p}: drop {row.label!r} appended without a lock on its folder ({unlocked}): "
            "appends to this file from other processes at the same time are not safe (a drop "
            "may be lost); append one at a time there",
            CalibrationWarning,
            stacklevel=2,
        )
    return meas


def _append(p: Path, row: Row, comment: str | None) -> None:
    """:func:`append_record`'s read, check and replace of ``p`` (under its lock)."""
    if p.exists() and not p.is_file():  # a device or a FIFO would be read without end
        raise ValueError(f"measurements file {str(p)!r} is not a regular file")
    data = p.read_bytes() if p.exists() else b""
    text = read_text(p, "CSV") if data.strip() else ""
    lines = text.splitlines(keepends=True)
    at = next((i for i, x in enumerate(lines) if x.strip() and not x.startswith("#")), None)
    if at is not None and any(x.strip() and not x.startswith("#") for x in lines[at + 1 :]):
        old = read_measurements(p)
        if row.label in old.labels:
            raise ValueError(
                f"{p}: a drop labelled {row.label!r} is there already (drop "
                f"{old.labels.index(row.label) + 1}): give the new drop another label"
            )
    header = next(csv.reader([lines[at]])) if at is not None else []
    newline = "\r\n" if at is not None and lines[at].endswith("\r\n") else "\n"
    fields, added = _fields(str(p), header, row)
    out = io.StringIO(newline="")
    csv.writer(out, lineterminator=newline).writerow(fields)
    if at is None:  # a new file, or one of comments only: a header of the row's columns
        head = io.StringIO(newline="")
        csv.writer(head, lineterminator=newline).writerow(added)
        lines += [head.getvalue()]
    elif added:  # columns the file lacks: at the end of the header, empty in earlier rows
        extra = io.StringIO(newline="")
        csv.writer(extra, lineterminator="").writerow(["", *added])
        lines = [
            _extended(x, extra.getvalue() if i == at else "," * len(added)) if i >= at else x
            for i, x in enumerate(lines)
        ]
    if lines and not lines[-1].endswith(("\n", "\r")):
        lines[-1] += newline
    lines += [f"# {_one_line(comment)}{newline}"] if comment else []
    lines.append(out.getvalue())
    bom = _BOM if data.startswith(_BOM) else b""
    new = "".join(lines)
    meas = Measurements.from_records(_records(new), source=str(p))  # refused before written
    twin = same_drop(meas, meas.n_drops - 1)
    if twin is not None:
        raise ValueError(
            f"{p}: drop {row.label!r} holds the values of drop {meas.labels[twin]!r} (drop "
            f"{twin + 1}): the same drop appended twice would count twice in a calibration; to "
            "replace that drop, remove its line first"
        )
    write_bytes_atomic(p, bom + new.encode("utf-8"))


@contextlib.contextmanager
def _locked(p: Path) -> Iterator[str]:
    """An exclusive lock (``fcntl.flock``) on the folder that holds ``p`` (the file a symbolic
    link names), held while the block runs, so that appends from several processes each see
    the drops of the others; the folder, not the file, since the write replaces the file, and
    no lock file is left beside it. Yields "" when locked; otherwise, the block running
    unlocked, why not: the folder cannot be opened (where it is missing the write fails on its
    own) or locked (``flock`` refused, as on some network file systems). Without ``fcntl``
    (Windows) the block runs unlocked and "" is yielded (module docstring)."""
    target = p.resolve() if p.is_symlink() else p
    try:
        import fcntl
    except ImportError:  # pragma: no cover - not on POSIX
        yield ""
        return
    try:
        fd = os.open(target.parent, os.O_RDONLY)
    except OSError as exc:
        fd, why = -1, f"the folder cannot be opened: {exc.strerror or exc}"
    if fd < 0:  # outside the handler: an error of the block is not chained to this one
        yield why
        return
    try:
        why = ""
        try:
            fcntl.flock(fd, fcntl.LOCK_EX)
        except OSError as exc:  # ENOLCK, EBADF: NFS without a lock service, for example
            why = f"the folder cannot be locked: {exc.strerror or exc}"
        try:
            yield why
        finally:
            if not why:
                with contextlib.suppress(OSError):  # closing the folder unlocks it anyway
                    fcntl.flock(fd, fcntl.LOCK_UN)
    finally:
        os.close(fd)


def check_label(label: str, name: str = "label") -> None:
    """ValueError naming ``name`` for a drop label that a CSV measurements file would not read
    back as written: empty, with spaces or tabs at either end (the reader strips them), holding
    a line break (a newline, a carriage return, or any that ``str.splitlines`` splits on) or
    starting with ``#`` (its line would be a comment)."""
    why = ""
    if not label.strip():
        why = "is empty"
    elif label.splitlines() != [label]:
        why = "holds a line break: it would split the drop's line"
    elif label != label.strip():
        why = "has spaces at an end, which the file's reader strips"
    elif label.startswith("#"):
        why = "starts with '#': its line would be read as a comment, and the drop lost"
    if why:
        raise ValueError(
            f"{name} {label!r} {why}; a drop label is text of one line, without spaces at its "
            "ends, that does not start with '#'"
        )


def _records(text: str) -> list[dict[str, str]]:
    """The rows of the CSV ``text`` as ``measurement_files.csv_records`` reads them."""
    kept = [x for x in text.splitlines() if x.strip() and not x.startswith("#")]
    rows = list(csv.reader(kept))
    return [
        {h: f for h, f in zip(rows[0], r, strict=False) if h.strip()}
        for r in rows[1:]
        if any(f.strip() for f in r)
    ]


def _one_line(text: str) -> str:
    return " ".join(text.split())


def _extended(line: str, tail: str) -> str:
    """A data line (or the header) with ``tail`` added before its line ending; a blank or a
    comment line as it is."""
    if not line.strip() or line.startswith("#"):
        return line
    body = line.rstrip("\r\n")
    return body + tail + line[len(body) :]


def _fields(where: str, header: list[str], row: Row) -> tuple[list[str], list[str]]:
    """(the new line's fields: the file's columns then the added ones, the added columns'
    headers): each value in its column's unit (module docstring)."""
    values = _values(row)
    canon: dict[str, int] = {}
    units: dict[str, str | None] = {}
    for j, h in enumerate(header):
        name, unit = split_header(h)
        if name.strip():
            c = column_kind(where, name)[1]
            canon.setdefault(c, j)
            units[c] = unit
    fields = [""] * len(header)
    added: list[str] = []
    for c, (x, si) in values.items():
        base = c.removesuffix("_sigma") if c.endswith("_sigma") else c
        if c in canon:
            unit = units[c] or (units.get(base) if c != base else None)
            fields[canon[c]] = _text(c, base, x, si, unit)
            continue
        unit = "deg" if base in (*ANGLES, *UNIT_REQUIRED) else (None if si in ("1", "") else si)
        if c != base and units.get(base):  # an uncertainty beside a file's column of a unit
            unit = units[base]
        added.append(c if unit is None or isinstance(x, str) else f"{c} [{unit}]")
        fields.append(_text(c, base, x, si, unit))
    return fields, added


def _values(row: Row) -> dict[str, tuple[Any, str]]:
    """Canonical column -> (value, its unit: the input's or SI; "" for text) of ``row``."""
    out: dict[str, tuple[Any, str]] = {"label": (row.label, "")}
    out |= {c: (row.categories[c], "") for c in DROP_CATEGORIES if c in row.categories}
    out |= {k: (x, INPUTS[k].unit) for k, x in row.inputs.items()}
    for q, x in row.observed.items():
        out[q], out[f"{q}_sigma"] = (x, MEASURABLE[q].unit), (row.sigma[q], MEASURABLE[q].unit)
    out |= {correlation_column(*pair): (x, "1") for pair, x in row.correlation.items()}
    return out


def _text(column: str, base: str, x: Any, si: str, unit: str | None) -> str:
    """``x`` (in ``si``) as the text of a field of a column of ``unit`` (None: bare)."""
    if isinstance(x, str):
        return x
    spec = INPUTS.get(column)
    if unit is None and spec is not None and spec.parse_unit != spec.unit:
        unit = spec.parse_unit  # a bare hardness is read in kgf/mm^2
    if unit is None and base in (*ANGLES, *UNIT_REQUIRED):
        return f"{_number(math.degrees(x))} deg"  # an angle is never bare
    if unit is None or unit.strip() in ("1", "-", si):
        return _number(x)
    if is_percent(unit):
        return _number(100.0 * x)
    return _number(x * to_si(1.0, si) / to_si(1.0, unit))


def _number(x: float) -> str:
    return f"{float(x):.12g}"
