"""Running CalculiX (``ccx``) and reading its text output (``.dat`` and ``.sta`` files).

ccx is found on PATH (or by the ``IMPACTLAB_CCX`` environment variable); it runs in a
temporary folder with ``OMP_NUM_THREADS=1`` (one process per unloading maximum runs in
parallel instead). Nothing here computes mechanics: it writes, runs and reads.
"""

from __future__ import annotations

import functools
import math
import os
import re
import shutil
import signal
import subprocess
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from subprocess import PIPE

import numpy as np

from impactlab.fe import interrupt

#: The one-line message when ccx is missing.
INSTALL_HINT = (
    "CalculiX (ccx) was not found on PATH: install it with `apt-get install calculix-ccx` "
    "(Debian/Ubuntu) or set IMPACTLAB_CCX to the ccx executable"
)

_FLOAT = r"[-+]?\d*\.?\d+(?:[eE][-+]?\d+)?"
_HEADER = re.compile(r"^\s*(.+?) for set (\S+) and time\s+(" + _FLOAT + r")\s*$")
_CONTACT = re.compile(r"^\s*contact stress .* and time\s+(" + _FLOAT + r")\s*$")


def _executable(name: str) -> bool:
    """Whether ``name`` is a file this process may execute (a path, or a command on PATH)."""
    path = Path(name)
    return (path.is_file() and os.access(path, os.X_OK)) or shutil.which(name) is not None


def find_ccx() -> str:
    """Path of the ccx executable; RuntimeError with how to install it when there is none, or
    naming ``IMPACTLAB_CCX`` when that is set to something that is not one (missing, a
    folder, or a file without execute permission)."""
    own = os.environ.get("IMPACTLAB_CCX", "").strip()
    if own and not _executable(own):
        why = " (a file without execute permission)" if Path(own).is_file() else ""
        raise RuntimeError(
            f"IMPACTLAB_CCX is set to {own!r}, which is not an executable file{why}; point it "
            f"at CalculiX's ccx, or unset it to use the ccx on PATH"
        )
    exe = own or shutil.which("ccx")
    if not exe or not _executable(exe):
        raise RuntimeError(INSTALL_HINT)
    return exe


class NotCalculixError(RuntimeError):
    """The ccx executable found (``IMPACTLAB_CCX`` or PATH) is not CalculiX: it prints no
    version for ``ccx -v``."""


@functools.lru_cache(maxsize=4)
def ccx_version(exe: str) -> str:
    """The version ccx prints for ``ccx -v`` (``This is Version 2.20``: ``2.20``), part of
    every cache key. :class:`NotCalculixError` in one line when ``exe`` prints no version (not
    CalculiX: ``IMPACTLAB_CCX=/bin/true``), cannot be started, or does not answer in 60 s."""
    try:
        out = subprocess.run([exe, "-v"], capture_output=True, text=True, timeout=60, check=False)
        text, status = out.stdout + out.stderr, exit_text(out.returncode)
    except (OSError, subprocess.TimeoutExpired) as exc:
        text, status = "", f"{type(exc).__name__}: {exc}"
    m = re.search(r"Version\s+(\d\S*)", text)
    if m:
        return m.group(1)
    said = " ".join(text.split())[:120]
    raise NotCalculixError(
        f"{exe} is not CalculiX's ccx: `{exe} -v` printed no version line such as 'This is "
        f"Version 2.20' ({status}; output: {said!r}); point IMPACTLAB_CCX at CalculiX's ccx, "
        "or unset it to use the ccx on PATH"
    )


@dataclass
class DatFile:
    """The printed results of one run: for each (quantity, set) the times and rows.

    ``totals[(what, set)]`` is a list of (time, vector); ``nodal[(what, set)]`` a list of
    (time, node ids (1-based), values (n, 3)). Times are total times (step 2 runs from 1 to
    2)."""

    totals: dict[tuple[str, str], list[tuple[float, np.ndarray]]] = field(default_factory=dict)
    nodal: dict[tuple[str, str], list[tuple[float, np.ndarray, np.ndarray]]] = field(
        default_factory=dict
    )


class DamagedOutputError(ValueError):
    """A ccx output file that cannot be what ccx wrote: a row of the wrong width, a number cut
    short, a file that ends inside a line or before the time its ``.sta`` file finished at.
    The message names the file, the line and what is wrong."""


class NonFiniteOutputError(DamagedOutputError):
    """A ccx output file with a nan or inf where ccx prints a number: ccx's solution diverged;
    the message names the file, the line and the value (no result is made of it)."""


