"""A switch in a TOML input file is a TOML boolean: a quoted "false" is refused (Python would
read the non-empty string as true). Through the ``cli_main`` fixture."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]


@pytest.mark.parametrize(
    ("line", "key"),
    [('flexible = "false"', "flexible"), ('gravity = "no"', "gravity"),
     ('constant_angle = "no"', "constant_angle"), ("gravity = 0", "gravity")],
)  # fmt: skip
def test_simulate_refuses_a_switch_that_is_not_a_boolean(
    tmp_path: Path, cli_main: CliMain, line: str, key: str
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(f'angle = "30 deg"\nvy = "-2 m/s"\n{line}\n')
    code, _, err = cli_main("simulate", "rod", "--config", str(cfg))
    assert code == 2 and f"{key} in {cfg} must be true or false (a TOML boolean" in err


def test_invert_refuses_a_gravity_that_is_not_a_boolean(tmp_path: Path, cli_main: CliMain) -> None:
    cfg = tmp_path / "drop.toml"
    cfg.write_text(
        'angle = "20 deg"\nv_i = "-1.41 m/s"\ne = 0.5\nmu = 0.2\ndelta_p = "22 um"\n'
        'L_s = "1400 um"\ngravity = "false"\n'
    )
    code, _, err = cli_main("invert", "--file", str(cfg))
    assert code == 2 and "gravity in the measurement file must be true or false" in err
    cfg.write_text(cfg.read_text().replace('"false"', "false"))
    code, out, _ = cli_main("invert", "--file", str(cfg))
    assert code == 0 and "neglected" in out
