"""``impactlab drop --config FILE``: the drop's option keys from a TOML file, at the top level or
in a ``[drop]`` table, under the command line's options; errors name a value read from the
file as ``key (in FILE)``, as ``impactlab simulate --config`` does (``cli.config_file``)."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]

#: A short drop: the rigid rod (no modes), the paper's 20 deg case.
CASE = 'angle = "20 deg"\nvy = "-1.41 m/s"\nmu = 0.2\nrigid = true\n'


def _input(cli_main: CliMain, *args: str) -> dict:
    code, out, err = cli_main("drop", *args, "--json")
    assert code == 0, err
    return json.loads(out)["input"]


def _error(cli_main: CliMain, *args: str) -> str:
    code, out, err = cli_main("drop", *args)
    assert code == 2 and out == "", err
    assert len(err.strip().splitlines()) == 1 and err.startswith("error: "), err
    return err.strip()


def test_the_files_values_are_used_and_the_command_line_wins(
    tmp_path: Path, cli_main: CliMain
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(CASE + 'tip_radius = "5 mm"\nmass = "0.1 kg"\nflat = "al-6061-t6"\n')
    given = _input(cli_main, "--config", str(cfg))
    assert given["body"]["type"] == "Rod"  # rigid = true
    assert given["body"]["tip_radius"]["value"] == 0.005  # tip_radius: the option's radius
    assert given["angle"]["value"] == pytest.approx(math.radians(20), rel=1e-15)
    assert given["velocity"]["value"] == [0.0, -1.41] and given["mu"]["value"] == 0.2
    assert given["flat"]["name"].startswith("aluminium 6061-T6")
    over = _input(
        cli_main, "--config", str(cfg), "--mu", "0.1", "--vy", "-2 m/s", "--radius", "6 mm"
    )
    assert over["mu"]["value"] == 0.1 and over["velocity"]["value"] == [0.0, -2.0]
    assert over["body"]["tip_radius"]["value"] == 0.006
    assert over["angle"] == given["angle"] and over["flat"] == given["flat"]  # kept from the file
    record = tmp_path / "drop.json"
    record.write_text(json.dumps({"input": given}))
    err = _error(cli_main, "--from", str(record), "--config", str(cfg))
    assert "--config and --from" in err and "leave out --config" in err


def test_a_drop_table_beside_a_simulate_table(tmp_path: Path, cli_main: CliMain) -> None:
    """One file for both commands: each reads its own table."""
    cfg = tmp_path / "both.toml"
    cfg.write_text(f'[drop]\n{CASE}\n[simulate]\nangle = "30 deg"\nvy = "-1 m/s"\n')
    assert _input(cli_main, "--config", str(cfg))["angle"]["value"] == pytest.approx(
        math.radians(20), rel=1e-15
    )
    code, out, err = cli_main("simulate", "--config", str(cfg), "--json")
    assert code == 0, err
    assert json.loads(out)["input"]["angle"]["value"] == pytest.approx(math.radians(30), rel=1e-15)


@pytest.mark.parametrize(
    ("text", "said"),
    [
        # simulate's table alone: its keys describe simulate's body, never the drop's
        (
            '[simulate]\nangle = "20 deg"\nvy = "-1 m/s"\n',
            "[simulate] in {cfg} is impactlab simulate's table; give impactlab drop's keys in a "
            "[drop] table (a file may hold both) or at the top level",
        ),
        (
            'mu = 0.2\n[drop]\nangle = "20 deg"\nvy = "-1 m/s"\n',
            "mu in {cfg}: beside a [drop] table the top level is not read; move it into [drop]",
        ),
        ("drop = 3\n", "drop in {cfg} must be a table, [drop], got 3"),
        ("angle = \n", "--config '{cfg}' is not valid TOML: Invalid value (at line 1, column 9)"),
    ],
)
def test_the_files_form_is_checked(tmp_path: Path, cli_main: CliMain, text: str, said: str) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(text)
    assert said.format(cfg=cfg) in _error(cli_main, "--config", str(cfg))


def test_an_unknown_key_gets_the_nearest_or_why(tmp_path: Path, cli_main: CliMain) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(CASE + "muu = 0.2\nflexible = true\n")
    err = _error(cli_main, "--config", str(cfg))
    said = (
        "unknown key(s) in the config file: flexible (impactlab simulate's: the drop's rod is "
        "flexible unless rigid = true), muu (did you mean 'mu'?); known: angle, "
    )
    assert said in err
    cfg.write_text(CASE + 'flat_E = "69 GPa"\n')
    err = _error(cli_main, "--config", str(cfg))
    assert "flat_E in the config file: give a material whole" in err


@pytest.mark.parametrize(
    ("line", "said"),
    [
        ('mass = "0 kg"', "mass (in {cfg}) must be > 0, got '0 kg'"),
        ("angle = 20", "angle (in {cfg}) 20 has no unit"),
        ('rigid = "true"', "rigid in {cfg} must be true or false (a TOML boolean"),
        (
            "modes_axial = 4",
            "modes_axial (in {cfg}): a rigid rod has no modes; leave out rigid (in {cfg})",
        ),
        ("law = 3", "law (in {cfg}) must be text, a name in quotes, got 3"),
        ('mu = "x"', "mu (in {cfg}) must be a number, got 'x'"),
        ("mu = -1.0", "mu (in {cfg}) must be >= 0"),  # the engine's words, the key's name
        ('time_limit = "1 us"', "raise time_limit (in {cfg})"),  # a drop's error: the key's name
        (
            'rate = "cowper-symonds"\nflat = "al-6061-t6"',
            "rate (in {cfg}) cowper-symonds: its constants are fitted for",
        ),
    ],
)
def test_a_bad_value_names_the_key_and_the_file(
    tmp_path: Path, cli_main: CliMain, line: str, said: str
) -> None:
    cfg = tmp_path / "case.toml"
    keys = {x.split(" = ")[0] for x in line.splitlines()}  # in place of the case's
    lines = [x for x in CASE.splitlines() if x.split(" = ")[0] not in keys]
    cfg.write_text("\n".join([*lines, line]) + "\n")
    assert said.format(cfg=cfg) in _error(cli_main, "--config", str(cfg))


def test_a_flexible_rods_option_in_the_file_is_its_key(tmp_path: Path, cli_main: CliMain) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text('angle = "20 deg"\nvy = "-1.41 m/s"\ninertia = "0.004 kg*m^2"\n')
    err = _error(cli_main, "--config", str(cfg))
    assert err.startswith(f"error: inertia (in {cfg}): the flexible rod's inertia follows")


def test_the_help_says_the_tables(cli_main: CliMain) -> None:
    code, out, _ = cli_main("drop", "--help")
    flat = " ".join(out.replace("│", " ").split())
    assert code == 0 and "in a [drop] table; options given here win" in flat
    assert "a [simulate] table alone is refused" in flat


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("simulate = 3\n", "simulate in {cfg} must be a table, [simulate], got 3"),
        (
            'mu = 0.2\n[simulate]\nangle = "20 deg"\n',
            "mu in {cfg}: beside a [simulate] table the top level is not read; move it into "
            "[simulate]",
        ),
        (
            '[drop]\nangle = "20 deg"\n',
            "[drop] in {cfg} is impactlab drop's table; give impactlab simulate's keys in a "
            "[simulate] table (a file may hold both) or at the top level",
        ),
    ],
    ids=["not-a-table", "keys-beside", "drop-table-alone"],
)
def test_simulate_reads_its_table_by_the_same_rule(
    tmp_path: Path, cli_main: CliMain, text: str, said: str
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(text)
    code, out, err = cli_main("simulate", "--config", str(cfg), "--vy", "-1 m/s")
    assert (code, out) == (2, "")
    assert err == f"error: {said.format(cfg=cfg)}\n"


#: The velocity in each form, a file's lines.
BY_VY = 'vx = "0.1 m/s"\nvy = "-1.5 m/s"\n'
BY_SPEED = 'speed = "2 m/s"\nincidence = "30 deg"\n'


@pytest.mark.parametrize("command", ["drop", "simulate"])
@pytest.mark.parametrize(
    ("in_file", "options", "velocity"),
    [
        (BY_SPEED, ("--vy", "-2 m/s"), (0.0, -2.0)),  # the other form: the file's is not read
        (BY_VY, ("--speed", "2 m/s", "--incidence", "30 deg"), (1.0, -math.sqrt(3))),
        (BY_VY, ("--vy", "-2 m/s"), (0.1, -2.0)),  # the same form: the given key wins
        (BY_VY + BY_SPEED, ("--vx", "0.2 m/s"), (0.2, -1.5)),  # both in the file: one given
    ],
    ids=["vy-over-speed", "speed-over-vy", "vy-over-vy", "vx-over-both"],
)
def test_a_velocity_on_the_command_line_replaces_the_files(
    tmp_path: Path,
    cli_main: CliMain,
    command: str,
    in_file: str,
    options: tuple[str, ...],
    velocity: tuple[float, float],
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(f'angle = "20 deg"\n{in_file}' + ("rigid = true\n" if command == "drop" else ""))
    code, out, err = cli_main(command, "--config", str(cfg), *options, "--json")
    assert code == 0, err
    assert json.loads(out)["input"]["velocity"]["value"] == pytest.approx(velocity, rel=1e-12)


@pytest.mark.parametrize("command", ["drop", "simulate"])
def test_two_velocities_in_one_place_are_refused_naming_each(
    tmp_path: Path, cli_main: CliMain, command: str
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(f'angle = "20 deg"\nvy = "-1.5 m/s"\n{BY_SPEED}')
    code, out, err = cli_main(command, "--config", str(cfg))
    assert (code, out) == (2, "")
    assert err.startswith(
        f"error: vy (in {cfg}) and speed (in {cfg})/incidence (in {cfg}) both given: they say "
        "the same thing; give one pair"
    ), err
    code, out, err = cli_main(
        command, "--angle", "20 deg", "--vy", "-1 m/s", "--speed", "2 m/s", "--incidence", "5 deg"
    )
    assert (code, out) == (2, "")
    assert err.startswith("error: --vy and --speed/--incidence both given"), err
    cfg.write_text('angle = "20 deg"\nspeed = "2 m/s"\n')
    code, out, err = cli_main(command, "--config", str(cfg))
    assert (code, out) == (2, "")
    assert f"go together: incidence (in {cfg}) is missing" in err


@pytest.mark.parametrize("command", ["drop", "simulate"])
def test_a_material_file_in_the_config_is_beside_it(
    tmp_path: Path, cli_main: CliMain, monkeypatch: pytest.MonkeyPatch, command: str
) -> None:
    """Relative to the config file's folder; on the command line, to the current folder."""
    sub = tmp_path / "sub"
    sub.mkdir()
    (sub / "mat.toml").write_text('E = "69 GPa"\nnu = 0.33\nSy = "276 MPa"\nrho = "2700 kg/m^3"\n')
    rigid = "rigid = true\n" if command == "drop" else ""
    (sub / "c.toml").write_text(f'angle = "20 deg"\nvy = "-1.41 m/s"\n{rigid}flat = "mat.toml"\n')
    monkeypatch.chdir(tmp_path)
    code, out, err = cli_main(command, "--config", "sub/c.toml", "--json")
    assert code == 0, err
    assert json.loads(out)["input"]["flat"]["E"]["value"] == 69e9
    code, out, err = cli_main(command, "--config", "sub/c.toml", "--flat", "mat.toml")
    assert (code, out) == (2, "")
    assert err == "error: --flat: material file 'mat.toml' does not exist\n"
    (sub / "c.toml").write_text(f'angle = "20 deg"\nvy = "-1.41 m/s"\n{rigid}flat = "no.toml"\n')
    code, out, err = cli_main(command, "--config", "sub/c.toml")
    assert err == "error: flat (in sub/c.toml): material file 'sub/no.toml' does not exist\n"