#: A number as ccx prints it in a ``.dat`` row: a mantissa with a decimal point and a two- or
#: three-digit exponent (``-2.359894E-02``; Fortran's E format drops the letter of a
#: three-digit one: ``4.286203-101``, ``1.0+100``), or nan / inf (read, then
#: refused: ``NonFiniteOutputError``); a node id: digits.
_NUMBER = re.compile(
    r"[-+]?(?:\d+\.\d*|\.\d+)(?:[EeDd][-+]\d{2,3}|[-+]\d{3})|[-+]?(?:nan|inf)", re.IGNORECASE
)
_NODE = re.compile(r"\d+")
#: Any number as Fortran prints it, for patterns that find numbers in text (``1.5``,
#: ``-2.359894E-02``, ``4.286203-101``); read it with :func:`fortran_value`.
FORTRAN_FLOAT = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+|[-+]\d{3})?(?![\d.EeDd+-])"
#: The exponent of a number whose letter Fortran dropped (``4.286203-101``).
_BARE_EXPONENT = re.compile(r"(?<=[\d.])([-+]\d{3})$")


def fortran_value(text: str) -> float:
    """A number as Fortran prints it as a float (``1.0D-05``, ``4.286203-101``: 4.3e-101)."""
    return float(_BARE_EXPONENT.sub(r"E\1", text.replace("D", "E").replace("d", "e")))


def _width(what: str) -> int:
    """The number of components the header ``what`` lists: ``displacements (vx,vy,vz)``: 3."""
    m = re.search(r"\(([^)]*)\)", what)
    return len(m.group(1).split(",")) if m else 3


def _row(line: str, width: int, nodal: bool, name: str, number: int) -> list[float]:
    """The numbers of one data row, after checking its width and each number's full form."""
    parts = line.split()
    expected = width + (1 if nodal else 0)
    if len(parts) != expected:
        raise DamagedOutputError(
            f"{name}, line {number}: {len(parts)} values where its block has {expected} "
            f"({line.strip()!r}); the file is damaged (cut short?)"
        )
    for j, part in enumerate(parts):
        ok = _NODE.fullmatch(part) if nodal and j == 0 else _NUMBER.fullmatch(part)
        if not ok:
            kind = "node id" if nodal and j == 0 else "number"
            raise DamagedOutputError(
                f"{name}, line {number}: {part!r} is not a whole {kind} as ccx prints it "
                f"({line.strip()!r}); the file is damaged (cut short?)"
            )
    values = [fortran_value(v) for v in parts]
    bad = [part for part, v in zip(parts, values, strict=True) if not math.isfinite(v)]
    if bad:
        raise NonFiniteOutputError(
            f"{name}, line {number}: {bad[0]!r} where ccx prints a finite number "
            f"({line.strip()!r}): ccx's solution is not finite there (it diverged); the run "
            "cannot be read, and nothing of it is kept or cached"
        )
    return values


def parse_dat(text: str, name: str = "job.dat", sizes: Mapping[str, int] | None = None) -> DatFile:
    """Parse the ``*NODE PRINT`` blocks of a ``.dat`` file (the contact-stress blocks are
    skipped: the contact radius is read from the surface displacements). ``name``: the file's
    name in messages; ``sizes``: the number of nodes of each printed node set, where known.
    DamagedOutputError (naming ``name``, the line and what is wrong) for a row whose width
    differs from its header's components (plus the node id), a number not in ccx's full form
    (``-2.359894E-02``: a number cut short would be read 100 times off), a nan or inf
    (:class:`NonFiniteOutputError`: ccx diverged), a text that ends
    inside a line, or a nodal block with other than its set's number of rows (``sizes``, else
    the set's first block: a file cut at a line's end inside a block)."""
    out = DatFile()
    if text and not text.endswith("\n"):
        last = text.splitlines()[-1].strip()
        raise DamagedOutputError(
            f"{name}, line {text.count(chr(10)) + 1}: the file ends inside a line ({last!r}); "
            "the file is damaged (cut short?)"
        )
    lines = text.splitlines()
    i, n = 0, len(lines)
    while i < n:
        m = _HEADER.match(lines[i])
        if m is None:
            i += 1
            continue
        what, nset, t = m.group(1).strip(), m.group(2), float(m.group(3))
        header = i + 1
        total = what.startswith("total")
        width = _width(what)
        i += 1
        rows: list[list[float]] = []
        while i < n and not lines[i].strip():
            i += 1
        while i < n and lines[i].strip() and not _HEADER.match(lines[i]):
            if _CONTACT.match(lines[i]):
                break
            rows.append(_row(lines[i], width, not total, name, i + 1))
            i += 1
        if not rows:
            raise DamagedOutputError(
                f"{name}, line {header}: the block {what!r} for set {nset} at time {t:g} has no "
                "rows; "
                "the file is damaged (cut short?)"
            )
        arr = np.asarray(rows, dtype=np.float64)
        if total:
            out.totals.setdefault((what.split()[1], nset), []).append((t, arr[0]))
        else:
            ids = arr[:, 0].astype(np.int64)
            blocks = out.nodal.setdefault((what.split()[0], nset), [])
            _check_rows(len(ids), sizes, blocks, (name, header, what, nset, t))
            blocks.append((t, ids, arr[:, 1:]))
    return out


