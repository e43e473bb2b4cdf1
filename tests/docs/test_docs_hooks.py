"""The build-time helpers of the documentation (docs/_hooks/offline.py), without a build."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

import pytest

HOOK = Path(__file__).resolve().parents[2] / "docs" / "_hooks" / "offline.py"


@pytest.fixture(scope="module")
def hook() -> ModuleType:
    for dep in ("mkdocs", "latex2mathml"):
        if importlib.util.find_spec(dep) is None:
            pytest.skip(f"{dep} is not installed (the docs extra of pyproject.toml)")
    spec = importlib.util.spec_from_file_location("impactlab_docs_offline", HOOK)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_math_becomes_mathml(hook: ModuleType) -> None:
    page = (
        '<p>a <span class="arithmatex">\\(E^{*4} &lt; \\tfrac{1}{2}\\)</span></p>'
        '<div class="arithmatex">\\[\\dot\\theta = \\omega\\]</div>'
    )
    out = hook.typeset_math(page)
    assert out.count("<math") == 2 and 'display="block"' in out and "\\(" not in out
    assert "<mo>&#x0003C;</mo>" in out and "<mfrac>" in out


def test_bad_math_fails_the_build(hook: ModuleType) -> None:
    with pytest.raises(ValueError, match="latex2mathml cannot typeset"):
        hook.typeset_math('<span class="arithmatex">\\(x^\\)</span>')
    with pytest.raises(ValueError, match="blank line"):
        hook.typeset_math('<div class="arithmatex">\\[a $$\n$$ b\\]</div>')
    with pytest.raises(ValueError, match="unknown"):
        hook.typeset_math('<span class="arithmatex">\\(\\unknowncmd x\\)</span>')


@pytest.mark.parametrize(
    ("text", "href", "after"),
    [
        ("see doi:10.1115/1.1866166.", "10.1115/1.1866166", "."),
        ("(Shampine, doi:10.1016/0771-050X(80)90013-3);", "10.1016/0771-050X(80)90013-3", ");"),
        ("| 10.1557/JMR.2004.0468 |", "10.1557/JMR.2004.0468", " |"),
    ],
)
def test_dois_become_links(hook: ModuleType, text: str, href: str, after: str) -> None:
    out = hook.link_dois(f"<p>{text}</p>")
    assert f'href="https://doi.org/{href}"' in out
    assert out.split("</a>")[1].startswith(after)


def test_dois_in_code_and_links_are_kept(hook: ModuleType) -> None:
    page = (
        '<a href="https://doi.org/10.1115/1.1866166">doi:10.1115/1.1866166</a>'
        "<code>doi:10.1115/1.1866166</code><pre><span>10.1115/1.1866166</span></pre>"
    )
    assert hook.link_dois(page) == page


@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("V_y = sqrt(p_y^5 R^3 / (30 E*^4 m)) and E* a", r"(30 E\*^4 m)) and E\* a"),
        ("abs(e* - 1), abs(e - 1)", r"abs(e\* - 1)"),
        ("Johnson, *Contact Mechanics* (1985), **bold**", "*Contact Mechanics* (1985), **bold**"),
        ("`E*^4` and $E^{*4}$ stay", "`E*^4` and $E^{*4}$ stay"),
        ("* a list item with delta*", r"* a list item with delta\*"),
    ],
)
def test_symbol_stars_are_escaped(hook: ModuleType, line: str, expected: str) -> None:
    assert expected in hook.escape_stars(line)


def test_emphasis_over_two_lines_is_kept(hook: ModuleType) -> None:
    import markdown

    text = "Brake, *An analytical contact model for\nnormal impacts*, Int. J. with E* a and E* b.\n"
    html = markdown.markdown(text, extensions=[hook.LiteralStars()])
    assert "<em>An analytical contact model for\nnormal impacts</em>" in html
    assert html.count("<em>") == 1 and "E* a and E* b" in html


def test_stars_in_indented_code_are_kept(hook: ModuleType) -> None:
    import markdown

    text = "Text E* a and E* b.\n\n    code E* x and E* y\n"
    html = markdown.markdown(text, extensions=[hook.LiteralStars()])
    assert "<em>" not in html and "code E* x and E* y" in html


def test_404_links_become_relative(hook: ModuleType) -> None:
    out = hook.relative_root_links('<a href="/engine/index.html"><img src="/a.png"><a href="//x">')
    assert out == '<a href="engine/index.html"><img src="a.png"><a href="//x">'


def test_sphinx_roles_read_as_names(hook: ModuleType) -> None:
    """mkdocstrings left ``:func:`` before the name (197 places in the API pages)."""
    page = (
        "<p>the form :func:<code>impactlab.analytic.invert</code> takes; :class:<code>Rod</code>"
        "</p><code>from :func:`impactlab.experiment.read_markers`.</code><p>ratio: 2</p>"
    )
    assert hook.drop_roles(page) == (
        "<p>the form <code>impactlab.analytic.invert</code> takes; <code>Rod</code></p>"
        "<code>from impactlab.experiment.read_markers.</code><p>ratio: 2</p>"
    )
