"""A tiny document model rendered to Markdown and to a self-contained HTML page (no extra deps).

Blocks: ``Heading``, ``Para`` (plain text; `backticks` become code), ``Table`` (a DataFrame),
``Figure`` (an image path relative to the report), ``Code`` (preformatted text), ``Bullets``.

The HTML page needs nothing beside it and nothing from the network: its images are embedded as
base64 ``data:`` URIs, its style is inline, and it has no script and no math to typeset. It fits
a 1280 px window: a wide table scrolls inside its own box, images shrink to the text width.
Every number of a table goes through :func:`fmt` (significant digits, no ``1.094e+04``).
"""

from __future__ import annotations

import base64
import html
import math
import mimetypes
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd


@dataclass(frozen=True)
class Heading:
    text: str
    level: int = 2


@dataclass(frozen=True)
class Para:
    text: str


@dataclass(frozen=True)
class Bullets:
    items: tuple[str, ...]


@dataclass(frozen=True)
class Code:
    text: str


@dataclass(frozen=True)
class Table:
    df: pd.DataFrame
    caption: str = ""
    digits: int = 4


@dataclass(frozen=True)
class Figure:
    path: str  # relative to the report
    caption: str


Block = Heading | Para | Bullets | Code | Table | Figure


_SUPERSCRIPT = str.maketrans(
    "-0123456789", "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079"
)


def fmt_number(x: float, digits: int = 4) -> str:
    """``x`` with ``digits`` significant digits: positional from 0.001 to below 1e6 (``10940``,
    ``0.1225``, trailing zeros dropped), otherwise as mantissa, the sign U+00D7 and a power of
    ten in superscript digits (``1.094`` U+00D7 ``10⁻⁵``); never Python's ``e+04``."""
    if not math.isfinite(x):
        return "-" if math.isnan(x) else ("inf" if x > 0 else "-inf")
    if x == 0:
        return "0"
    digits = max(int(digits), 1)
    mantissa, exp_text = f"{x:.{digits - 1}e}".split("e")
    exp = int(exp_text)  # the exponent after rounding to ``digits`` (9.99996 -> 1.000e+01)
    positional = -3 <= exp < 6
    decimals = digits - 1 - exp
    text = f"{round(x, decimals):.{max(decimals, 0)}f}" if positional else mantissa
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return text if positional else f"{text}\u00d710{str(exp).translate(_SUPERSCRIPT)}"


def fmt(x: Any, digits: int = 4) -> str:
    """Format one table cell: numbers with ``digits`` significant digits (:func:`fmt_number`),
    NaN/None as a dash, booleans as yes/no, anything else as ``str``."""
    if x is None:
        return "-"
    if isinstance(x, bool):
        return "yes" if x else "no"
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        return fmt_number(x, digits)
    return str(x)


def fmt_pct(x: Any) -> str:
    """A relative difference as a signed percentage (a dash for None/NaN)."""
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:+.1%}"


def _md_inline(text: str) -> str:
    return text.replace("|", "\\|")


def to_markdown(blocks: Sequence[Block], title: str) -> str:
    out = [f"# {title}", ""]
    for b in blocks:
        if isinstance(b, Heading):
            out += ["#" * b.level + " " + b.text, ""]
        elif isinstance(b, Para):
            out += [b.text, ""]
        elif isinstance(b, Bullets):
            out += [f"- {item}" for item in b.items] + [""]
        elif isinstance(b, Code):
            out += ["```", b.text.rstrip("\n"), "```", ""]
        elif isinstance(b, Figure):
            out += [f"![{b.caption}]({b.path})", "", f"*{b.caption}*", ""]
        elif isinstance(b, Table):
            if b.caption:
                out += [f"**{b.caption}**", ""]
            cols = [str(c) for c in b.df.columns]
            out.append("| " + " | ".join(_md_inline(c) for c in cols) + " |")
            out.append("|" + "|".join("---" for _ in cols) + "|")
            for _, row in b.df.iterrows():
                out.append("| " + " | ".join(_md_inline(fmt(v, b.digits)) for v in row) + " |")
            out.append("")
    return "\n".join(out)