def test_simulate_says_why_a_drop_key_is_none_of_its(tmp_path: Path, cli_main: CliMain) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text('angle = "20 deg"\nvy = "-1.41 m/s"\nrigid = true\n')
    code, out, err = cli_main("simulate", "--config", str(cfg))
    assert (code, out) == (2, "")
    assert err.startswith(
        "error: unknown key(s) in the config file: rigid (impactlab drop's: simulate's rod is "
        "rigid unless flexible = true); known: "
    ), err


@pytest.mark.parametrize("command", ["drop", "simulate"])
@pytest.mark.parametrize("key", ["friction", "law", "stop", "rate"])
def test_a_name_that_is_no_text_is_refused_alike(
    tmp_path: Path, cli_main: CliMain, command: str, key: str
) -> None:
    cfg = tmp_path / "case.toml"
    flexible = "flexible = true\n" if command == "simulate" and key in ("stop", "rate") else ""
    cfg.write_text(f'angle = "20 deg"\nvy = "-1.41 m/s"\n{flexible}{key} = true\n')
    code, out, err = cli_main(command, "--config", str(cfg))
    assert (code, out) == (2, "")
    assert err == f"error: {key} (in {cfg}) must be text, a name in quotes, got True\n"


@pytest.mark.parametrize("command", ["drop", "simulate"])
def test_numeric_text_in_the_file_is_a_number(
    tmp_path: Path, cli_main: CliMain, command: str
) -> None:
    """Every quantity-free number (mu, damping, rtol, a mode count) reads numeric text."""
    cfg = tmp_path / "case.toml"
    flexible = "flexible = true\n" if command == "simulate" else ""
    cfg.write_text(
        f'angle = "20 deg"\nvy = "-1.41 m/s"\n{flexible}mu = "0.2"\ndamping = "0.1"\n'
        'rtol = "1e-6"\nmodes_axial = "2"\nmodes_bending = "3"\n'
    )
    code, out, err = cli_main(command, "--config", str(cfg), "--json")
    assert code == 0, err
    given = json.loads(out)["input"]
    assert given["mu"]["value"] == 0.2 and given["rtol"]["value"] == 1e-6
    body = given["body"]
    assert body["damping"]["value"] == 0.1
    assert (body["n_axial"], body["n_bending"]) == (2, 3)


