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


def test_heavy_modules_are_imported_on_first_use_only() -> None:
    """``import impactlab`` imports neither pint nor scipy's optimize, linalg and integrate (about
    0.5 s together); the command line's modules do not import pint. The first use imports them
    and gives the same numbers as before."""
    code = (
        "import sys, impactlab\n"
        "heavy = ('pint', 'scipy.optimize', 'scipy.linalg', 'scipy.integrate')\n"
        "loaded = [m for m in heavy if m in sys.modules]\n"
        "assert not loaded, f'imported by import impactlab: {loaded}'\n"
        "import impactlab.cli\n"
        "assert 'pint' not in sys.modules, 'pint imported by impactlab.cli'\n"
        "from impactlab.units import to_si\n"
        "assert abs(to_si('8.8 mm', 'm') - 0.0088) < 1e-15\n"
        "from impactlab.bodies.beam_modes import eb_beta_l\n"
        "assert abs(eb_beta_l(1)[0] - 4.730040744862704) < 1e-12\n"
        "assert 'pint' in sys.modules and 'scipy.optimize' in sys.modules\n"
    )
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, res.stderr
