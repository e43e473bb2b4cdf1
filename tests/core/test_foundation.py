"""The L0 helpers: the one matplotlib policy and the version."""

from __future__ import annotations

import os
import subprocess
import sys
from importlib.metadata import version

import pytest

from impactlab._version import __version__

_CODE = """
import sys
import matplotlib
{before}
from impactlab._mpl import pyplot
print(pyplot().get_backend().lower())
"""


def _backend(before: str = "", mplbackend: str | None = None) -> str:
    env = {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}
    if mplbackend is not None:
        env["MPLBACKEND"] = mplbackend
    res = subprocess.run(
        [sys.executable, "-c", _CODE.format(before=before)],
        env=env,
        capture_output=True,
        text=True,
        check=True,
    )
    return res.stdout.strip().splitlines()[-1]


@pytest.mark.parametrize(
    ("before", "mplbackend", "expected"),
    [
        ("", None, "agg"),  # nothing chosen: Agg
        ("", "svg", "svg"),  # the environment's choice stays
        ("matplotlib.use('pdf')", None, "pdf"),  # matplotlib.use stays
    ],
)
def test_pyplot_selects_agg_only_when_nothing_was_chosen(
    before: str, mplbackend: str | None, expected: str
) -> None:
    assert _backend(before, mplbackend) == expected


def test_version_is_the_installed_one() -> None:
    assert __version__ == version("impactlab")
