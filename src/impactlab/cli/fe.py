"""``impactlab fe indent``: the finite-element indentation reference (CalculiX).

Examples::

    impactlab fe indent --max "10 um" --max "100 um"              # the paper's pair, R = 8.8 mm
    impactlab fe indent --max "5 um" --flat-E "69 GPa" --flat-nu 0.33 --flat-sy "276 MPa"
    impactlab fe indent --max "20 um" --sphere rigid --hardening flat.csv --json
    impactlab fe indent --max "50 um" --mesh 2 --plot --out fe-out/
    impactlab fe indent --max "5 um" --mu 0.3 --loading-only     # no unloading step
"""

from __future__ import annotations

import json
import sys
import warnings
from pathlib import Path
from typing import Any, cast

import typer

from impactlab._version import __version__
from impactlab.cli._common import (
    SI_UNITS,
    UserError,
    as_option,
    console,
    positive,
    print_rows,
    quantity,
)
from impactlab.cli.config_values import plain_number
from impactlab.cli.fe_hardening import read_hardening
from impactlab.cli.fe_output import (
    FIGURE,
    STOPPED_AT,  # noqa: F401  (re-exported: the old home)
    UNITS,
    case_line,
    case_record,
    plot_runs,
    run_summary,
    summary_rows,
)
from impactlab.cli.output_paths import check_replaceable
from impactlab.materials import Material, get_material

fe_app = typer.Typer(
    name="fe",
    help="Finite-element reference (CalculiX): sphere-on-flat indentation.",
    no_args_is_help=True,
    rich_markup_mode=None,
)


def _material(
    name: str | None, E: str | None, nu: float | None, sy: str | None, label: str
) -> Material:
    """The library material ``name`` (or a material by values, ``impactlab.materials``), or
    the one --LABEL-E, --LABEL-nu and --LABEL-sy define whole: all three or none (a library
    material is never partly changed); a name given with them is refused (None: not given,
    the paper's: aisi-1010 for the flat, aisi-201 for the sphere)."""
    values = {"E": E, "nu": nu, "sy": sy}
    given = [k for k, v in values.items() if v is not None]
    if name is not None and given:  # one of them would be ignored
        named = "--body/--material" if label == "body" else f"--{label}"
        raise UserError(f"{named} and --{label}-E/-nu/-sy both given: they name the {label}'s "
                        "material; give one (a material, or its values)")  # fmt: skip
    if name is None:  # the paper's flat and rod
        name = "aisi-1010" if label == "flat" else "aisi-201"
    if not given:
        try:
            return get_material(name, "--body/--material" if label == "body" else f"--{label}")
        except ValueError as exc:
            raise UserError(str(exc)) from None
    if len(given) < 3:
        missing = [f"--{label}-{k}" for k in values if values[k] is None]
        raise UserError(
            f"{', '.join(f'--{label}-{k}' for k in given)} without {', '.join(missing)}: a "
            f"material by values is given whole (a library material is never partly changed)"
        )
    try:  # its warnings only for a material that is made: a refused one gets one line
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            made = Material(
                f"{label} (custom)",
                quantity(E, "Pa", f"--{label}-E"),  # type: ignore[arg-type]
                float(nu),  # type: ignore[arg-type]
                quantity(sy, "Pa", f"--{label}-sy"),  # type: ignore[arg-type]
            )
    except ValueError as exc:  # the Material's own words, named by the option that set it
        option = {"E": "E", "nu": "nu", "yield_strength": "sy"}.get(str(exc).split()[0])
        raise UserError(f"--{label}-{option or 'E/nu/sy'}: {exc}") from None
    for w in caught:
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return made


#: The options of ``make_problem``'s parameters, for its messages.
_OPTIONS = {"delta_max": "--max", "radius": "--radius", "sphere": "--sphere", "mu": "--mu",
            "mesh_level": "--mesh", "flat_hardening": "--hardening"}  # fmt: skip
#: The unit hint of a length given as a bare number (taken in m).
BARE_HINT = " (a bare number is in m: give a unit, e.g. '5 um')"
#: The largest sphere radius [m] taken: a larger one is a unit mistake (--radius 5: 5 m).
MAX_RADIUS = 1.0


