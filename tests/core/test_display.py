"""Results render as tables in Jupyter."""

from __future__ import annotations

import math

import impactlab as il
from impactlab._display import format_number


def test_inversion_renders_html_table() -> None:
    res = il.invert(
        angle=math.radians(20), v_i=-1.41, e=0.5, mu=0.2, delta_p=22e-6, sliding_length=1400e-6
    )
    page = res._repr_html_()
    assert page.startswith("<table>") and "InversionResult" in page
    cell = f"<td style='text-align:right'>{format_number(res.duration * 1e3)}</td>"
    assert f"<td>duration</td>{cell}<td>ms</td>" in page  # the display units of print()
