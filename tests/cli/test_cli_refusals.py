"""The command line refuses what it would otherwise do wrong or silently, in one line naming the
option: a rod other than the paper's without its mass, a sphere's --diameter, --flat beside
--flat-E/-nu/-sy, --law-file after the command, a Monte Carlo too large for the memory (and
any MemoryError), a mu at which the tip sticks; and its help and error texts say what the
command line takes."""

from __future__ import annotations

import pytest
import typer

from impactlab.cli import app

ROD = ("simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2")
MASS_RULE = "--mass or --diameter: give one (or both) for a rod other than the paper's"


@pytest.mark.parametrize("other", [("--material", "al-6061-t6"), ("--length", "100 mm")])
def test_simulate_refuses_another_rod_without_its_mass(cli_main, other) -> None:
    code, out, err = cli_main(*ROD, *other, "--json")
    assert code == 2 and out == ""
    assert err.startswith(f"error: {MASS_RULE}"), err
    code, _, err = cli_main(*ROD, *other, "--mass", "0.16 kg", "--json")
    assert code == 0, err


def test_simulate_takes_another_rods_mass_from_its_diameter(cli_main) -> None:
    import json

    code, out, err = cli_main(*ROD, "--material", "al-6061-t6", "--diameter", "15.875 mm", "--json")
    assert code == 0, err
    mass = json.loads(out)["input"]["body"]["mass"]
    assert 0.15 < float(mass["value"] if isinstance(mass, dict) else mass) < 0.17


def test_a_config_files_rod_is_named_by_its_keys(cli_main, tmp_path) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text('material = "al-6061-t6"\n')
    code, _, err = cli_main(*ROD, "--config", str(cfg))
    assert code == 2
    assert f"mass (in {cfg}) or diameter (in {cfg}): give one" in err, err


def test_a_spheres_size_is_its_radius(cli_main) -> None:
    code, _, err = cli_main("simulate", "sphere", "--vy", "-1 m/s", "--diameter", "10 mm")
    assert code == 2
    assert "--diameter is a rod's; a sphere's size is its radius, --radius" in err, err


def test_fe_indent_refuses_a_flat_named_and_given_by_values(cli_main) -> None:
    args = ("fe", "indent", "--max", "5 um", "--flat-E", "200 GPa", "--flat-nu", "0.3",
            "--flat-sy", "300 MPa")  # fmt: skip
    code, _, err = cli_main(*args, "--flat", "pmma")
    assert code == 2
    assert "--flat and --flat-E/-nu/-sy both given" in err, err


@pytest.mark.parametrize("option", ["--body", "--material"])
def test_fe_indent_refuses_a_sphere_named_and_given_by_values(cli_main, option) -> None:
    args = ("fe", "indent", "--max", "5 um", "--body-E", "200 GPa", "--body-nu", "0.3",
            "--body-sy", "300 MPa")  # fmt: skip
    code, _, err = cli_main(*args, option, "al-6061-t6")
    assert code == 2
    assert "--body/--material and --body-E/-nu/-sy both given" in err, err


def test_fe_indent_help_says_a_bare_modulus_is_in_pa() -> None:
    cmd = typer.main.get_command(app).commands["fe"].commands["indent"]  # type: ignore[attr-defined]
    helps = {p.name: p.help or "" for p in cmd.params}
    assert "a bare number: Pa" in helps["flat_E"] and "a bare number: Pa" in helps["flat_sy"]


def test_law_file_after_the_command_says_where_it_goes(cli_main) -> None:
    code, _, err = cli_main("simulate", "--law-file", "x.toml", "--law", "my", "rod")
    assert code == 2 and err.count("\n") == 1
    assert "--law-file goes before the command: impactlab --law-file FILE.toml simulate" in err


def test_invert_bounds_the_monte_carlo_samples(cli_main, tmp_path) -> None:
    args = ("invert", "--case", "paper-20", "--sigma-mu", "0.01")
    code, _, err = cli_main(*args, "--samples", "99999999999")
    assert code == 2 and err.count("\n") == 1
    assert "--samples must be at most 10,000,000" in err, err
    measured = tmp_path / "m.toml"
    measured.write_text('case = "paper-20"\nsamples = 20000000\n')
    code, _, err = cli_main("invert", "--file", str(measured))
    assert code == 2 and "samples in the measurement file must be at most" in err, err


def test_a_memory_error_is_one_line(cli_main, monkeypatch) -> None:
    import impactlab.cli.invert as invert_cli

    def exhausted(*_args, **_kwargs):
        raise MemoryError("Unable to allocate 745. GiB for an array")

    monkeypatch.setattr(invert_cli, "invert", exhausted)
    code, _, err = cli_main("invert", "--case", "paper-20")
    assert code == 2 and err.count("\n") == 1, err
    assert err.startswith("error: out of memory: Unable to allocate 745. GiB"), err


def test_invert_names_mu_when_the_tip_sticks(cli_main) -> None:
    args = ("invert", "--angle", "20 deg", "--vi", "-1.41", "--e", "0.5", "--delta-p", "22 um",
            "--ls", "1400 um")  # fmt: skip
    for mu in ("20", "4"):
        code, _, err = cli_main(*args, "--mu", mu)
        assert code == 2 and err.startswith("error: --mu lies far above the critical mu_c"), err
        assert "rod's impulse coefficients" not in err


def test_invert_words_the_sigma_of_e_for_the_command_line(cli_main) -> None:
    args = ("invert", "--angle", "20 deg", "--vi", "-1.41", "--e", "1.5", "--mu", "0.2",
            "--delta-p", "22 um", "--ls", "1400 um")  # fmt: skip
    code, _, err = cli_main(*args)
    assert code == 2 and "--sigma-e on the command line" in err, err


def test_calibrate_restart_help_reads() -> None:
    cmd = typer.main.get_command(app).commands["calibrate"]  # type: ignore[attr-defined]
    text = next(p.help for p in cmd.params if p.name == "restart")
    assert "a chain saved with other inputs stops a run" in (text or "")


@pytest.mark.parametrize(
    ("args", "named"),
    [
        (("simulate", "rod", "--config", ""), "'--config'"),
        (("simulate", "rod", "--out=", "--plot"), "'--out'"),
        (("sweep", "run", " "), "'STUDY'"),
        (("sweep", "export", "", "x.csv"), "'STORE'"),
        (("--law-file", "", "laws"), "'--law-file'"),
    ],
)
def test_an_empty_path_is_refused_by_name(cli_main, args, named) -> None:
    """It was read as the current folder: "--config '.' is a folder", a path never given."""
    code, out, err = cli_main(*args)
    assert code == 2 and out == "", err
    assert err.startswith(f"error: Invalid value for {named}: an empty path ("), err
    assert "'.'" not in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("command", [("simulate", "rod"), ("simulate", "rod", "--flexible"),
                                     ("drop", "--rigid")])  # fmt: skip
def test_another_tip_radius_asks_for_the_rods_mass(cli_main, command) -> None:
    """--radius "5 mm" kept the paper's 0.46 kg: a rod wider than its tip, run as plain success
    (rigid) or refused over a mass never given (flexible)."""
    code, out, err = cli_main(
        *command, "--angle", "20 deg", "--vy", "-1.41 m/s", "--radius", "5 mm"
    )
    assert code == 2 and out == "" and err.startswith(f"error: {MASS_RULE}"), err
    code, _, err = cli_main(*ROD, "--radius", "8.8 mm", "--json")  # the paper's own tip: runs
    assert code == 0, err
