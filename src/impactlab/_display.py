"""HTML tables for results in Jupyter (``_repr_html_``)."""

from __future__ import annotations

import html
from collections.abc import Iterable


def html_table(title: str, rows: Iterable[tuple[str, str, str]]) -> str:
    """A three-column (quantity, value, unit) HTML table."""
    body = "".join(
        f"<tr><td>{html.escape(a)}</td><td style='text-align:right'>{html.escape(b)}</td>"
        f"<td>{html.escape(c)}</td></tr>"
        for a, b, c in rows
    )
    return (
        f"<table><thead><tr><th>{html.escape(title)}</th><th>value</th><th>unit</th></tr>"
        f"</thead><tbody>{body}</tbody></table>"
    )
