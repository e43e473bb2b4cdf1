"""mkdocs hook: a documentation site that works offline and from disk.

- **Math typeset at build time.** pymdownx.arithmatex (``generic: true``) marks every ``$...$``
  and ``$$...$$`` formula; this hook converts the TeX inside to MathML with ``latex2mathml``
  (PyPI, pure Python). Chosen over vendoring MathJax because MathML needs no JavaScript and no
  font or script files next to the pages (MathJax 3's component plus its fonts is over 1 MB to
  commit and keep current); Chromium (>= 109), Firefox and Safari render MathML natively, the
  pages stay readable from disk, on an HPC login node or in a plane, and a formula that cannot
  be converted fails the build instead of showing raw TeX to the reader.
- **DOIs are links.** Every ``doi:10.xxxx/...`` (or bare ``10.xxxx/...``) in the text of a page,
  the docstrings rendered by mkdocstrings included, becomes a link to https://doi.org/.
- **Sphinx roles read as names.** A docstring's ``:func:`name``` shows as ``name`` in code:
  mkdocstrings leaves the role's marker as text.
- **A star after a symbol is a star.** ``E*^4``, ``delta*^1.5``, ``e* - 1`` outside code: the
  markdown extension :class:`LiteralStars` escapes a lone ``*`` that directly follows a letter,
  digit or closing bracket, so that two of them on a line no longer make the text between them
  emphasis (which silently changed formulas). Intended ``*emphasis*`` and ``**strong**`` are kept.
  It is added to the markdown extensions before mkdocstrings copies them, so docstrings get it too.
"""

from __future__ import annotations

import html
import re
from typing import Any

from latex2mathml.converter import convert as tex_to_mathml
from markdown import Extension, Markdown
from markdown.preprocessors import Preprocessor
from mkdocs.plugins import event_priority

__all__ = [
    "LiteralStars",
    "drop_roles",
    "escape_stars",
    "link_dois",
    "relative_root_links",
    "typeset_math",
]

# --- math -----------------------------------------------------------------------------------

_MATH = re.compile(
    r'<(?P<tag>span|div) class="arithmatex">(?P<tex>.*?)</(?P=tag)>',
    re.DOTALL,
)
_DELIMS = {"span": (r"\(", r"\)"), "div": (r"\[", r"\]")}


def typeset_math(page_html: str) -> str:
    """Replace the TeX of every arithmatex element by MathML (``display="block"`` for ``div``).

    Raises ValueError naming the formula when one is not delimited as arithmatex writes it or
    latex2mathml cannot convert it.
    """

    def convert(m: re.Match[str]) -> str:
        tag, raw = m["tag"], html.unescape(m["tex"]).strip()
        left, right = _DELIMS[tag]
        if not (raw.startswith(left) and raw.endswith(right)):
            raise ValueError(f"arithmatex element without {left} {right} delimiters: {raw!r}")
        tex = raw[len(left) : -len(right)].strip()
        if "$" in tex:  # two $$ formulas on adjacent lines are read as one
            raise ValueError(f"a $ inside the formula {tex!r}: separate formulas by a blank line")
        try:
            mathml = tex_to_mathml(tex, display="block" if tag == "div" else "inline")
        except Exception as exc:  # latex2mathml raises many exception types for bad TeX
            raise ValueError(f"latex2mathml cannot typeset {tex!r}: {exc}") from exc
        # latex2mathml passes unknown commands through as text, and the column separators of
        # an environment it does not know (aligned) as the character &
        unknown = re.findall(r"\\[A-Za-z]+|<mi>&</mi>", mathml)
        if unknown:
            raise ValueError(f"latex2mathml cannot typeset {tex!r}: unknown {unknown}")
        return f'<{tag} class="arithmatex">{mathml}</{tag}>'

    return _MATH.sub(convert, page_html)


# --- DOI links ------------------------------------------------------------------------------

# the text between tags; the contents of these elements are left alone
_SKIP = ("a", "code", "pre", "script", "style", "math", "title", "textarea")
_TOKEN = re.compile(r"(<!--.*?-->|<[^>]+>)", re.DOTALL)
_TAG_NAME = re.compile(r"</?\s*([a-zA-Z][a-zA-Z0-9]*)")
_DOI = re.compile(r"(?<![\w/.:-])(?P<prefix>doi:\s?)?(?P<doi>10\.\d{4,9}/[^\s<>\"']+)", re.I)


def _trim_doi(doi: str) -> str:
    """The DOI without the sentence's punctuation: trailing ``.,;:`` and unbalanced ``)`` ``]``."""
    while doi:
        last = doi[-1]
        pair = {")": "(", "]": "["}.get(last)
        if not (last in ".,;:" or (pair and doi.count(last) > doi.count(pair))):
            break
        doi = doi[:-1]
    return doi


def _link_text(text: str) -> str:
    def link(m: re.Match[str]) -> str:
        doi = _trim_doi(m["doi"])
        rest = m["doi"][len(doi) :]
        label = (m["prefix"] or "") + doi
        href = "https://doi.org/" + html.escape(html.unescape(doi), quote=True)
        return f'<a class="doi" href="{href}">{label}</a>{rest}'

    return _DOI.sub(link, text)