def _check_rows(
    found: int,
    sizes: Mapping[str, int] | None,
    earlier: list[tuple[float, np.ndarray, np.ndarray]],
    where: tuple[str, int, str, str, float],
) -> None:
    """DamagedOutputError when a nodal block of ``found`` rows has fewer or more than its set's
    nodes (``sizes``), or than the set's first block (``earlier``); ``where``: (file name,
    header line, quantity, set, time)."""
    name, line, what, nset, t = where
    if sizes is not None and nset in sizes:
        expected = int(sizes[nset])
        basis = f"the set has {expected} nodes"
    elif earlier:
        expected = len(earlier[0][1])
        basis = f"its block at time {earlier[0][0]:g} has {expected}"
    else:
        return
    if found != expected:
        raise DamagedOutputError(
            f"{name}, line {line}: the block {what!r} for set {nset} at time {t:g} has {found} "
            f"rows where {expected} are expected ({basis}); the file is damaged (cut short?)"
        )


@dataclass(frozen=True)
class StaRow:
    """One line of the ``.sta`` file: an attempt at an increment; ``converged`` False for the
    attempts ccx marks ``U`` (not converged: the increment was cut back and tried again)."""

    step: int
    increment: int
    attempt: int
    converged: bool
    iterations: int
    total_time: float


def parse_sta(text: str) -> list[StaRow]:
    """Every attempt listed in a ``.sta`` file."""
    rows = []
    for line in text.splitlines():
        parts = line.split()
        if len(parts) == 7 and parts[0].isdigit() and parts[1].isdigit():
            att = parts[2]
            rows.append(
                StaRow(
                    int(parts[0]),
                    int(parts[1]),
                    int(att.rstrip("U")),
                    not att.endswith("U"),
                    int(parts[3]),
                    float(parts[4]),
                )
            )
    return rows


@dataclass(frozen=True)
class RunOutput:
    """What one ccx run left: its ``.dat`` text, ``.sta`` text, return code, the tail of its
    terminal output (the error message when it stopped) and its wall time [s]."""

    dat: str
    sta: str
    returncode: int
    log_tail: str
    seconds: float


def run_ccx(deck: str, workdir: Path, exe: str, timeout: float | None = None) -> RunOutput:
    """Write ``deck`` as ``job.inp`` in ``workdir`` and run ``ccx -i job`` there (one thread)."""
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / "job.inp").write_text(deck)
    env = dict(os.environ)
    env["OMP_NUM_THREADS"] = "1"
    env["CCX_NPROC_EQUATION_SOLVER"] = "1"
    t0 = time.perf_counter()
    # tracked, so that Ctrl-C or SIGTERM ends it and its folder is removed (``fe.interrupt``)
    proc = interrupt.popen([exe, "-i", "job"], cwd=workdir, env=env, stdout=PIPE, stderr=PIPE)
    try:
        stdout, stderr = proc.communicate(timeout=timeout)
        rc, tail = proc.returncode, _error_lines(stdout + stderr, proc.returncode)
    except subprocess.TimeoutExpired:
        proc.kill()
        stdout, stderr = proc.communicate()
        rc = -9
        tail = f"ccx stopped after the time limit of {timeout} s; {_error_lines(stdout + stderr)}"
    finally:
        if proc.poll() is None:  # an exception in this thread: ccx does not outlive it
            proc.kill()
            proc.wait()
        interrupt.release(proc)
    seconds = time.perf_counter() - t0
    dat = workdir / "job.dat"
    sta = workdir / "job.sta"
    return RunOutput(
        dat=dat.read_text() if dat.exists() else "",
        sta=sta.read_text() if sta.exists() else "",
        returncode=rc,
        log_tail=tail,
        seconds=seconds,
    )


def exit_text(returncode: int) -> str:
    """How ccx ended: ``exit status 255``, or ``killed by signal 11 (SIGSEGV)``."""
    if returncode >= 0:
        return f"exit status {returncode}"
    try:
        name = f" ({signal.Signals(-returncode).name})"
    except ValueError:
        name = ""
    return f"killed by signal {-returncode}{name}"


def _error_lines(log: str, returncode: int = 0) -> str:
    """The ``*ERROR`` messages of a ccx log (the last ones), or its last lines; for a run
    that ended with a non-zero status, that status first (ccx may crash without an
    ``*ERROR`` line: ``ccx exit status 255, no *ERROR message; its last output: ...``)."""
    lines = [ln.strip() for ln in log.splitlines() if ln.strip()]
    errors = [i for i, ln in enumerate(lines) if ln.startswith("*ERROR")]
    if errors:
        i = errors[-1]
        text = " ".join(lines[i : i + 3])
        return text if returncode == 0 else f"ccx {exit_text(returncode)}: {text}"
    text = " ".join(lines[-3:])
    if returncode == 0:
        return text
    return f"ccx {exit_text(returncode)}, no *ERROR message; its last output: {text or 'none'}"
