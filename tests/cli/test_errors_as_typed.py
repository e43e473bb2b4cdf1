"""The command line's refusals name the option as the user typed it, not the API's keyword:
a velocity beyond its range (``--vx "2e4 m/s"``, or the ``--speed``/``--incidence`` that gave
it, rounded), a rod's mass and diameter that do not fit its material, ``sweep uncertainty``'s
``--percentile`` and ``--output``; ``materials NAME`` offers no definition by values, which it
does not show."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

ROD = ("simulate", "rod", "--angle", "20 deg")


@pytest.mark.parametrize(
    ("args", "head"),
    [
        ((*ROD, "--vy", "-1", "--vx", "2e4 m/s"), '--vx "2e4 m/s" exceeds 10000 m/s'),
        (("drop", "--angle", "20 deg", "--vy", "-2e4 m/s"), '--vy "-2e4 m/s" exceeds 10000 m/s'),
        (
            (*ROD, "--speed", "2e4 m/s", "--incidence", "10 deg"),
            '--speed "2e4 m/s", --incidence "10 deg" give vy = -1.97e+04 m/s, which exceeds',
        ),
        (
            (*ROD, "--vy", "-1", "--mass", "0.1 kg", "--diameter", "12 mm"),
            '--mass "0.1 kg", --diameter "12 mm" and length 304.8 mm imply a density',
        ),
        (
            ("drop", "--angle", "20 deg", "--vy", "-1", "--mass", "0.1 kg", "--diameter", "12 mm",
             "--length", "200 mm"),
            '--mass "0.1 kg", --diameter "12 mm" and --length "200 mm" imply a density',
        ),
    ],
)  # fmt: skip
def test_simulate_and_drop_name_the_options_as_typed(
    cli_main: Any, args: tuple[str, ...], head: str
) -> None:
    code, _, err = cli_main(*args)
    assert code == 2 and err.startswith(f"error: {head}"), err
    assert "velocity[" not in err and "(0.012 m)" not in err


def test_a_config_file_s_keys_are_named_as_its_own(cli_main: Any, tmp_path: Path) -> None:
    cfg = tmp_path / "c.toml"
    cfg.write_text('angle = "20 deg"\nvy = "-1 m/s"\nmass = "0.1 kg"\ndiameter = "12 mm"\n')
    code, _, err = cli_main("drop", "--config", str(cfg))
    assert code == 2
    assert err.startswith(f'error: mass (in {cfg}) "0.1 kg", diameter (in {cfg}) "12 mm" and '
                          "length 304.8 mm imply"), err  # fmt: skip


def test_sweep_uncertainty_names_percentile_and_output(cli_main: Any, tmp_path: Path) -> None:
    store = tmp_path / "none.zarr"
    store.mkdir()
    code, _, err = cli_main("sweep", "uncertainty", str(store), "--percentile", "150")
    assert (code, err) == (2, "error: --percentile 150: a percentile lies in [0, 100]\n")
    from impactlab.cli.sweep import _output_worded

    assert _output_worded("output(s) ['foo'] not in the sweep; it has: e, T") == (
        "--output 'foo': not in the sweep; it has: e, T"
    )
    assert _output_worded("output 'flags' holds bitmasks").startswith("--output 'flags' holds")


def test_materials_name_offers_no_properties(cli_main: Any) -> None:
    code, _, err = cli_main("materials", "foo")
    assert code == 2 and err.startswith("error: NAME: unknown material 'foo'")
    assert "give its properties" not in err and err.rstrip().endswith("(see 'impactlab materials')")


def test_sweep_export_to_a_folder_names_the_target(cli_main: Any, tmp_path: Path) -> None:
    store = tmp_path / "s.zarr"
    store.mkdir()
    code, _, err = cli_main("sweep", "export", str(store), str(tmp_path))
    assert (code, err) == (
        2,
        f"error: target {str(tmp_path)!r} is a folder: give the name of the file to write, "
        "ending in .csv (CSV), .nc or .nc4 (NetCDF-4)\n",
    )


@pytest.mark.parametrize("given", ["", "E=69GPa, nu=0.33", "steel.toml", "."])
def test_materials_name_refuses_values_and_files_as_no_library_name(
    cli_main: Any, given: str
) -> None:
    """It answered "expected a material name, 'key=value' properties or a TOML file", or asked
    for the missing properties, which the command then refuses."""
    code, _, err = cli_main("materials", given)
    assert code == 2
    start = f"error: NAME: {given!r} is not a library name (see 'impactlab materials')"
    assert err.startswith(start)
    assert "missing" not in err and "expected a material name" not in err
