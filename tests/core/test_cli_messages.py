"""The command line answers angle errors in degrees, prints no numpy repr,
shows impactlab's warnings as one line and reports max_delta_ratio (``impactlab simulate rod``
through the command's ``main``, in this process: the ``cli_main`` fixture)."""

from __future__ import annotations

import json
from collections.abc import Callable

import pytest

CliMain = Callable[..., tuple[int, str, str]]


def _rod(cli_main: CliMain, *args: str) -> tuple[int, str, str]:
    return cli_main("simulate", "rod", *args)


@pytest.mark.parametrize("angle", ["95 deg", "-20 deg"])
def test_angle_error_is_in_degrees(cli_main: CliMain, angle: str) -> None:
    code, _, err = _rod(cli_main, "--angle", angle, "--vy", "-1.41 m/s")
    assert code == 2
    assert err.strip() == f"error: --angle must be in (0, 90] deg, got {angle}"


def test_receding_velocity_error_has_no_numpy_repr(cli_main: CliMain) -> None:
    code, _, err = _rod(cli_main, "--angle", "20 deg", "--vy", "1.41 m/s")
    assert code == 2 and "np.float64" not in err
    assert "= 1.41 m/s must be < 0" in err


def test_implausible_input_warning_is_one_line(cli_main: CliMain) -> None:
    _, _, err = _rod(cli_main, "--angle", "20 deg", "--vy", "-1e3 m/s")
    lines = err.strip().splitlines()
    assert lines[0].startswith("warning: the impact speed (1000 m/s) exceeds 100 m/s")
    assert "ImplausibleInputWarning" not in err and ".py:" not in err


def test_json_and_table_report_max_delta_ratio(cli_main: CliMain) -> None:
    code, out, err = _rod(cli_main, "--angle", "20 deg", "--vy", "-1.41 m/s", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["max_delta_ratio"]["unit"] == "1" and data["max_delta_ratio"]["value"] > 110.0
    assert data["extrapolated"] is True
    _, table, _ = _rod(cli_main, "--angle", "20 deg", "--vy", "-1.41 m/s")
    assert sum("max_delta_ratio" in line for line in table.splitlines()) == 1