def _bare(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _check_sizes(maxima: list[str], deltas: list[float], radius: str, R: float) -> None:
    """The radius at most :data:`MAX_RADIUS`, each --max below it and below the largest the
    radius allows (``fe.problem.largest_delta_max``); a unit hint for bare ones."""
    from impactlab.fe.problem import largest_delta_max, rounded_down

    if R > MAX_RADIUS:
        hint = " (a bare number is in m: give a unit, e.g. '5 mm')" if _bare(radius) else ""
        raise UserError(f"--radius {radius!r} ({R:g} m) is larger than {MAX_RADIUS:g} m, the "
                        f"largest sphere taken{hint}")  # fmt: skip
    for text, d in zip(maxima, deltas, strict=True):
        hint = BARE_HINT if _bare(text) or _bare(radius) else ""
        if d >= R:
            raise UserError(
                f"--max {text!r} ({d:g} m) must be smaller than the sphere radius (--radius "
                f"{radius!r}, {R:g} m){hint}"
            )
        if d >= largest_delta_max(R):
            raise UserError(
                f"--max {text!r} ({d:g} m) is too large for the sphere radius (--radius "
                f"{radius!r}, {R:g} m): the contact radius would reach the sphere's equator; "
                f"allowed --max < {rounded_down(largest_delta_max(R))} m{hint}"
            )


def _check_run(workers: int | None, out: Path | None, mu: str) -> float:
    """Before any run: --workers at least 1; the figure's folder ``out`` (with --plot) holds
    no user's file of its name (``output_paths.check_replaceable``); --mu a number (returned)."""
    from impactlab.cli.output_paths import output_dir

    if workers is not None and workers < 1:
        raise UserError(f"--workers must be a positive integer, got {workers}")
    if out is not None:
        check_replaceable(output_dir(out, "--out"), [FIGURE], "fe indent", "--out")
    return plain_number(mu, "--mu")


@fe_app.command("indent", short_help="Indent a flat with a sphere and unload it (CalculiX).")
def indent_cmd(
    maxima: list[str] = typer.Option(
        ...,
        "--max",
        metavar="DEPTH",
        help="Largest interference, with units ('20 um'); repeatable: --max '10 um' --max "
        "'100 um'.",
    ),
    radius: str = typer.Option(
        "8.8 mm",
        "--radius",
        help=f"Sphere radius, e.g. '5 mm' (bare number: m; at most {MAX_RADIUS:g} m).",
    ),
    sphere: str = typer.Option(
        "elastic-plastic", help="rigid (its material not used), elastic or elastic-plastic."
    ),
    body: str | None = typer.Option(
        None,
        "--body",
        "--material",
        help="The sphere's material: a library name (see 'impactlab materials'), properties "
        "'E=200GPa, nu=0.3, Sy=760MPa, rho=7800kg/m^3' or a TOML file (default aisi-201; or "
        "--body-E/-nu/-sy).",
    ),
    flat: str | None = typer.Option(
        None,
        help="The flat's material: a library name, properties 'E=69GPa, nu=0.33, Sy=276MPa, "
        "rho=2700kg/m^3' or a TOML file (default aisi-1010; or --flat-E/-nu/-sy).",
    ),
    flat_E: str | None = typer.Option(
        None, "--flat-E", help="Flat's Young's modulus, e.g. '69 GPa' (a bare number: Pa)."
    ),
    flat_nu: float | None = typer.Option(None, "--flat-nu", help="Flat's Poisson's ratio."),
    flat_sy: str | None = typer.Option(
        None, "--flat-sy", help="Flat's yield strength, e.g. '276 MPa' (a bare number: Pa)."
    ),
    body_E: str | None = typer.Option(
        None, "--body-E", help="Sphere's Young's modulus, e.g. '210 GPa' (a bare number: Pa)."
    ),
    body_nu: float | None = typer.Option(None, "--body-nu", help="Sphere's Poisson's ratio."),
    body_sy: str | None = typer.Option(
        None, "--body-sy", help="Sphere's yield strength, e.g. '1.5 GPa' (a bare number: Pa)."
    ),
    hardening: Path | None = typer.Option(
        None,
        help="CSV of the flat's true stress [Pa], true plastic strain (first strain 0); a "
        "header line naming the columns (plastic_strain,stress_Pa) sets their order.",
    ),
    mu_text: str = typer.Option("0", "--mu", help="Friction coefficient of the contact."),
    mesh: int = typer.Option(1, "--mesh", help="Mesh level 1-4 (each doubles the elements)."),
    loading_only: bool = typer.Option(
        False,
        "--loading-only",
        help="Stop at each --max: the loading curve only (no unloading, delta_r or dent).",
    ),
    workers: int | None = typer.Option(None, help="Parallel ccx processes (default: CPUs)."),
    no_cache: bool = typer.Option(False, "--no-cache", help="Run even if cached."),
    plot: bool = typer.Option(False, "--plot", help=f"Write a figure ({FIGURE})."),
    out: Path = typer.Option(
        Path("."), "--out", show_default=False, help="Folder for the figure (default: current)."
    ),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output (with curves)."),
) -> None:
    """Indent a flat with a sphere to each --max and unload (CalculiX, axisymmetric; with
    --loading-only the run stops at each --max).

    Examples:

    \b
      impactlab fe indent --max "10 um" --max "100 um"
      impactlab fe indent --max "5 um" --flat-E "69 GPa" --flat-nu 0.33 \\
        --flat-sy "276 MPa"
      impactlab fe indent --max "20 um" --sphere rigid --hardening flat.csv --json
      impactlab fe indent --max "50 um" --mesh 2 --plot --out fe-out/
      impactlab fe indent --max "5 um" --mu 0.3 --loading-only
    """
    from impactlab.fe import DamagedRunsError, NotCalculixError, find_ccx, indent
    from impactlab.fe.problem import make_problem

    R = cast(float, positive(radius, "m", "--radius"))  # the option has a default
    deltas = [positive(m, "m", "--max") for m in maxima]
    fm = _material(flat, flat_E, flat_nu, flat_sy, "flat")
    bm = _material(body, body_E, body_nu, body_sy, "body")
    table = read_hardening(hardening) if hardening is not None else None
    mu = _check_run(workers, out if plot else None, mu_text)
    _check_sizes(maxima, cast(list[float], deltas), radius, R)
    for d in deltas:  # bad input is refused before ccx is looked for (``indent`` checks again)
        try:
            make_problem(
                fm, bm, radius=R, delta_max=d, sphere=sphere, flat_hardening=table, mu=mu,
                mesh_level=mesh, unload=not loading_only,
            )  # fmt: skip
        except ValueError as exc:  # named by the option that set it: "NAME must", "NAME: ..."
            head, colon, rest = str(exc).partition(": ")
            text = f"{_OPTIONS[head]}: {rest}" if colon and head in _OPTIONS else str(exc)
            raise UserError(as_option(text, _OPTIONS, _OPTIONS.__getitem__)) from None
    try:
        find_ccx()
    except RuntimeError as exc:  # not installed: one line saying how to install it
        raise UserError(str(exc)) from None
    done: list[int] = []
    show = sys.stdout.isatty() and not as_json

    def progress(i: int, res: Any) -> None:
        done.append(i)
        if show:
            console.print(
                f"[{len(done)}/{len(deltas)}] delta_max = {res.delta_max * 1e6:.4g} um: "
                f"{res.status()} ({res.run_time:.1f} s)",
                markup=False,
            )

    kwargs: dict[str, Any] = {
        "radius": R, "delta_max": deltas, "sphere": sphere, "flat_hardening": table, "mu": mu,
        "mesh_level": mesh, "unload": not loading_only, "workers": workers,
        "use_cache": not no_cache, "progress": progress,
    }  # fmt: skip
    damaged: DamagedRunsError | None = None
    try:
        if show:
            with console.status(f"running {len(deltas)} CalculiX indentation(s) ..."):
                results = indent(fm, bm, **kwargs)
        else:
            results = indent(fm, bm, **kwargs)
    except DamagedRunsError as exc:  # the runs that ended are printed, then the error
        damaged, results = exc, [r for r in exc.results if r is not None]
    except NotCalculixError as exc:  # IMPACTLAB_CCX=/bin/true: one line, before any run
        raise UserError(str(exc)) from None
    case = case_record(  # what was indented: the JSON's "case"; a rigid sphere's material unused
        bm, fm, table, sphere=sphere, sphere_material_used=sphere != "rigid", radius=R, mu=mu,
        mesh_level=mesh, loading_only=loading_only,
    )  # fmt: skip
    if as_json:
        from impactlab._json import to_json
        from impactlab.fe.cache import ARRAYS

        payload = [
            {**run_summary(r), **{n: getattr(r, n).tolist() for n in ARRAYS}} for r in results
        ]
        materials = ("E", "nu", "yield_strength", "brinell_hardness", "meyer_index", "density")
        units = {**UNITS, **{key: SI_UNITS[key] for key in materials}, "radius": "m", "mu": "1",
                 "true_stress": "Pa", "true_plastic_strain": "1"}  # fmt: skip
        doc = {"case": case, "runs": payload, "impactlab_version": __version__}
        print(json.dumps(to_json(doc, units), indent=2))
    else:
        console.print(case_line(bm, fm, table, sphere, R, mu, mesh), markup=False)
        for r in results:
            print_rows(summary_rows(r), f"FE indentation to {r.delta_max * 1e6:.4g} um")
    if plot:
        path = plot_runs(results, out)
        if not as_json:
            console.print(f"figure: {path}", markup=False)
    if damaged is not None:
        raise UserError(str(damaged))
    failed = [r for r in results if not r.usable]
    if failed:  # what converged is printed above; the status says that not all did
        raise UserError(
            f"{len(failed)} of {len(results)} FE run(s) did not converge"
            + ("" if all(not r.converged for r in failed) else " or do not balance their forces")
            + " (delta_max = "
            + ", ".join(f"{r.delta_max * 1e6:.4g} um" for r in failed)
            + "): their curves stop at the last converged point; see each run's status"
        )


def register(app: typer.Typer) -> None:
    """Add ``impactlab fe ...`` to the command line."""
    app.add_typer(fe_app, name="fe")
