"""The documentation site builds with ``mkdocs build --strict`` (broken links, missing nav
targets, bad snippets and mkdocstrings errors all fail it), the API pages are generated, and
the site works offline and from disk: one ``page.html`` per page, math typeset as MathML, no
script, stylesheet or font from another host, DOIs as links, 404.html with relative links."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

# the built site: the session fixture ``site`` of conftest.py (skips without the docs extra)


def test_site_builds(site: Path) -> None:
    assert (site / "index.html").exists()
    for page in (
        "tutorials/simulate.html",
        "tutorials/invert.html",
        "tutorials/analyze.html",
        "tutorials/sweep.html",
        "tutorials/reproduce.html",
        "verification/index.html",
        "engine/benchmarks.html",
        "changelog.html",
    ):
        assert (site / page).exists(), page
    # use_directory_urls: false, so that the site opens from disk without a web server
    assert not (site / "tutorials" / "simulate" / "index.html").exists()


@pytest.mark.parametrize(
    ("page", "objects"),
    [
        (
            "api/dynamics",
            (
                "impactlab.dynamics.simulate.simulate",
                "impactlab.dynamics.results.ImpactResult",
                "impactlab.dynamics.results.DentMap",
                "impactlab.dynamics.simulate.rerun",
                "impactlab.dynamics.provenance.input_record",
                "impactlab.dynamics.plotting.plot_force_time",
                "impactlab.dynamics.plotting.save_figures",
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
        ("api/fe", ("impactlab.fe.indent", "impactlab.fe.impact", "impactlab.fe.tabulated_law")),
        ("api/flags", ("impactlab.flags.ResultFlag", "impactlab.flags.messages")),
        (
            "api/verification",
            ("impactlab.verification.verify_hertz", "impactlab.verification.main"),
        ),
    ],
)
def test_api_pages_document_the_objects(site: Path, page: str, objects: tuple[str, ...]) -> None:
    html = (site / f"{page}.html").read_text(encoding="utf-8")
    ids = set(re.findall(r'id="([^"]+)"', html))
    missing = [o for o in objects if o not in ids]
    assert not missing, missing


def test_changelog_is_included(site: Path) -> None:
    html = (site / "changelog.html").read_text(encoding="utf-8")
    assert "Unreleased" in html and "--8&lt;--" not in html


def _pages(site: Path) -> list[Path]:
    return sorted(p for p in site.rglob("*.html") if "search" not in p.parts)


def test_no_file_from_another_host(site: Path) -> None:
    """No script, stylesheet, font or image is loaded from the network (MathJax from a CDN and
    Google fonts were): the site reads the same offline."""
    remote = re.compile(r'<(?:script|link|img)\b[^>]*\b(?:src|href)="(?:https?:)?//', re.I)
    offenders = [str(p.relative_to(site)) for p in _pages(site) if remote.search(p.read_text())]
    assert not offenders, offenders
    css = "".join(p.read_text() for p in site.rglob("*.css"))
    assert "fonts.googleapis" not in css and "@import url(http" not in css


def test_math_is_typeset_at_build_time(site: Path) -> None:
    html = (site / "engine" / "index.html").read_text(encoding="utf-8")
    assert html.count("<math") >= 100  # the engine page has over 100 formulas
    assert 'display="block"' in html
    for page in _pages(site):
        text = page.read_text(encoding="utf-8")
        for m in re.finditer(r'class="arithmatex">(.{0,40})', text):
            assert m.group(1).startswith("<math"), (page.name, m.group(1))


def test_symbol_stars_are_not_emphasis(site: Path) -> None:
    """``E*^4`` in a page and in a docstring (mkdocstrings) stays a formula."""
    for page in ("laws/thornton.html", "verification/index.html", "api/contact.html"):
        html = (site / page).read_text(encoding="utf-8")
        assert "E*^4" in html, page
        assert not re.search(r"E<em>|\*\^4 m\)\)</em>", html), page


def test_dois_are_links(site: Path) -> None:
    html = (site / "laws" / "index.html").read_text(encoding="utf-8")
    assert '<a class="doi" href="https://doi.org/10.1115/1.1866166">' in html
    unlinked = []
    for page in _pages(site):
        text = re.sub(
            r"<a\b.*?</a>|<(code|pre|script|math)\b.*?</\1>", "", page.read_text(), flags=re.S
        )
        text = re.sub(r"<[^>]+>", "", text)
        unlinked += [f"{page.name}: {m}" for m in re.findall(r"\b10\.\d{4,9}/\S+", text)]
    assert not unlinked, unlinked[:10]


def test_404_links_resolve_from_disk(site: Path) -> None:
    html = (site / "404.html").read_text(encoding="utf-8")
    links = re.findall(r'(?:href|src)="([^"#?]+)', html)
    local = [u for u in links if not re.match(r"[a-z]+:", u)]
    assert local and not [u for u in local if u.startswith("/")]
    missing = [u for u in local if not (site / u).exists()]
    assert not missing, missing
    assert 'href="engine/benchmarks.html"' in html  # the benchmarks page is in the nav


def test_every_link_resolves_from_disk(site: Path) -> None:
    """Every relative link and asset of every page names a file of the site (opened from disk
    there is no web server to turn a folder into its index.html)."""
    broken = []
    for page in _pages(site):
        for url in re.findall(r'(?:href|src)="([^"]+)"', page.read_text(encoding="utf-8")):
            path = url.split("#")[0].split("?")[0]
            if not path or re.match(r"[a-z][a-z0-9+.-]*:|//", path):
                continue  # an anchor on the page, or another scheme (https:, data:, mailto:)
            # from disk, a path from the root starts at the file system's root
            if path.startswith("/") or not (page.parent / path).is_file():
                broken.append(f"{page.relative_to(site)} -> {url}")
    assert not broken, broken[:10]
