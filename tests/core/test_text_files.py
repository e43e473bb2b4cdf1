"""A user's input file that is not UTF-8 text (a binary file, another encoding) is refused in one
line that names the option or the file, says what it should be and where the first bad byte is:
every command that reads a TOML, JSON or CSV file, and the Python API's readers alike
(``impactlab._validation.read_text_file``, the one reader)."""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from pathlib import Path

import pytest

from impactlab._validation import read_text_file

CliMain = Callable[..., tuple[int, str, str]]

#: Not UTF-8: byte 1 (0xff) can start no UTF-8 sequence.
JUNK = b"\x00\xff\xfe garbage"
ROD = ("simulate", "rod", "--angle", "20 deg", "--vy", "-1 m/s")


@pytest.fixture
def junk(tmp_path: Path) -> Callable[[str], str]:
    """``junk(name)``: the path of a file ``name`` in a temporary folder holding :data:`JUNK`."""

    def make(name: str) -> str:
        path = tmp_path / name
        path.write_bytes(JUNK)
        return str(path)

    return make


# (command line with {toml}, {json} or {csv} for the junk file, what the message names it)
COMMANDS = [
    (("simulate", "--from", "{json}"), "--from"),
    (("drop", "--from", "{json}"), "--from"),
    ((*ROD, "--config", "{toml}"), "--config"),
    (("invert", "--file", "{toml}"), "--file"),
    (("--law-file", "{toml}", "laws"), "law file"),
    ((*ROD, "--flat", "{toml}"), "--flat:"),
    (("calibrate", "--config", "{toml}"), "calibration file"),
    (("calibrate", "{csv}", "-p", "mu=uniform(0, 1)"), "measurements file"),
    (("analyze", "--rod", "{toml}", "x.csv", "y.npy"), "--rod"),
    (("analyze", "--geometry", "{toml}", "x.csv", "y.npy"), "--geometry"),
    (("sweep", "run", "{toml}"), "study file"),
    (("fe", "indent", "--max", "10 um", "--hardening", "{csv}"), "--hardening"),
]


@pytest.mark.parametrize(
    ("args", "named"), COMMANDS, ids=lambda a: " ".join(a) if isinstance(a, tuple) else a
)
def test_a_command_refuses_a_binary_input_file_in_one_line(
    cli_main: CliMain, junk: Callable[[str], str], args: tuple[str, ...], named: str
) -> None:
    paths = {kind: junk(f"bin.{kind}") for kind in ("toml", "json", "csv")}
    argv = [a.format(**paths) for a in args]
    given = next(p for p in paths.values() if p in argv)
    kind = Path(given).suffix.lstrip(".").upper()
    code, out, err = cli_main(*argv)
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and err.startswith("error: "), err
    assert f"{named} {given!r} is not a text file" in err, err
    assert f"is not a text file ({kind} is UTF-8 text; byte 1 is 0xff)" in err
    assert "codec" not in err and "Traceback" not in err and out == ""


# -- the Python API ---------------------------------------------------------------------------


def test_read_text_file_names_the_file_and_the_byte(tmp_path: Path) -> None:
    f = tmp_path / "a.toml"
    f.write_bytes(b"\xef\xbb\xbfx = 1\n")  # a byte order mark is dropped
    assert read_text_file(f, "TOML") == "x = 1\n"
    f.write_bytes(b"\xef\xbb\xbfx = '\xe9'\n")  # Latin-1: byte 8 of the file, counting the mark
    message = (
        "study file 'a.toml' is not UTF-8 text (TOML is read as UTF-8): line 1, byte 8 is 0xe9, "
        "'é' in Windows-1252, the encoding of a spreadsheet or editor set to a Western European "
        "language; save the file as UTF-8 (an editor: encoding UTF-8)"
    )  # it said "not a text file" of a text file in another encoding
    with pytest.raises(ValueError, match=f"^{re.escape(message)}$"):
        read_text_file(f, "TOML", "study file 'a.toml'")
    with pytest.raises(ValueError, match=r"^not UTF-8 text \(CSV is read as UTF-8\).*\(Excel: "):
        read_text_file(f, "CSV")
    f.write_bytes(b"x = 1\n\x00\xe9")  # a NUL byte: not text in any encoding
    with pytest.raises(
        ValueError, match=r"^not a text file \(CSV is UTF-8 text; byte 7 is 0xe9\)$"
    ):
        read_text_file(f, "CSV")
    with pytest.raises(FileNotFoundError):
        read_text_file(tmp_path / "none.toml", "TOML")