@pytest.mark.parametrize("command", ["drop", "simulate"])
@pytest.mark.parametrize(
    ("line", "said"),
    [
        ('rtol = "tight"', "rtol (in {cfg}) must be a number, got 'tight'"),
        (
            "rtol = 1.0",
            "rtol (in {cfg}) must lie in [1e-13, 1e-05] for a drop (the drop's default is 1e-07), "
            "got 1.0",
        ),
        ('damping = "x"', "damping (in {cfg}) must be a number in [0, 1), got 'x'"),
        ('modes_axial = "2.5"', "modes_axial (in {cfg}) must be an integer >= 0, got '2.5'"),
    ],
)
def test_a_bad_number_names_the_key(
    tmp_path: Path, cli_main: CliMain, command: str, line: str, said: str
) -> None:
    cfg = tmp_path / "case.toml"
    flexible = "flexible = true\n" if command == "simulate" else ""
    cfg.write_text(f'angle = "20 deg"\nvy = "-1.41 m/s"\n{flexible}{line}\n')
    code, out, err = cli_main(command, "--config", str(cfg))
    assert (code, out) == (2, "")
    assert err == f"error: {said.format(cfg=cfg)}\n"


@pytest.mark.parametrize(
    ("line", "options", "said"),
    [
        (
            'inertia = "0.004 kg*m^2"',
            (),
            "give rigid = true (in {cfg}) for a rigid rod of another inertia",
        ),
        ("", ("--inertia", "0.004"), "give --rigid for a rigid rod of another inertia"),
        ('length = "200 mm"', (), "error: mass (in {cfg}) or diameter (in {cfg}): give one"),
        ('material = "brass-c360"', (), "error: mass (in {cfg}) or diameter (in {cfg}): give one"),
        ('material = "brass-c360"', ("--length", "0.2"), "error: --mass or --diameter: give one"),
    ],
    ids=["inertia-in-file", "inertia-given", "length-in-file", "material-in-file", "length-given"],
)
def test_a_missing_key_is_named_where_its_partner_was_given(
    tmp_path: Path, cli_main: CliMain, line: str, options: tuple[str, ...], said: str
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(f'angle = "20 deg"\nvy = "-1.41 m/s"\n{line}\n')
    assert said.format(cfg=cfg) in _error(cli_main, "--config", str(cfg), *options)
