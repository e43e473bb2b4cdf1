"""One table of what an error of the system on a file means (``impactlab._oserror``): the
command line's one line, a sweep's store-write error and its lock refusal say the same words
for the same errno."""

from __future__ import annotations

import errno
import os
from pathlib import Path

import pytest

from impactlab._oserror import UNWRITABLE, oserror_words
from impactlab.cli import _system_error_line
from impactlab.sweep.backends import WRITE_ERRORS, write_error
from impactlab.sweep.locking import _unwritable


def _exc(code: int) -> OSError:
    return OSError(code, os.strerror(code), "x.csv")


@pytest.mark.parametrize("code", sorted(WRITE_ERRORS))
def test_the_cli_and_a_sweep_say_the_same_words(code: int) -> None:
    words = oserror_words(_exc(code))
    assert words is not None
    what, todo = words
    assert _system_error_line(_exc(code)) == (
        f"{what} writing 'x.csv': {todo} and run the command again"
    )
    line = str(write_error(_exc(code), Path("b.zarr"), 2, 5))
    assert line.startswith(f"{what} writing 'b.zarr' (2 of 5 chunks stored; ")


@pytest.mark.parametrize("code", sorted(UNWRITABLE))
def test_the_lock_refusal_says_them_too(code: int) -> None:
    words = oserror_words(_exc(code))
    assert words is not None
    text = _unwritable(Path("b.zarr"), Path("b.zarr/.sweep/lock"), _exc(code))
    assert text.startswith(f"store 'b.zarr': {words[0]}, so a run cannot write it")


def test_where_to_write_instead_is_the_caller_s() -> None:
    assert oserror_words(_exc(errno.EROFS), elsewhere="choose another --out") == (
        "read-only file system",
        "make it writable (or choose another --out)",
    )
    assert "choose another --out" in str(write_error(_exc(errno.EROFS), Path("b.zarr"), None, 5))
    assert oserror_words(_exc(errno.EIO)) is None
    assert str(write_error(_exc(errno.EIO), Path("b.zarr"), None, 5)).startswith(
        f"{os.strerror(errno.EIO)} writing 'b.zarr'"
    )