_CSS = """
body { font-family: system-ui, sans-serif; max-width: 75em; margin: 2em auto; padding: 0 1em;
       line-height: 1.45; color: #222; }
p, li, figcaption, caption { overflow-wrap: anywhere; }
.table-wrap { max-width: 100%; overflow-x: auto; margin: 0.5em 0 1.5em; }
table { border-collapse: collapse; font-size: 0.9em; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.5em; text-align: right; }
th { background: #eee; } td:first-child, th:first-child { text-align: left; }
td.text { text-align: left; } td.long { min-width: 12em; }
caption { caption-side: top; font-weight: bold; text-align: left; padding-bottom: 0.3em; }
figure { margin: 1em 0; } img { max-width: 100%; height: auto; } figcaption { font-style: italic; }
code, pre { background: #f4f4f4; } pre { padding: 0.6em; overflow-x: auto; max-width: 100%; }
"""


_DOI = re.compile(r"\bdoi:(10\.\d{4,9}/[^\s<>\"]*[^\s<>\".,;:)])")


def _html_inline(text: str) -> str:
    """Escaped text; `backticks` as code, ``doi:10...`` as a link to https://doi.org/."""
    esc = re.sub(r"`([^`]+)`", r"<code>\1</code>", html.escape(text))
    return _DOI.sub(r'<a href="https://doi.org/\1">doi:\1</a>', esc)


def data_uri(path: Path) -> str:
    """The file at ``path`` as a base64 ``data:`` URI (its type from the file name)."""
    kind = mimetypes.guess_type(path.name)[0] or "application/octet-stream"
    return f"data:{kind};base64," + base64.b64encode(path.read_bytes()).decode("ascii")


def _html_table(b: Table) -> str:
    rows = ['<div class="table-wrap"><table>']
    if b.caption:
        rows.append(f"<caption>{_html_inline(b.caption)}</caption>")
    rows.append("<tr>" + "".join(f"<th>{html.escape(str(c))}</th>" for c in b.df.columns) + "</tr>")
    for _, row in b.df.iterrows():
        cells = []
        for v in row:
            text = fmt(v, b.digits)
            cls = (
                ""
                if not isinstance(v, str)
                else ' class="text long"'
                if len(v) > 40
                else ' class="text"'
            )
            cells.append(f"<td{cls}>{_html_inline(text)}</td>")
        rows.append("<tr>" + "".join(cells) + "</tr>")
    rows.append("</table></div>")
    return "\n".join(rows)


def _html_block(b: Block, base: Path | None) -> str:
    if isinstance(b, Heading):
        return f"<h{b.level}>{_html_inline(b.text)}</h{b.level}>"
    if isinstance(b, Para):
        return f"<p>{_html_inline(b.text)}</p>"
    if isinstance(b, Bullets):
        return "<ul>" + "".join(f"<li>{_html_inline(i)}</li>" for i in b.items) + "</ul>"
    if isinstance(b, Code):
        return f"<pre>{html.escape(b.text)}</pre>"
    if isinstance(b, Figure):
        src = data_uri(base / b.path) if base is not None else b.path
        return (
            f'<figure><img src="{html.escape(src)}" alt="{html.escape(b.caption)}">'
            f"<figcaption>{_html_inline(b.caption)}</figcaption></figure>"
        )
    return _html_table(b)


def to_html(blocks: Sequence[Block], title: str, base: Path | None = None) -> str:
    """The page. With ``base`` (the folder the figure paths are relative to) every image is
    embedded as a ``data:`` URI, so the page is one self-contained file; without it, the images
    are linked by their relative paths."""
    out = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{html.escape(title)}</title><style>{_CSS}</style></head><body>",
        f"<h1>{html.escape(title)}</h1>",
    ]
    out += [_html_block(b, base) for b in blocks]
    out.append("</body></html>")
    return "\n".join(out)
