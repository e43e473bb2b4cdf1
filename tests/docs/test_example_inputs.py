"""The input files that the user docs' commands name exist in the repository (examples/data/)
and read through the readers those commands use; a TOML block shown as a file's content holds
that file's study; the signatures the materials page documents are the code's. Fast: readers
only, no calibration or sweep."""

from __future__ import annotations

import inspect
import math
import re
import tomllib
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
DATA = ROOT / "examples" / "data"

#: the pages whose commands read an input file, and the files each must name
PAGES = {
    "calibrate.md": ("examples/data/drops.csv",),
    "tutorials/invert.md": ("examples/data/measurements.toml",),
    "analytic.md": ("examples/data/measurements.toml",),
    "tutorials/analyze.md": (
        "examples/data/drop.csv",
        "examples/data/dent.npy",
        "examples/data/markers.toml",
        "examples/analyze_experiment.py",
    ),
    "experiment.md": (
        "examples/data/drop.csv",
        "examples/data/dent.npy",
        "examples/data/markers.toml",
        "examples/analyze_experiment.py",
    ),
}
#: input files that a command once named without any folder, where a fresh clone has none
BARE = ("drops.csv", "measurements.toml", "drop.csv", "dent.npy", "markers.toml")
#: what ``python examples/analyze_experiment.py drop-files`` writes into drop-files/
EXAMPLE_WRITES = ("drop.c3d", "dent.x3p", "markers.toml")


def _text(page: str) -> str:
    return (DOCS / page).read_text(encoding="utf-8")


def _blocks(text: str, lang: str = r"\w*") -> list[str]:
    """The fenced code blocks of a page (of one language when ``lang`` is given)."""
    return re.findall(rf"```{lang}\n(.*?)```", text, flags=re.S)


def _commands(page: str) -> list[str]:
    """The shell commands and Python calls in a page's code blocks (continuation lines joined)."""
    out = []
    for block in _blocks(_text(page)):
        joined = re.sub(r"\\\n\s*", " ", block)
        out += [ln for ln in joined.splitlines() if re.search(r"impactlab |calibrate\(", ln)]
    return out


@pytest.mark.parametrize("page", sorted(PAGES))
def test_every_named_input_file_exists(page: str) -> None:
    text = _text(page)
    named = set(re.findall(r"examples/[\w./-]+\.(?:csv|toml|npy|py)\b", text))
    assert set(PAGES[page]) <= named, (page, named)
    missing = sorted(n for n in named if not (ROOT / n).is_file())
    assert not missing, f"{page} names files the repository lacks: {missing}"


@pytest.mark.parametrize("page", sorted(PAGES))
def test_no_command_reads_a_file_a_fresh_clone_lacks(page: str) -> None:
    """A command names a file by its path in the repository, or one the example script writes
    into drop-files/ (the page says to run it first)."""
    text = _text(page)
    for cmd in _commands(page):
        for token in re.findall(r"[\w./-]+\.(?:csv|toml|npy|c3d|x3p)\b", cmd):
            if token.startswith("drop-files/"):
                assert token.removeprefix("drop-files/") in EXAMPLE_WRITES, (page, cmd)
                assert "python examples/analyze_experiment.py drop-files" in text, page
            elif token in ("cal.toml", "STUDY.toml") or token.startswith("calib/"):
                continue  # a file the reader writes, or a placeholder
            else:
                assert token not in BARE and (ROOT / token).is_file(), (page, token, cmd)


def test_drops_csv_reads_as_calibration_measurements() -> None:
    from impactlab.calibrate import read_measurements

    m = read_measurements(DATA / "drops.csv")
    assert m.n_drops == 5
    assert set(m.quantities) == {"e", "spin_out", "delta_p", "scar_length"}
    assert m.inputs["angle"] == pytest.approx([math.radians(a) for a in (20, 45, 70, 30, 60)])
    assert 40e-6 < m.observed["delta_p"].min() < m.observed["delta_p"].max() < 300e-6
    assert m.sigma["delta_p"] == pytest.approx([3e-6] * 5)
    assert "mu" not in m.inputs or all(map(math.isnan, m.inputs["mu"]))  # mu is the free one