def link_dois(page_html: str) -> str:
    """Every DOI in the text of ``page_html`` (not inside links, code, math or scripts) as a
    link to https://doi.org/."""
    out: list[str] = []
    skip: list[str] = []
    for part in _TOKEN.split(page_html):
        if part.startswith("<"):
            name = _TAG_NAME.match(part)
            tag = name.group(1).lower() if name else ""
            if tag in _SKIP and not part.endswith("/>"):
                if part.startswith("</"):
                    if tag in skip:
                        del skip[len(skip) - 1 - skip[::-1].index(tag) :]
                else:
                    skip.append(tag)
            out.append(part)
        else:
            out.append(part if skip else _link_text(part))
    return "".join(out)


# --- literal stars --------------------------------------------------------------------------

# segments left as they are: inline code, math, and intended emphasis / strong emphasis
_PROTECTED = re.compile(
    r"(?P<code>(`+).+?\2)"
    r"|(?P<math>\$\$.+?\$\$|\$[^$\s](?:[^$]*[^$\s])?\$|\\\(.+?\\\))"
    r"|(?P<strong>(?<![\w*\\])\*\*(?=\S).+?(?<=\S)\*\*(?![\w*]))"
    r"|(?P<em>(?<![\w*\\])\*(?=[^\s*]).+?(?<=[^\s*\\])\*(?![\w*]))",
    re.DOTALL,  # emphasis and code spans may run over the lines of a paragraph
)
_LONE_STAR = re.compile(r"(?<=[\w)\]}])(?<![*\\])\*(?!\*)")


def escape_stars(text: str) -> str:
    """``text`` (a paragraph) with each lone ``*`` that follows a word character or a closing
    bracket escaped, outside code spans, math and intended emphasis (``*a b*``, ``**a**``)."""
    out, pos = [], 0
    for m in _PROTECTED.finditer(text):
        out.append(_LONE_STAR.sub(r"\\*", text[pos : m.start()]))
        out.append(m.group(0))
        pos = m.end()
    out.append(_LONE_STAR.sub(r"\\*", text[pos:]))
    return "".join(out)


class _StarPreprocessor(Preprocessor):
    """Runs after the fenced code blocks are stashed (their priority is higher)."""

    def run(self, lines: list[str]) -> list[str]:
        out: list[str] = []
        para: list[str] = []  # the text lines of the current paragraph
        code = math = False
        blank = True
        for ln in lines:
            # an indented code block: indented lines after a blank line (kept as they are)
            code = ln.startswith(("    ", "\t")) and (blank or code)
            blank = not ln.strip()
            opens_or_closes = ln.count("$$") % 2 == 1  # a $$ block of several lines
            if code or blank or math or opens_or_closes:
                out += escape_stars("\n".join(para)).split("\n") if para else []
                para = []
                out.append(ln)
            else:
                para.append(ln)
            math ^= opens_or_closes
        out += escape_stars("\n".join(para)).split("\n") if para else []
        return out


class LiteralStars(Extension):
    """Markdown extension: a ``*`` right after a symbol is literal (see the module docstring)."""

    def extendMarkdown(self, md: Markdown) -> None:  # noqa: N802 (Markdown's API name)
        md.preprocessors.register(_StarPreprocessor(md), "impactlab_literal_stars", 5)


# --- mkdocs events --------------------------------------------------------------------------


@event_priority(100)  # before mkdocstrings copies the markdown extensions for the docstrings
def on_config(config: Any) -> Any:
    config.markdown_extensions.append(LiteralStars())
    return config


# --- Sphinx roles -----------------------------------------------------------------------------

_ROLE_BACKTICKS = re.compile(r":(?:func|class|data|meth|mod|attr|exc|obj):`([^`<>]+)`")
_ROLE_CODE = re.compile(r":(?:func|class|data|meth|mod|attr|exc|obj):(?=<code>)")


def drop_roles(page_html: str) -> str:
    """A docstring's Sphinx role (``:func:`name```) as its name in code: mkdocstrings renders
    the role's marker as text (``:func:<code>name</code>``), or, inside code, the whole role."""
    return _ROLE_CODE.sub("", _ROLE_BACKTICKS.sub(r"\1", page_html))


def on_page_content(html_text: str, **_: Any) -> str:
    return link_dois(typeset_math(drop_roles(html_text)))


_ROOT_URL = re.compile(r'(?P<attr>\b(?:href|src)=")/(?!/)')


def relative_root_links(page_html: str) -> str:
    """``href="/x"`` and ``src="/x"`` as ``href="x"``: without a ``site_url`` mkdocs writes the
    404 page's links from the server root, which from disk (file://) is the file system's root.
    The 404 page lies in the site's root, so the relative links resolve from disk and from a
    server that serves the site at any path (for a missing page in the site's root)."""
    return _ROOT_URL.sub(r"\g<attr>", page_html)


def on_post_template(output_content: str, template_name: str, **_: Any) -> str:
    return relative_root_links(output_content) if template_name == "404.html" else output_content
