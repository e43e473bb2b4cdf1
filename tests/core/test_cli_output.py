"""One output layer: every command and ``print(result)`` show the same fields in the
same display units, with one number format; ``--json`` has the documented shape everywhere;
``--version``; CLI defaults equal the Python API's; help texts name units and defaults."""

from __future__ import annotations

import inspect
import json
import math

import pytest
import typer
from typer.testing import CliRunner

import impactlab as il
from impactlab._display import display_unit, format_number
from impactlab._json import shape_problems
from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod
from impactlab.cli import app
from impactlab.cli.analyze import analyze_cmd
from impactlab.cli.drop import drop_cmd
from impactlab.dynamics.drop import simulate_drop
from impactlab.experiment import analyze
from impactlab.friction import DEFAULT_MU
from impactlab.materials import AISI_201
from impactlab.schema import FIELDS

runner = CliRunner()
WIDE = {"COLUMNS": "200"}
ROD20 = ["simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2"]
INVERT = [
    "invert",
    *("--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2"),
    *("--delta-p", "22 um", "--ls", "1400 um", "--samples", "200"),
]


def _ok(args: list[str]) -> str:
    res = runner.invoke(app, args, env=WIDE)
    assert res.exit_code == 0, res.output
    return res.stdout


def _json(args: list[str]) -> dict:
    data = json.loads(_ok([*args, "--json"]))
    assert shape_problems(data) == [], shape_problems(data)[:5]
    return data


def _table(text: str) -> dict[str, tuple[str, str]]:
    """The rows of the rich tables in ``text``: name -> (value, unit)."""
    rows = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.split("│")[1:-1]]
        if len(cells) == 3 and cells[0]:
            rows[cells[0]] = (cells[1], cells[2])
    return rows


@pytest.mark.parametrize(
    ("x", "text"),
    [
        (10940.0, "10940"),
        (1.0940e4 + 0.4, "10940"),
        (62.0513, "62.051"),
        (0.12250, "0.1225"),
        (-3.0, "-3"),
        (99999.7, "100000"),
        (2e11, "2e11"),
        (6.2e-5, "6.2e-5"),
        (0.0, "0"),
        (7, "7"),
        (math.inf, "inf"),
    ],
)
def test_one_number_format(x: float, text: str) -> None:
    assert format_number(x) == text


def test_every_schema_field_has_a_display_unit() -> None:
    """The display table is derived from the schema's SI units: no field shows a raw SI unit
    where a display unit exists (lengths of the dent in um, times in ms, angles in deg)."""
    for name, f in FIELDS.items():
        d = display_unit(name, f.unit)
        assert d.unit and d.scale > 0, name
    assert display_unit("delta_p", "m").unit == "um"
    assert display_unit("duration", "s").unit == "ms"
    assert display_unit("angle", "rad").unit == "deg"


def test_print_and_simulate_show_the_same_rows() -> None:
    """``print(result)`` and ``impactlab simulate`` render the same fields, values and units
    (once: "delta_p 6.20513e-05 m" and "angle 0.349066 rad" in the CLI, "62.051 um" in print)."""
    r = il.simulate(PAPER_ROD, angle="20 deg", velocity=(0.0, -1.41), mu=0.2)
    rows = _table(_ok(ROD20))
    printed = [ln for ln in str(r).splitlines()[1:] if not ln.strip().startswith("warning")]
    assert len(printed) == len(rows) > 20
    for name, text, unit in r._rows():
        if name == "warning":  # the command writes the warnings to stderr
            continue
        assert rows[name] == (text, unit), name
        shown = [name, *text.split(), *(unit.split() if unit != "-" else [])]
        assert any(line.split() == shown for line in printed), name
    assert rows["delta_p"] == (format_number(r.delta_p * 1e6), "um")
    assert rows["angle"] == ("20", "deg") and rows["duration"][1] == "ms"


def test_tables_show_no_python_reprs() -> None:
    for args in (ROD20, ["materials"], ["laws", "brake"], INVERT):
        out = _ok(args)
        for raw in ("{'", "['", "e+0", "e-0", "nan", "± 0 "):
            assert raw not in out, (args, raw)


def test_invert_prints_no_zero_sigmas_and_labels_the_magnitudes() -> None:
    """Without uncertainties: no "± 0" columns nor Monte Carlo rows; v_i shows as the JSON's
    magnitude, labelled |v_i| (a bare "v_i 1.41" once read as a lost sign for --vi -1.41)."""
    rows = _table(_ok(INVERT))
    assert rows["|v_i|"] == ("1.41", "m/s") and rows["angle"] == ("20", "deg")
    assert rows["duration"] == ("4.106", "ms") and "T_mc" not in rows
    assert all("±" not in v for v, _u in rows.values())
    rows = _table(_ok([*INVERT, "--sigma-ls", "50 um"]))
    assert rows["|sliding_length|"] == ("1400 ± 50", "um")
    assert "±" in rows["duration"][0] and "±" in rows["T_mc"][0]
    r = il.invert(angle="20 deg", v_i=-1.41, e=0.5, mu=0.2, delta_p=22e-6, sliding_length=1.4e-3)
    assert "± 0" not in str(r) and "|v_i| = 1.41 m/s" in str(r)


