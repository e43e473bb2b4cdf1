"""An analysed experiment's JSON (``to_dict``, results.json, ``impactlab analyze --json``) is in
SI, as docs/json-schema.md promises: angles in rad, no ``_deg`` keys, no ``"unit": "deg"``."""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"  # as conftest.EXAMPLE_DATA
CliMain = Callable[..., tuple[int, str, str]]


def _walk(node: Any, path: str = "") -> Iterator[tuple[str, Any]]:
    if isinstance(node, dict):
        for k, v in node.items():
            yield f"{path}.{k}", v
            yield from _walk(v, f"{path}.{k}")
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from _walk(v, f"{path}[{i}]")


def _degrees(record: Any) -> list[str]:
    return [
        p for p, v in _walk(record) if p.endswith("_deg") or (p.endswith(".unit") and v == "deg")
    ]


def test_to_dict_is_si(analysed_example) -> None:
    res = analysed_example
    record = res.to_dict()
    assert _degrees(record) == []
    assert res.dent is not None
    assert abs(res.dent.sliding_angle) <= math.pi  # rad
    assert record["dent"]["sliding_angle"] == {"value": res.dent.sliding_angle, "unit": "rad"}


def test_the_commands_json_is_si(cli_main: CliMain) -> None:
    code, out, err = cli_main(
        "analyze", str(DATA / "drop.csv"), str(DATA / "dent.npy"), "--pixel-size", "12 um",
        "--height-unit", "um", "--up", "+y", "--geometry", str(DATA / "markers.toml"), "--json",
    )  # fmt: skip
    assert code == 0, err
    assert _degrees(json.loads(out)) == []


def test_the_saved_record_names_its_options_and_version(tmp_path: Path) -> None:
    """results.json is the folder's record of the analysis: with the settings as given and the
    version that made it, what repeats it."""
    import tomllib

    import numpy as np

    import impactlab
    from impactlab.experiment import MarkerGeometry, analyze

    table = tomllib.loads((DATA / "markers.toml").read_text())["markers"]
    geometry = MarkerGeometry.from_mapping(table)
    analyze(
        DATA / "drop.csv", None, geometry=geometry, up="+y", out_dir=tmp_path, figures=False,
        n_samples=500,
    )  # fmt: skip
    record = json.loads((tmp_path / "results.json").read_text())
    assert record["impactlab_version"] == impactlab.__version__
    options = record["options"]
    assert options["up"] == "+y" and options["n_samples"] == 500 and options["gravity"] is False
    assert np.allclose(options["geometry"]["markers"], geometry.markers)
    assert options["geometry"]["labels"] == list(geometry.labels or ())