def _material(path: Path) -> object:
    from impactlab.materials import get_material

    return get_material(path, "flat")


def _law(path: Path) -> object:
    from impactlab.contact import read_law_file

    return read_law_file(path)


def _law_curves(path: Path) -> object:
    """A law file whose loading CSV is the junk file."""
    from impactlab.contact import read_law_file

    law = path.parent / "law.toml"
    law.write_text(
        'name = "junk-law"\nbody_material = "aisi-201"\nflat_material = "aisi-1010"\n'
        f'radius = "8.8 mm"\nloading = "{path.name}"\nunloading = "{path.name}"\n'
    )
    return read_law_file(law)


def _calibration(path: Path) -> object:
    from impactlab.calibrate.config import load_config

    return load_config(path)


def _measurements(path: Path) -> object:
    from impactlab.calibrate import read_measurements

    return read_measurements(path)


def _study(path: Path) -> object:
    from impactlab.sweep.studyfile import read_study_file

    return read_study_file(path)


def _markers(path: Path) -> object:
    from impactlab.experiment import read_markers

    return read_markers(path, units="mm")


def _scan(path: Path) -> object:
    from impactlab.experiment import read_scan

    return read_scan(path, pixel_size="2 um", height_unit="um")


def _curves(path: Path) -> object:
    from impactlab.contact.indentation_data import read_curves

    return read_curves(path)


# (reader, file name, what the message names it)
READERS = [
    (_material, "m.toml", "flat: '{path}'"),
    (_law, "law.toml", "law file '{path}'"),
    (_law_curves, "loading.csv", "loading CSV '{path}'"),
    (_calibration, "cal.toml", "calibration file '{path}'"),
    (_measurements, "m.csv", "measurements file '{path}'"),
    (_measurements, "m.toml", "measurements file '{path}'"),
    (_study, "study.toml", "study file '{path}'"),
    (_markers, "markers.csv", "{path}:"),
    (_scan, "scan.csv", "{path}:"),
    (_curves, "curves.json", "curves file '{path}'"),
]


@pytest.mark.parametrize(
    ("reader", "name", "named"), READERS, ids=lambda x: getattr(x, "__name__", x)
)
def test_a_reader_refuses_a_binary_file_in_one_line(
    tmp_path: Path, reader: Callable[[Path], object], name: str, named: str
) -> None:
    path = tmp_path / name
    path.write_bytes(JUNK)
    kind = path.suffix.lstrip(".").upper()
    with pytest.raises(ValueError, match="not a text file") as info:
        reader(path)
    text = str(info.value)
    assert "\n" not in text and "codec" not in text
    assert named.format(path=path) in text, text
    assert f"not a text file ({kind} is UTF-8 text; byte 1 is 0xff)" in text


def test_a_readable_file_still_reads(tmp_path: Path) -> None:
    from impactlab.contact.indentation_data import read_curves

    f = tmp_path / "curves.json"
    f.write_text(json.dumps({"format": "other", "version": 0}))
    with pytest.raises(ValueError, match="is not an indentation curves file"):
        read_curves(f)
    m = tmp_path / "m.toml"
    m.write_bytes(b'\xef\xbb\xbfE = "69 GPa"\nnu = 0.33\nSy = "276 MPa"\nrho = 2700\n')
    assert _material(m).E == 69e9  # type: ignore[attr-defined]