def test_json_has_named_quantities_with_units() -> None:
    sim = _json(ROD20)
    assert sim["delta_p"]["unit"] == "m" and "sigma" not in sim["delta_p"]
    assert sim["velocity_out"]["unit"] == "m/s" and len(sim["velocity_out"]["value"]) == 2
    assert sim["law"] == "ghaednia" and isinstance(sim["flags"], int) and sim["n_steps"] > 0
    sphere = _json(["simulate", "sphere", "--vy", "-1 m/s"])
    assert "angle" not in sphere and "angle_out" not in sphere
    inv = _json([*INVERT, "--sigma-ls", "50 um"])
    assert inv["duration"]["unit"] == "s" and inv["duration"]["sigma"] > 0
    assert inv["inputs"]["v_i"] == {"value": 1.41, "unit": "m/s"}
    ls = {"value": 1.4e-3, "unit": "m", "sigma": pytest.approx(5e-5, rel=1e-12)}
    assert inv["inputs"]["sliding_length"] == ls
    assert inv["sensitivity_T"]["sliding_length"]["unit"] == "s/m"
    assert "sigma" not in _json(INVERT)["duration"]
    assert _json(["materials"])["aisi-201"]["E"] == {"value": 200e9, "unit": "Pa"}
    law = _json(["laws", "brake"])
    assert law["example"]["E_star"]["unit"] == "Pa"
    _json(["laws"])


def test_version() -> None:
    res = runner.invoke(app, ["--version"])
    assert res.exit_code == 0 and res.stdout.strip() == f"impactlab {il.__version__}"


def _defaults(cmd: object) -> dict[str, object]:
    """The typer option defaults of a command function, by parameter name."""
    out = {}
    for name, p in inspect.signature(cmd).parameters.items():  # type: ignore[arg-type]
        default = getattr(p.default, "default", p.default)
        if default is not None and default is not ...:
            out[name] = default
    return out


def test_cli_defaults_equal_the_python_defaults() -> None:
    """Every option that a command shares with its Python function has the same default."""
    pairs = ((drop_cmd, simulate_drop), (analyze_cmd, analyze))
    for cmd, func in pairs:
        py = {n: p.default for n, p in inspect.signature(func).parameters.items()}
        shared = {k: v for k, v in _defaults(cmd).items() if k in py}
        assert shared, cmd
        for name, value in shared.items():
            assert (None if value == "none" else value) == py[name], (cmd.__name__, name)
    sim = _json(["simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s"])
    py = inspect.signature(il.simulate).parameters
    assert sim["mu"]["value"] == py["mu"].default == DEFAULT_MU
    assert (sim["law"], sim["friction"]) == (py["law"].default, py["friction"].default)
    inv = _json(INVERT[:-2])
    assert inv["n_samples"] == inspect.signature(il.invert).parameters["n_samples"].default
    assert inv["gravity"] is inspect.signature(il.invert).parameters["gravity"].default


def test_simulate_chooses_the_materials() -> None:
    data = _json([*ROD20, "--material", "aisi-201", "--flat", "aisi-201"])
    rod = Rod(
        length=PAPER_ROD.length,
        tip_radius=PAPER_ROD.tip_radius,
        mass=PAPER_ROD.mass,
        material=AISI_201,
    )
    r = il.simulate(rod, AISI_201, angle="20 deg", velocity=(0.0, -1.41), mu=0.2)
    assert data["e"]["value"] == r.e
    assert data["e"]["value"] != _json(ROD20)["e"]["value"]
    res = runner.invoke(app, [*ROD20, "--flat", "unobtainium"])
    assert isinstance(res.exception, ValueError)  # main() prints it as one line, status 2
    assert "--flat: unknown material 'unobtainium'" in str(res.exception)


#: (command, words its help must contain: units of every quantity option, the defaults)
HELP = [
    (
        ["simulate"],
        [
            "deg",
            "rad",
            "m/s",
            "rad/s",
            "kg",
            "mm",
            "kg*m^2",
            f"default {DEFAULT_MU:g}",
            "default ghaednia",
            "aisi-201",
            "aisi-1010",
            "--flexible",
        ],
    ),
    (["drop"], ["deg", "m/s", "rad/s", "[0, 1)", "default ghaednia", "default none"]),
    (
        ["invert"],
        [
            "deg",
            "rad",
            "m/s",
            "um",
            "[sigma]",
            "[rod]",
            "kg",
            "default 20000",
            "default 0",
            "8.8 mm",
            "0.4607 kg",
            "0.3048 m",
        ],
    ),
    (["analyze"], ["[rod]", "'paper' (default)", "um", "+z", "default: no"]),
    (["laws"], ["8.8 mm", "aisi-201", "aisi-1010"]),
    (["materials"], ["GPa", "MPa", "kgf/mm^2"]),
    (["sweep", "run"], ["--max-cases", "default: all"]),
    ([], ["--version"]),
]


