"""The documentation site builds with ``mkdocs build --strict`` (broken links, missing nav
targets, bad snippets and mkdocstrings errors all fail it), and the API pages are generated."""

from __future__ import annotations

import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.skipif(
    importlib.util.find_spec("mkdocs") is None
    or importlib.util.find_spec("mkdocstrings_handlers") is None,
    reason="mkdocs or mkdocstrings[python] is not installed",
)


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("site")
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1")
    proc = subprocess.run(
        [
            sys.executable,
            "-m",
            "mkdocs",
            "build",
            "--strict",
            "-f",
            str(ROOT / "mkdocs.yml"),
            "-d",
            str(out),
        ],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-4000:]
    return out


def test_site_builds(site: Path) -> None:
    assert (site / "index.html").exists()
    for page in (
        "tutorials/simulate",
        "tutorials/invert",
        "tutorials/analyze",
        "tutorials/sweep",
        "tutorials/reproduce",
        "verification",
        "changelog",
    ):
        assert (site / page / "index.html").exists(), page


@pytest.mark.parametrize(
    ("page", "objects"),
    [
        (
            "api/dynamics",
            (
                "impactlab.dynamics.simulate.simulate",
                "impactlab.dynamics.results.ImpactResult",
                "impactlab.dynamics.results.DentMap",
            ),
        ),
        (
            "api/analytic",
            (
                "impactlab.analytic.invert",
                "impactlab.analytic.alpha",
                "impactlab.analytic.critical_friction",
            ),
        ),
        (
            "api/contact",
            (
                "impactlab.contact.get_law",
                "impactlab.contact.law_names",
                "impactlab.contact.ContactModel",
            ),
        ),
        ("api/bodies", ("impactlab.bodies.Rod", "impactlab.bodies.Sphere")),
        ("api/experiment", ("impactlab.experiment.analyze", "impactlab.experiment.read_scan")),
        ("api/sweep", ("impactlab.sweep.Study", "impactlab.sweep.run_sweep")),
        ("api/paper", ("impactlab.paper.reproduce",)),
        (
            "api/verification",
            ("impactlab.verification.verify_hertz", "impactlab.verification.main"),
        ),
    ],
)
def test_api_pages_document_the_objects(site: Path, page: str, objects: tuple[str, ...]) -> None:
    html = (site / page / "index.html").read_text(encoding="utf-8")
    ids = set(re.findall(r'id="([^"]+)"', html))
    missing = [o for o in objects if o not in ids]
    assert not missing, missing


def test_changelog_is_included(site: Path) -> None:
    html = (site / "changelog" / "index.html").read_text(encoding="utf-8")
    assert "Unreleased" in html and "--8&lt;--" not in html
