"""Details of the command line's messages: an error about a value of a --config file names the
key and the file once, a spin that is too fast names the contact point's reach of the body it
is about, and an analysis whose stage failed says so in its table's ok row."""

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


def test_an_analysis_whose_stage_failed_has_an_ok_row(tmp_path: Path, cli_main) -> None:
    data = Path(__file__).resolve().parents[2] / "examples" / "data"
    broken = tmp_path / "dent.x3p"
    broken.write_bytes(b"PK\x03\x04 truncated")
    code, out, err = cli_main("analyze", str(data / "drop.csv"), str(broken), "--up", "+y",
                              "--geometry", str(data / "markers.toml"))  # fmt: skip
    assert code == 2 and "error: scan: " in err
    assert "no: the scan stage failed (see the error)" in " ".join(out.split())


def test_a_drop_too_slow_to_integrate_names_the_option(cli_main) -> None:
    code, _, err = cli_main("drop", "--angle", "20 deg", "--vy", "-1e-12 m/s")
    assert code == 2
    assert err.startswith('error: --vy "-1e-12 m/s": the tip\'s normal approach speed')
