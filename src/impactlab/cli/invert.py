"""``impactlab invert``: impact duration and mean force from a measured dent (paper Eqs. 12, 29)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import typer

from impactlab.analytic import InversionResult, invert
from impactlab.bodies import PAPER_ROD, Rod
from impactlab.cli._common import UserError, emit, load_toml, quantity
from impactlab.paper.data import get_case

# input name -> (SI unit used for parsing, accepted TOML keys)
_FIELDS: dict[str, tuple[str, tuple[str, ...]]] = {
    "angle": ("degree", ("angle",)),
    "v_i": ("m/s", ("vi", "v_i")),
    "e": ("", ("e",)),
    "mu": ("", ("mu",)),
    "delta_p": ("m", ("delta_p", "delta-p")),
    "L_s": ("m", ("ls", "L_s", "l_s")),
    "dv_cy": ("m/s", ("dv_cy", "dv-cy")),
}
_ROD_FIELDS: dict[str, str] = {"mass": "kg", "length": "m", "tip_radius": "m", "inertia": "kg*m^2"}
#: input name -> keyword of impactlab.analytic.invert, where they differ
_ARGUMENTS = {"L_s": "sliding_length"}


def _parse(value: Any, unit: str, name: str) -> float:
    if unit == "":
        if isinstance(value, str):
            try:
                return float(value)
            except ValueError:
                raise UserError(f"{name} must be a number, got {value!r}") from None
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise UserError(f"{name} must be a number, got {value!r}")
        return float(value)
    if unit == "degree":
        return quantity(value, "degree", name)  # type: ignore[return-value]
    return quantity(value, unit, name)  # type: ignore[return-value]


def _from_file(
    data: dict[str, Any],
) -> tuple[dict[str, float], dict[str, float], dict[str, float], dict[str, Any]]:
    values: dict[str, float] = {}
    sigmas: dict[str, float] = {}
    rod: dict[str, float] = {}
    extra: dict[str, Any] = {}
    alias = {k: name for name, (_, keys) in _FIELDS.items() for k in keys}
    for key, val in data.items():
        if key == "sigma":
            if not isinstance(val, dict):
                raise UserError("[sigma] must be a table of uncertainties")
            for sk, sv in val.items():
                if sk not in alias:
                    raise UserError(
                        f"unknown key {sk!r} in [sigma]; allowed: {', '.join(sorted(alias))}"
                    )
                name = alias[sk]
                sigmas[name] = _parse(sv, _FIELDS[name][0], f"sigma.{sk}")
        elif key == "rod":
            if not isinstance(val, dict):
                raise UserError("[rod] must be a table (mass, length, tip_radius, inertia)")
            for rk, rv in val.items():
                if rk not in _ROD_FIELDS:
                    raise UserError(
                        f"unknown key {rk!r} in [rod]; allowed: {', '.join(_ROD_FIELDS)}"
                    )
                rod[rk] = _parse(rv, _ROD_FIELDS[rk], f"rod.{rk}")
        elif key in ("case", "gravity", "samples", "seed"):
            extra[key] = val
        elif key in alias:
            values[alias[key]] = _parse(val, _FIELDS[alias[key]][0], key)
        else:
            raise UserError(
                f"unknown key {key!r} in the measurement file; allowed: "
                f"{', '.join(sorted([*alias, 'sigma', 'rod', 'case', 'gravity']))}"
            )
    return values, sigmas, rod, extra


def run_invert(
    *,
    case: str | None = None,
    file: Path | None = None,
    values: dict[str, Any] | None = None,
    sigmas: dict[str, Any] | None = None,
    rod: dict[str, Any] | None = None,
    gravity: bool | None = None,
    samples: int | None = None,
    seed: int | None = None,
) -> InversionResult:
    """Merge case < file < command line and call :func:`impactlab.analytic.invert` (the paper
    case's negative dent depth and sliding length enter as magnitudes)."""
    v: dict[str, float] = {}
    s: dict[str, float] = {}
    r: dict[str, float] = {}
    fv, fs, fr, extra = _from_file(load_toml(file))
    case = case or extra.get("case")
    if case is not None:
        x = get_case(str(case))
        v.update(angle=x.angle, v_i=x.v_i, e=x.e, mu=x.mu, delta_p=abs(x.delta_p), L_s=abs(x.L_s))
    v.update(fv)
    s.update(fs)
    r.update(fr)
    for name, val in (values or {}).items():
        if val is not None:
            v[name] = _parse(val, _FIELDS[name][0], "--" + name.replace("_", "-").lower())
    for name, val in (sigmas or {}).items():
        if val is not None:
            s[name] = _parse(val, _FIELDS[name][0], "--sigma-" + name.replace("_", "-").lower())
    for name, val in (rod or {}).items():
        if val is not None:
            r[name] = _parse(val, _ROD_FIELDS[name], "--" + name.replace("_", "-"))
    missing = [n for n in ("angle", "v_i", "mu", "delta_p", "L_s") if n not in v]
    if missing:
        opts = {
            "angle": "--angle",
            "v_i": "--vi",
            "mu": "--mu",
            "delta_p": "--delta-p",
            "L_s": "--ls",
        }
        raise UserError(
            "missing input(s): "
            + ", ".join(opts[m] for m in missing)
            + " (or use --case paper-20|paper-45|paper-70 or --file)"
        )
    if "e" not in v and "dv_cy" not in v:
        raise UserError("missing input: --e (or --dv-cy) is needed for the mean force")
    for n in s:
        if n not in v:
            raise UserError(f"an uncertainty is given for {n} but not its value")
    rod_obj = PAPER_ROD
    if r:
        # without an explicit inertia the slender-rod m L^2 / 12 of the (new) mass and length
        rod_obj = Rod(
            mass=r.get("mass", PAPER_ROD.mass),
            length=r.get("length", PAPER_ROD.length),
            tip_radius=r.get("tip_radius", PAPER_ROD.tip_radius),
            inertia=r.get("inertia"),
        )
    grav = gravity if gravity is not None else bool(extra.get("gravity", False))
    n_mc = samples if samples is not None else int(extra.get("samples", 20_000))
    seed_mc = seed if seed is not None else int(extra.get("seed", 0))
    kwargs: dict[str, Any] = {_ARGUMENTS.get(k, k): (val, s.get(k, 0.0)) for k, val in v.items()}
    return invert(**kwargs, rod=rod_obj, gravity=grav, n_samples=n_mc, seed=seed_mc)


def invert_cmd(
    angle: str | None = typer.Option(
        None, "--angle", help="Rod-to-flat angle ('20 deg'; bare numbers are degrees)."
    ),
    vi: str | None = typer.Option(
        None, "--vi", help="Drop velocity of the tip ('-1.41 m/s'; the sign is ignored)."
    ),
    e: str | None = typer.Option(None, "--e", help="Coefficient of restitution (tip, normal)."),
    mu: str | None = typer.Option(None, "--mu", help="Friction coefficient (paper Eq. 28)."),
    delta_p: str | None = typer.Option(
        None,
        "--delta-p",
        help="Permanent dent depth, a magnitude ('22 um'; the paper prints -22 um).",
    ),
    ls: str | None = typer.Option(
        None, "--ls", help="Sliding length L_s, a magnitude ('1400 um'; the paper prints -1400 um)."
    ),
    dv_cy: str | None = typer.Option(
        None,
        "--dv-cy",
        help="Measured change of the centre-of-mass vertical velocity ('0.62 m/s'): F from Eq. 29.",
    ),
    sigma_angle: str | None = typer.Option(None, "--sigma-angle", help="Std. dev. of angle."),
    sigma_vi: str | None = typer.Option(None, "--sigma-vi", help="Std. dev. of v_i."),
    sigma_e: str | None = typer.Option(None, "--sigma-e", help="Std. dev. of e."),
    sigma_mu: str | None = typer.Option(None, "--sigma-mu", help="Std. dev. of mu."),
    sigma_delta_p: str | None = typer.Option(None, "--sigma-delta-p", help="Std. dev. of delta_p."),
    sigma_ls: str | None = typer.Option(None, "--sigma-ls", help="Std. dev. of L_s."),
    sigma_dv_cy: str | None = typer.Option(None, "--sigma-dv-cy", help="Std. dev. of dv_cy."),
    mass: str | None = typer.Option(None, "--mass", help="Rod mass (default 0.4607 kg)."),
    length: str | None = typer.Option(None, "--length", help="Rod length (default 0.3048 m)."),
    tip_radius: str | None = typer.Option(
        None, "--tip-radius", help="Tip radius (default 8.8 mm)."
    ),
    inertia: str | None = typer.Option(
        None,
        "--inertia",
        help="I_C about the centre of mass (default m L^2/12), e.g. '3.6e-3 kg*m^2'.",
    ),
    case: str | None = typer.Option(
        None, "--case", help="Start from the paper's measurements: paper-20, paper-45 or paper-70."
    ),
    file: str | None = typer.Option(
        None,
        "--file",
        help="TOML file with the measurements (keys as the options; [sigma] and [rod] tables).",
    ),
    gravity: bool | None = typer.Option(
        None,
        "--gravity/--no-gravity",
        help="Include gravity during the contact (default: no, as the paper).",
    ),
    samples: int | None = typer.Option(
        None, "--samples", help="Monte Carlo samples (default 20000)."
    ),
    seed: int | None = typer.Option(None, "--seed", help="Monte Carlo seed (default 0)."),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output (SI)."),
) -> None:
    """Impact duration T and mean normal force F from a measured oblique impact of the rod.

    Inverts the paper's Eq. 12 (corrected) for T and Eq. 29 (or the rigid-body identity
    F T = (1 + e)|v_i| / K_y) for F, with first-order and Monte Carlo uncertainties.

    Example: impactlab invert --angle "20 deg" --vi "-1.41 m/s" --e 0.5 --mu 0.2
    --delta-p "22 um" --ls "1400 um" --sigma-ls "50 um"
    """
    res = run_invert(
        case=case,
        file=Path(file) if file is not None else None,
        values={
            "angle": angle,
            "v_i": vi,
            "e": e,
            "mu": mu,
            "delta_p": delta_p,
            "L_s": ls,
            "dv_cy": dv_cy,
        },
        sigmas={
            "angle": sigma_angle,
            "v_i": sigma_vi,
            "e": sigma_e,
            "mu": sigma_mu,
            "delta_p": sigma_delta_p,
            "L_s": sigma_ls,
            "dv_cy": sigma_dv_cy,
        },
        rod={"mass": mass, "length": length, "tip_radius": tip_radius, "inertia": inertia},
        gravity=gravity,
        samples=samples,
        seed=seed,
    )
    if as_json:
        emit(res.to_dict(), as_json=True)
    else:
        _print_result(res)


def _print_result(res: InversionResult) -> None:
    data = {
        "T": res.T * 1e3,
        "sigma T (first order)": res.sigma_T_linear * 1e3,
        "sigma T (Monte Carlo)": res.sigma_T_mc * 1e3,
        "F": res.F,
        "sigma F (first order)": res.sigma_F_linear,
        "sigma F (Monte Carlo)": res.sigma_F_mc,
        "force from": res.force_method,
        "alpha": res.alpha,
        "mu_c": res.mu_c,
        "K_x": res.K_x,
        "K_y": res.K_y,
        "angle": math.degrees(res.inputs["angle"][0]),
        "gravity": "included" if res.gravity else "neglected (paper)",
    }
    units = {
        "T": "ms",
        "sigma T (first order)": "ms",
        "sigma T (Monte Carlo)": "ms",
        "F": "N",
        "sigma F (first order)": "N",
        "sigma F (Monte Carlo)": "N",
        "K_x": "1/kg",
        "K_y": "1/kg",
        "angle": "deg",
    }
    emit(data, as_json=False, title="impactlab invert (paper Eqs. 12, 29)", units=units)
    if res.mc_rejected > 0:
        typer.echo(
            f"note: {res.mc_rejected:.2%} of the Monte Carlo samples fell in the "
            "sticking regime or out of range and were discarded"
        )


def register(app: typer.Typer) -> None:
    """Add ``impactlab invert`` to ``app``."""
    app.command("invert")(invert_cmd)
