"""The command line answers angle errors in degrees, prints no numpy repr,
shows impactlab's warnings as one line and reports max_delta_ratio."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, MPLBACKEND="Agg")
    env.pop("IMPACTLAB_DEBUG", None)
    return subprocess.run(
        [sys.executable, "-m", "impactlab", "simulate", "rod", *args],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
    )


@pytest.mark.parametrize("angle", ["95 deg", "-20 deg"])
def test_angle_error_is_in_degrees(angle: str) -> None:
    p = _run("--angle", angle, "--vy", "-1.41 m/s")
    assert p.returncode == 2
    assert p.stderr.strip() == f"error: --angle must be in (0, 90] deg, got {angle}"


def test_receding_velocity_error_has_no_numpy_repr() -> None:
    p = _run("--angle", "20 deg", "--vy", "1.41 m/s")
    assert p.returncode == 2 and "np.float64" not in p.stderr
    assert "= 1.41 m/s must be < 0" in p.stderr


def test_implausible_input_warning_is_one_line() -> None:
    p = _run("--angle", "20 deg", "--vy", "-1e6 m/s")
    lines = p.stderr.strip().splitlines()
    assert lines[0].startswith("warning: the impact speed (1e+06 m/s) exceeds 100 m/s")
    assert "ImplausibleInputWarning" not in p.stderr and ".py:" not in p.stderr


def test_json_and_table_report_max_delta_ratio() -> None:
    p = _run("--angle", "20 deg", "--vy", "-1.41 m/s", "--json")
    assert p.returncode == 0, p.stderr
    data = json.loads(p.stdout)
    assert data["max_delta_ratio"]["unit"] == "1" and data["max_delta_ratio"]["value"] > 110.0
    assert data["extrapolated"] is True
    table = _run("--angle", "20 deg", "--vy", "-1.41 m/s")
    assert sum("max_delta_ratio" in line for line in table.stdout.splitlines()) == 1
