"""The reproduction's current "Can physics explain the experiment?" table (no simulation)
and readers of the section's sentences, shared by the wording tests."""

from __future__ import annotations

import pandas as pd

from impactlab.paper.physics import (
    CONFIGURATIONS,
    CONTACT_TIME_COLUMN,
    E_COLUMN,
    FE_TABULATED,
    MEASURED,
    MU_COLUMN,
    RATE_LOWER,
    SCAR_COLUMN,
    SEQUENCE_COLUMN,
    T_COLUMN,
)
from impactlab.paper.physics_report import physics_section
from impactlab.paper.report import Bullets, Para

RIGID, FLEX, RATE = (c.name for c in CONFIGURATIONS)
LOWER = RATE_LOWER.name
SEQ, TOUCH = SEQUENCE_COLUMN, CONTACT_TIME_COLUMN
COLUMNS: tuple[str, ...] = (E_COLUMN, "delta_p [um]", SCAR_COLUMN, T_COLUMN, SEQ, TOUCH)
COLUMNS += ("contacts", "F_max [N]", "rate factor")
#: The comparison of ``impactlab reproduce`` (physics_comparison.csv), 20 / 45 / 70 deg: T is
#: Eq. 12's of each row's own dent and scar; the sequence's duration and time in contact.
CURRENT: dict[str, list[tuple[float | None, ...]]] = {
    MEASURED: [
        (0.5, 22.0, 1400.0, 4.105951, None, None, None, None, None),
        (0.49, 26.0, 1650.0, 1.382249, None, None, None, None, None),
        (0.05, 105.0, 200.0, 0.146252, None, None, None, None, None),
    ],
    RIGID: [
        (0.4225, 62.0513, 22.0421, 0.1084, 0.1225, 0.1225, 1, 3808.7413, 1.0),
        (0.4184, 111.0656, 100.9776, 0.1348, 0.1424, 0.1424, 1, 7485.933, 1.0),
        (0.4141, 225.5506, 191.2036, 0.1761, 0.184, 0.184, 1, 16592.9274, 1.0),
    ],
    FLEX: [
        (0.7239, 32.4689, 261.3463, 0.7866, 0.9502, 0.6255, 4, 1756.2533, 1.0),
        (0.6019, 57.3413, 1005.7513, 0.8616, 0.976, 0.601, 4, 3470.2401, 1.0),
        (0.3828, 163.5588, 1216.9708, 0.7521, 0.8988, 0.3347, 2, 11611.264, 1.0),
    ],
    RATE: [
        (0.7392, 22.8919, 263.7124, 0.7867, 0.9514, 0.6237, 4, 2043.3803, 2.6445),
        (0.6656, 40.385, 1006.0967, 0.8541, 0.9645, 0.5801, 5, 3933.3125, 2.6728),
        (0.324, 110.3338, 1052.1065, 0.6412, 0.972, 0.3132, 2, 13240.8815, 2.6385),
    ],
    LOWER: [
        (0.7248, 31.5072, 261.2564, 0.7857, 0.9489, 0.6215, 4, 1812.877, 1.1316),
        (0.6144, 54.8247, 1005.4433, 0.8602, 0.974, 0.6031, 4, 3547.6414, 1.1329),
        (0.3628, 155.0676, 1211.3063, 0.7464, 0.9053, 0.3307, 2, 11844.031, 1.1293),
    ],
    FE_TABULATED.name: [
        (0.7104, 23.6453, 266.6179, 0.7957, 0.9608, 0.6535, 3, 1644.2295, 1.0),
        (0.6092, 47.4906, 957.2325, 0.8168, 0.8667, 0.5798, 3, 3394.9155, 1.0),
        (0.3705, 156.6739, 1221.4723, 0.7528, 0.8955, 0.319, 3, 11906.89, 1.0),
    ],
}


#: Eq. 28's mu of each row, 20 / 45 / 70 deg (the measured row: the measured mu).
MU: dict[str, tuple[float, float, float]] = {
    MEASURED: (0.2, 0.13, 0.1),
    RIGID: (0.2, 0.13, 0.1),
    FLEX: (0.1671, 0.1253, 0.0793),
    RATE: (0.1659, 0.1184, 0.0923),
    LOWER: (0.1663, 0.1241, 0.079),
    FE_TABULATED.name: (0.1665, 0.1271, 0.0773),
}


def table_of(changes: dict[tuple[str, int, str], float] | None = None) -> pd.DataFrame:
    """The comparison table of :data:`CURRENT`, with ``changes`` (configuration, angle, column:
    value) applied."""
    rows = [
        {"configuration": c, "angle [deg]": a, **dict(zip(COLUMNS, r, strict=True)), "flags": ""}
        | {MU_COLUMN: MU[c][i]}
        for i, a in enumerate((20, 45, 70))
        for c, values in CURRENT.items()
        for r in [values[i]]
    ]
    table = pd.DataFrame(rows)
    for (config, angle, column), value in (changes or {}).items():
        at = (table["configuration"] == config) & (table["angle [deg]"] == angle)
        table.loc[at, column] = value
    table["contacts"] = table["contacts"].astype("Int64")
    return table


def section_text(table: pd.DataFrame) -> tuple[str, list[str], list[str], str]:
    """The section's (intro of the findings, explained bullets, unexplained bullets, closing)."""
    blocks = physics_section(table, {}, 11)
    i = next(k for k, b in enumerate(blocks) if isinstance(b, Para) and b.text.startswith("What"))
    intro = blocks[i]
    assert isinstance(intro, Para)
    explained = list(getattr(blocks[i + 1], "items", ()))
    assert bool(explained) != intro.text.endswith(": nothing at any angle.")
    rest = blocks[i + 1 + bool(explained) :]
    missed: list[str] = []
    if isinstance(rest[0], Para) and rest[0].text == "What they do not explain:":
        missed = list(rest[1].items)  # type: ignore[union-attr]
    closing = [b for b in blocks if isinstance(b, Para)][-1].text
    bullets = 1 + bool(explained) + bool(missed)  # the configurations' list too
    assert sum(isinstance(b, Bullets) for b in blocks) == bullets
    return intro.text, explained, missed, closing


def bullet(items: list[str], start: str) -> str:
    found = [b for b in items if b.startswith(start)]
    assert len(found) == 1, (start, items)
    return found[0]
