"""An error about a value of a --config file names the key and the file once, and a spin that
is too fast names the contact point's reach of the body it is about."""

from __future__ import annotations

from pathlib import Path


def test_a_config_value_is_named_once(tmp_path: Path, cli_main) -> None:
    config = tmp_path / "c.toml"
    config.write_text('angle = "20 deg"\nvy = -1.41\nradius = "1 kg"\n', encoding="utf-8")
    code, _, err = cli_main("simulate", "rod", "--config", str(config))
    assert code == 2
    where = f"(in {config})"
    assert err.strip().startswith(f"error: radius {where}: '1 kg' has the wrong dimension")
    assert err.count(where) == 1


def test_a_spin_too_fast_names_the_reach_of_either_body(cli_main) -> None:
    argv = ("simulate", "sphere", "--radius", "3 mm", "--vy", "-1", "--spin", "1e9 rad/s")
    code, _, err = cli_main(*argv)
    assert code == 2
    assert "(0.003 m from the centre of mass: L/2 + R for a rod, R for a sphere)" in err
