"""A tiny document model rendered to Markdown and to a self-contained HTML page (no extra deps).

Blocks: ``Heading``, ``Para`` (plain text; `backticks` become code), ``Table`` (a DataFrame),
``Figure`` (an image path relative to the report), ``Code`` (preformatted text), ``Bullets``.
"""

from __future__ import annotations

import html
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
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


def fmt(x: Any, digits: int = 4) -> str:
    """Format one table cell: numbers with ``digits`` significant digits, NaN/None as a dash."""
    if x is None:
        return "-"
    if isinstance(x, bool):
        return "yes" if x else "no"
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        if math.isnan(x):
            return "-"
        if x == 0:
            return "0"
        return f"{x:.{digits}g}"
    return str(x)


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
table { border-collapse: collapse; margin: 0.5em 0 1.5em; font-size: 0.9em; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.5em; text-align: right; }
th { background: #eee; } td:first-child, th:first-child { text-align: left; }
caption { caption-side: top; font-weight: bold; text-align: left; padding-bottom: 0.3em; }
figure { margin: 1em 0; } img { max-width: 100%; } figcaption { font-style: italic; }
code, pre { background: #f4f4f4; } pre { padding: 0.6em; overflow-x: auto; }
"""


def _html_inline(text: str) -> str:
    esc = html.escape(text)
    return re.sub(r"`([^`]+)`", r"<code>\1</code>", esc)


def to_html(blocks: Sequence[Block], title: str) -> str:
    out = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{html.escape(title)}</title><style>{_CSS}</style></head><body>",
        f"<h1>{html.escape(title)}</h1>",
    ]
    for b in blocks:
        if isinstance(b, Heading):
            out.append(f"<h{b.level}>{_html_inline(b.text)}</h{b.level}>")
        elif isinstance(b, Para):
            out.append(f"<p>{_html_inline(b.text)}</p>")
        elif isinstance(b, Bullets):
            out.append("<ul>" + "".join(f"<li>{_html_inline(i)}</li>" for i in b.items) + "</ul>")
        elif isinstance(b, Code):
            out.append(f"<pre>{html.escape(b.text)}</pre>")
        elif isinstance(b, Figure):
            out.append(
                f'<figure><img src="{html.escape(b.path)}" alt="{html.escape(b.caption)}">'
                f"<figcaption>{_html_inline(b.caption)}</figcaption></figure>"
            )
        elif isinstance(b, Table):
            rows = ["<table>"]
            if b.caption:
                rows.append(f"<caption>{_html_inline(b.caption)}</caption>")
            rows.append(
                "<tr>" + "".join(f"<th>{html.escape(str(c))}</th>" for c in b.df.columns) + "</tr>"
            )
            for _, row in b.df.iterrows():
                rows.append(
                    "<tr>"
                    + "".join(f"<td>{html.escape(fmt(v, b.digits))}</td>" for v in row)
                    + "</tr>"
                )
            rows.append("</table>")
            out.append("\n".join(rows))
    out.append("</body></html>")
    return "\n".join(out)