def test_the_calibration_file_block_reads(tmp_path: Path) -> None:
    """The page's cal.toml, saved in the repository root, finds its measurements there."""
    from impactlab.calibrate import read_measurements
    from impactlab.calibrate.config import load_config

    block = next(b for b in _blocks(_text("calibrate.md"), "toml") if "measurements =" in b)
    rel = tomllib.loads(block)["measurements"]
    assert (ROOT / rel).is_file(), rel
    cfg = tmp_path / "cal.toml"
    cfg.write_text(block.replace(f'"{rel}"', f'"{(ROOT / rel).as_posix()}"'), encoding="utf-8")
    kw = load_config(cfg)
    assert read_measurements(kw["measurements"]).n_drops == 5
    assert [m.name for m in kw["models"]][:2] == ["ghaednia/coulomb", "jackson-green/coulomb"]


def test_measurements_toml_reads_as_the_invert_command_does() -> None:
    from impactlab.cli._common import load_toml
    from impactlab.cli.invert import run_invert
    from impactlab.cli.invert_inputs import from_file

    path = DATA / "measurements.toml"
    values, sigmas, rod, extra, _ = from_file(load_toml(path, "--file"))
    assert values["angle"] == pytest.approx(math.radians(20))
    assert values["delta_p"] == pytest.approx(22e-6) and values["L_s"] == pytest.approx(1.4e-3)
    assert sigmas == pytest.approx({"L_s": 50e-6, "mu": 0.01}) and not rod and not extra
    # docs/tutorials/invert.md: with gravity, T = 4.049 ms at 20 deg
    result, _ = run_invert(file=path, gravity=True, samples=200)
    assert result.duration * 1e3 == pytest.approx(4.049, abs=5e-4)


def test_the_analytic_page_shows_measurements_toml_whole() -> None:
    block = next(b for b in _blocks(_text("analytic.md"), "toml") if 'vi = "-1.41 m/s"' in b)
    assert tomllib.loads(block) == tomllib.loads((DATA / "measurements.toml").read_text())


def test_plain_drop_files_read_as_the_analyze_command_does() -> None:
    """drop.csv, dent.npy and markers.toml with the options the docs' command gives."""
    from impactlab.cli.analyze import _geometry_from
    from impactlab.experiment import measure_dent, read_markers, read_scan

    cmd = next(c for c in _commands("tutorials/analyze.md") if "dent.npy" in c)
    pixel = re.search(r'--pixel-size "([^"]+)"', cmd)
    unit = re.search(r"--height-unit (\w+)", cmd)
    assert pixel is not None and unit is not None and "--up +y" in cmd
    tracks = read_markers(DATA / "drop.csv")
    assert tracks.labels == ("M1", "M2", "M3") and tracks.rate == pytest.approx(500.0)
    geometry = _geometry_from(str(DATA / "markers.toml"), {})
    assert geometry is not None and tuple(geometry.labels or ()) == tracks.labels
    hm = read_scan(DATA / "dent.npy", pixel_size=pixel.group(1), height_unit=unit.group(1))
    assert hm.dx == pytest.approx(12e-6)
    dent = measure_dent(hm)
    assert dent.delta_p.value == pytest.approx(22e-6, rel=0.02)
    assert dent.sliding_length.value == pytest.approx(1400e-6, rel=0.02)


def test_binary_example_inputs_are_small() -> None:
    for p in DATA.iterdir():
        assert p.stat().st_size < 200_000, p.name


def test_the_sweep_tutorial_shows_the_whole_study_file() -> None:
    """The block shown as examples/study-regime-map.toml holds that file's study: every key
    (only its comments may be left out, and the page says so)."""
    text = _text("tutorials/sweep.md")
    after = text[text.index("`examples/study-regime-map.toml`") :]
    block = _blocks(after, "toml")[0]
    path = ROOT / "examples" / "study-regime-map.toml"
    assert tomllib.loads(block) == tomllib.loads(path.read_text(encoding="utf-8"))
    assert "comment lines left out" in after[: after.index("```toml")]


@pytest.mark.parametrize("call", ["SwiftHardening.from_tensile", "PowerLawHardening"])
def test_materials_page_names_the_parameters(call: str) -> None:
    """docs/materials.md writes each call with the code's parameter names, in their order, and
    names every parameter without a default."""
    from impactlab.materials import hardening

    obj: Any = hardening
    for attr in call.split("."):
        obj = getattr(obj, attr)
    shown = re.search(rf"`{re.escape(call)}\(([^)]*)\)`", _text("materials.md"))
    assert shown is not None, call
    names = [a.split("=")[0].strip() for a in shown.group(1).replace("\n", " ").split(",")]
    sig = inspect.signature(obj).parameters
    assert all(n in sig for n in names), (names, list(sig))
    assert names == sorted(names, key=list(sig).index)
    required = [n for n, p in sig.items() if p.default is inspect.Parameter.empty]
    assert set(required) <= set(names), (required, names)
