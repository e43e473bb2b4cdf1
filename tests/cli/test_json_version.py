"""Every ``--json`` document names the impactlab that wrote it (``impactlab_version`` at its
top level): the listings of laws and materials beside their names, one law, the laws'
accuracy and ``warm`` too (the sweep's documents: tests/cli/test_sweep_run_json.py)."""

from __future__ import annotations

import json
from typing import Any

import pytest

from impactlab._version import __version__


@pytest.mark.parametrize(
    "args",
    [
        ("laws", "--json"),
        ("laws", "hertz", "--json"),
        ("laws", "--accuracy", "--json"),
        ("materials", "--json"),
    ],
)
def test_the_document_names_its_version(cli_main: Any, args: tuple[str, ...]) -> None:
    code, out, err = cli_main(*args)
    assert code == 0, err
    assert json.loads(out)["impactlab_version"] == __version__


def test_the_listings_keep_their_names(cli_main: Any) -> None:
    from impactlab.contact import law_names
    from impactlab.materials import PRESETS

    laws = json.loads(cli_main("laws", "--json")[1])
    assert list(laws) == [*law_names(), "impactlab_version"]
    materials = json.loads(cli_main("materials", "--json")[1])
    assert list(materials) == [*PRESETS, "impactlab_version"]


def test_warm_json_names_its_version(cli_main: Any, monkeypatch: pytest.MonkeyPatch) -> None:
    import impactlab.dynamics.warm as warm

    monkeypatch.setattr(warm, "warm_in_processes", lambda parts, jobs: [])
    code, out, err = cli_main("warm", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["impactlab_version"] == __version__ and doc["parts"] == []
