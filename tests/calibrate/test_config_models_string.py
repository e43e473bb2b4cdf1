"""A calibration file's ``models`` given as one text is one model (it was split into its
characters: ``model 'g': unknown contact law 'g'``), one ``[model]`` table is one model, and
models of another kind are refused naming the key."""

from __future__ import annotations

from pathlib import Path

import pytest

from impactlab.calibrate.config import load_config

HEAD = 'measurements = "drops.csv"\n'
TAIL = '[parameters]\nmu = "uniform(0, 0.6)"\n'


def _names(tmp_path: Path, text: str) -> list[str]:
    path = tmp_path / "cfg.toml"
    path.write_text(HEAD + text + TAIL)
    return [m.name for m in load_config(path)["models"]]


@pytest.mark.parametrize(
    ("text", "names"),
    [
        ('models = "ghaednia/coulomb"\n', ["ghaednia/coulomb"]),
        ('models = ["ghaednia/coulomb", "jackson-green/coulomb"]\n',
         ["ghaednia/coulomb", "jackson-green/coulomb"]),
        ('model = "jackson-green/coulomb"\n', ["jackson-green/coulomb"]),
        ('[model]\nlaw = "ghaednia"\n', ["ghaednia/coulomb"]),
        ('[[model]]\nlaw = "ghaednia"\n[[model]]\nlaw = "jackson-green"\n',
         ["ghaednia/coulomb", "jackson-green/coulomb"]),
    ],
)  # fmt: skip
def test_one_model_text_or_table_is_one_model(tmp_path: Path, text: str, names: list[str]):
    assert _names(tmp_path, text) == names


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("models = 5\n",
         r"cfg.toml: models must be a list of model texts, e.g. \[\"ghaednia/coulomb\"\], got 5$"),
        ("model = true\n", r"cfg.toml: model must be \[\[model\]\] tables .*, got True$"),
    ],
)  # fmt: skip
def test_models_of_another_kind_are_refused_naming_the_key(tmp_path: Path, text: str, match: str):
    with pytest.raises(ValueError, match=match):
        _names(tmp_path, text)