@pytest.mark.parametrize(("command", "words"), HELP)
def test_help_texts_name_units_and_defaults(command: list[str], words: list[str]) -> None:
    """Rich markup once swallowed "[rod]" and "[sigma]"; every quantity option names its unit
    and its default."""
    out = " ".join(_ok([*command, "--help"]).split())
    for word in words:
        assert word in out, (command, word)


FLEX = [*ROD20, "--flexible", "--modes-axial", "1", "--modes-bending", "2"]


def test_simulate_flexible_rod_is_the_drop() -> None:
    """``simulate rod --flexible`` runs ``impactlab.simulate(FlexibleRod(...))``
    (a DropResult) and prints through the same output layer."""
    data = _json(FLEX)
    body = FlexibleRod.paper(n_axial=1, n_bending=2)
    ref = il.simulate(body, angle="20 deg", velocity=(0.0, -1.41), mu=0.2, history=False)
    assert data["e"] == {"value": ref.e, "unit": "1"}
    assert data["n_contacts"] == ref.n_contacts and len(data["contacts"]) == ref.n_contacts
    rows = _table(_ok(FLEX))
    assert rows["dent_depth"] == (format_number(ref.dent_depth * 1e6), "um")
    assert rows["sequence_duration"][1] == "ms" and rows["sequence_mean_force"][1] == "N"
    assert "flags" in rows and "delta_p" not in rows


def test_simulate_flexible_rod_stop() -> None:
    """``--stop flight`` follows the other end's impacts as ``simulate(..., stop="flight")``
    does (the drop of ``impactlab drop --stop``)."""
    body = FlexibleRod.paper(n_axial=1, n_bending=2)
    ref = il.simulate(body, angle="20 deg", velocity=(0.0, -1.41), mu=0.2, history=False,
                      stop="flight")  # fmt: skip
    data = _json([*FLEX, "--stop", "flight"])
    assert data["n_contacts"] == ref.n_contacts > _json(FLEX)["n_contacts"]
    assert data["e"]["value"] == ref.e


def test_simulate_flexible_takes_a_time_limit() -> None:
    """``--time-limit`` is ``simulate(..., time_limit=)`` for the flexible rod's drop."""
    body = FlexibleRod.paper(n_axial=1, n_bending=2)
    ref = il.simulate(body, angle="20 deg", velocity=(0.0, -1.41), mu=0.2, history=False,
                      time_limit=2.0)  # fmt: skip
    data = _json([*FLEX, "--time-limit", "2 s"])
    assert data["e"]["value"] == ref.e and data["input"]["time_limit"]["value"] == 2.0


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        ([*ROD20, "--modes-axial", "3"], "--modes-axial: only a drop has modes"),
        ([*ROD20, "--stop", "flight"], "--stop: only a drop has"),
        ([*FLEX, "--stop", "landing"], "stop must be one of"),
        ([*ROD20, "--rate", "johnson-cook"], "--rate: only a drop has"),
        ([*ROD20, "--time-limit", "1 s"], "--time-limit: only a drop has"),
        (
            [*FLEX, "--time-limit", "1 ms"],
            "ms after the first touch (its last step ended past --time-limit): raise --time-limit",
        ),
        (["simulate", "sphere", "--vy", "-1 m/s", "--flexible"], "--flexible: a sphere has no"),
        ([*FLEX, "--inertia", "1 kg*m^2"], "--inertia: the flexible rod's inertia"),
        ([*FLEX, "--constant-angle"], "--constant-angle: the flexible rod's"),
        ([*FLEX, "--rate", "fast"], "--rate must be one of"),
        ([*FLEX, "--plot"], "--plot: the flexible rod's drop has no figures"),
    ],
)
def test_options_that_do_not_apply_are_refused(args: list[str], needle: str) -> None:
    res = runner.invoke(app, args)
    assert isinstance(res.exception, ValueError) and needle in str(res.exception)


#: The quantity options of each command (they take a value with a unit).
QUANTITY_OPTIONS = {
    "simulate": ("angle", "vy", "vx", "spin", "inertia", "radius", "length", "mass"),
    "drop": ("angle", "vy", "vx", "spin"),
    "invert": ("angle", "vi", "delta_p", "ls", "dv_cy", "mass", "length", "tip_radius"),
    "laws": ("radius",),
}
UNITS = ("deg", "rad", "m/s", "rad/s", "kg", " m", "mm", "um", "kg*m^2")


@pytest.mark.parametrize("command", sorted(QUANTITY_OPTIONS))
def test_every_quantity_option_names_its_unit_and_default(command: str) -> None:
    """The help of each quantity option names a unit, what a bare number means (or that the
    angle needs its unit), and its default (or that it is required)."""
    cmd = typer.main.get_command(app).commands[command]  # type: ignore[attr-defined]
    params = {p.name: p for p in cmd.params}
    for name in QUANTITY_OPTIONS[command]:
        text = params[name].help or ""
        assert any(u in text for u in UNITS), (command, name, text)
        assert "bare number" in text or "refused" in text or "with its unit" in text, text
        shown_default = params[name].default is not None and params[name].show_default
        said = any(w in text for w in ("default", "required", "optional"))
        assert said or shown_default, (command, name, text)
