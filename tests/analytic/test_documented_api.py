"""What docs/analytic.md and docs/tutorials/invert.md say about the analytic module holds: the
signatures of Sec. 9 are the functions' own (keyword names included), the sticking angles of
Sec. 3 are those mu_c gives, and the tutorial quotes the command's angle errors verbatim."""

from __future__ import annotations

import inspect
import math
import re
from collections.abc import Callable
from pathlib import Path

import pytest
from scipy.optimize import brentq

import impactlab.analytic as an
import impactlab.bodies as bodies

DOCS = Path(__file__).resolve().parents[2] / "docs"
ANALYTIC = (DOCS / "analytic.md").read_text(encoding="utf-8")
TUTORIAL = (DOCS / "tutorials" / "invert.md").read_text(encoding="utf-8")
CliMain = Callable[..., tuple[int, str, str]]


def _api_block() -> str:
    section = ANALYTIC.split("## 9. API", 1)[1]
    return section.split("```text", 1)[1].split("```", 1)[0]  # a listing, not Python


def _documented_signatures() -> dict[str, list[str]]:
    """name -> the parameter names of each ``name(...) -> ...`` line of Sec. 9's block."""
    block = " ".join(_api_block().split("\n"))
    out = {}
    for name, params in re.findall(r"(\w+)\(([^()]*)\)\s*->", block):
        out[name] = [p.split("=")[0].strip() for p in params.split(",") if p.strip() != "*"]
    return out


def test_section_9_lists_the_functions_signatures() -> None:
    documented = _documented_signatures()
    assert {"impact_duration", "invert", "sliding_length", "lever_arms"} <= set(documented)
    for name, params in documented.items():
        func = getattr(an, name, None) or getattr(bodies, name)
        assert params == list(inspect.signature(func).parameters), name


def test_section_3_sticking_angles() -> None:
    text = ANALYTIC.split("## 3.", 1)[1].split("## 4.", 1)[0]
    pattern = (
        r"is ([\d.]+) deg for mu = 0\.10, ([\d.]+) deg for\s+0\.13, ([\d.]+) deg for 0\.20, "
        r"([\d.]+) deg for 0\.30 and ([\d.]+) deg for 0\.50"
    )
    found = re.search(pattern, text)
    assert found is not None
    for mu, printed in zip((0.10, 0.13, 0.20, 0.30, 0.50), found.groups(), strict=True):
        theta = brentq(lambda th, mu=mu: an.critical_friction(th) - mu, 0.5, 0.5 * math.pi - 1e-6)
        assert float(printed) == round(math.degrees(theta), 1), mu


@pytest.mark.parametrize("angle", ["90 deg", "0 deg"])
def test_the_tutorial_quotes_the_angle_errors(cli_main: CliMain, angle: str) -> None:
    code, _, err = cli_main("invert", "--angle", angle, "--vi", "-1.41 m/s", "--e", "0.5",
                            "--mu", "0.2", "--delta-p", "22 um", "--ls", "1400 um")  # fmt: skip
    message = err.strip().removeprefix("error: ")
    assert code == 2 and message.startswith("--angle must lie in (0, 90) deg")
    assert message in " ".join(TUTORIAL.split())
