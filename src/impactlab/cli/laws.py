"""``impactlab laws``: the registered contact laws, their sources, validity and parameters.

Examples::

    impactlab laws                      # table of all laws
    impactlab laws --json               # the same, machine-readable
    impactlab laws brake                # one law, with its numbers for the paper's pair
    impactlab laws ghaednia --radius "5 mm" --body aisi-1010 --flat aisi-1010 --json
    impactlab laws --accuracy           # every law against the shipped FE curves
    impactlab laws jackson-green --accuracy --json
"""

from __future__ import annotations

import textwrap
from typing import Any

import typer
from rich.table import Table
from rich.text import Text

from impactlab._display import field_row
from impactlab._json import quantity as quantity_json
from impactlab.cli._common import UserError, console, emit, positive
from impactlab.cli.laws_accuracy import print_accuracy
from impactlab.cli.printing import print_wrapped, versioned
from impactlab.contact import get_law, law_names
from impactlab.contact.base import ContactLaw
from impactlab.contact.registered import RegisteredLaw
from impactlab.materials import ContactPair, get_material


def _stand_in_text(rng: dict[str, Any]) -> str:
    """The law's range beyond the FE cases in one line: the limit, its status and its source
    (the verified part is the ``calibrated_range`` row above it)."""
    limit = rng.get("delta_ratio_max")
    ref = str(rng.get("delta_ref", "")).split(" (")[0]
    head = "no limit" if limit is None else f"{limit:g} {ref}"
    status, meaning = rng.get("status", ""), rng.get("status_meaning", "")
    return f"{head} ({status}: {meaning}); source: {rng.get('source', '')}"


def _param_text(law: ContactLaw) -> str:
    if not law.parameters:
        return "none"
    return "\n".join(
        f"{q.name} = {q.default_text}" + (f" [{q.unit}]" if q.unit not in ("", "-", "1") else "")
        for q in law.parameters
    )


def _numbers(law: ContactLaw, pair: ContactPair, radius: float) -> dict[str, Any]:
    """The law's characteristic numbers for ``pair`` and ``radius`` (SI)."""
    model = law.build(pair, radius)
    dy, fy = model.yield_onset
    out: dict[str, Any] = {
        "E_star": model.E_star,
        "radius": model.radius,
        "delta_y": dy,
        "F_y": fy,
        "switch_interference": model.switch_interference,
        "max_interference": model.max_interference,
        "calibrated_max_interference": model.calibrated_max_interference,
    }
    for key, value in model.details.items():
        out.setdefault(key, value)
    return out


_UNITS = {
    "E_star": "Pa",
    "radius": "m",
    "delta_y": "m",
    "F_y": "N",
    "switch_interference": "m",
    "switch_force": "N",
    "max_interference": "m",
    "calibrated_max_interference": "m",
    "delta_c": "m",
    "F_c": "N",
    "delta_p": "m",
    "a_p": "m",
    "P0": "Pa",
    "p_y": "Pa",
    "hardness_HB": "kgf/mm^2",
    "full_contact_interference": "m",
    "pole_interference": "m",
    "delta_c_jackson_green": "m",
    # dimensionless numbers of the laws' details
    **dict.fromkeys(
        (
            "C",
            "B",
            "switch_ratio",
            "published_jump",
            "eps",
            "t_yield",
            "residual_ratio",
            "F_nu",
            "z_over_a_at_yield",
            "meyer_index",
            "max_eq24_over_hertz",
            "limit_pressure_ratio",
            "delta_ratio_max",
            "first_failure_delta_ratio",
            "e_over_sy",
            "e_star_over_sy",
            "nu",
            # the tabulated law's (and a registered law's) curves and fit
            "elastic_limit_over_delta_c",
            "curves_e_star_over_sy",
            "curves_nu",
            "ratio_offset",
            "loading_fit_max",
            "loading_fit_rms",
            "residual_raised",
        ),
        "1",
    ),
}


#: The pair and radius of one law's example numbers (the paper's), as the options' defaults.
_EXAMPLE_PAIR = {"--radius": "8.8 mm", "--body": "aisi-201", "--flat": "aisi-1010"}


def laws(
    name: str | None = typer.Argument(None, help="Show one law in detail (e.g. 'brake')."),
    radius: str = typer.Option(
        _EXAMPLE_PAIR["--radius"],
        "--radius",
        help="Tip radius for the example numbers of one law, e.g. '5 mm' (bare number: m).",
    ),
    body: str = typer.Option(
        None,
        "--body",
        help="Body material: library name or properties (default aisi-201).",
    ),
    material: str = typer.Option(
        None, "--material", help="The body material, as --body (the name simulate gives it)."
    ),
    flat: str = typer.Option(
        _EXAMPLE_PAIR["--flat"], "--flat", help="Flat material: library name or properties."
    ),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output."),
    accuracy: bool = typer.Option(
        False,
        "--accuracy",
        help="Measured accuracy against the shipped FE curves (impactlab.fe): force and "
        "delta_r/delta_max errors, verified ranges, a recommendation per material pair.",
    ),
) -> None:
    """List the contact laws (title, reference/DOI, validity, parameters) or show one.

    Example: impactlab laws jackson-green --radius "8.8 mm" --json
    """
    try:
        if body is not None and material is not None:
            raise ValueError(
                "--body and --material both given: they name the body's material; give one"
            )
        body_option = "--body" if material is None else "--material"
        body_default = _EXAMPLE_PAIR["--body"]
        chosen = {"--radius": radius, body_option: material or body, "--flat": flat}
        given = [
            o for o, v in chosen.items() if v not in (None, _EXAMPLE_PAIR.get(o, body_default))
        ]
        if given and name is None and not accuracy:  # they set one law's example numbers
            raise ValueError(
                f"{', '.join(given)} without a law: they set the example numbers of one law "
                "(impactlab laws NAME --radius ...); the list has none"
            )
        if accuracy:
            if given:
                raise ValueError(
                    f"{', '.join(given)} with --accuracy: the accuracy is measured against the "
                    "shipped FE cases, each with its own pair and radius (all are listed); "
                    "leave them out"
                )
            print_accuracy(name, as_json)
            return
        body = material or body or _EXAMPLE_PAIR["--body"]
        _laws(name, radius, body, flat, as_json, body_option)
    except ValueError as exc:  # one line, no traceback, whichever entry point runs us
        print_wrapped(f"error: {exc}")
        raise typer.Exit(2) from None


def register(app: typer.Typer) -> None:
    """Add ``impactlab laws`` to ``app``."""
    app.command("laws")(laws)


def _described(law: ContactLaw) -> dict[str, Any]:
    """``law.describe()`` with each parameter's default as a quantity of its unit (JSON), and
    its ``unit`` as the JSON writes units (``"1"`` for a dimensionless one, not ``"-"``)."""
    info = law.describe()
    params = []
    for p in info.get("parameters", []):
        unit = p.get("unit") if p.get("unit") not in (None, "", "-") else "1"
        p = {**p, "unit": unit}
        if isinstance(p.get("default"), float):
            p = {**p, "default": quantity_json(p["default"], unit)}
        params.append(p)
    return {**info, "parameters": params}


def _citation(ref: Any) -> str:
    if isinstance(ref, dict) and "citation" in ref:
        return str(ref["citation"]) + (f" (doi:{ref['doi']})" if ref.get("doi") else "")
    return str(ref)


#: The narrowest terminal [columns] that gets the overview as a table; below it, one block per
#: law, each field wrapped to the terminal's width (an 80-column terminal reads it unfolded).
WIDE_TABLE = 120


def _law_blocks(width: int) -> None:
    """The overview as one block per law: its name and title, then the reference with its DOI,
    the validity and the parameters, each wrapped to ``width`` under a hanging indent."""
    for n in law_names():
        law = get_law(n)
        lines = textwrap.wrap(f"{n}: {law.title}", width)
        for label, text in (
            ("reference", f"{law.reference} (doi:{law.doi})"),
            ("validity", law.validity),
            ("parameters", _param_text(law).replace("\n", "; ")),
        ):
            lines += textwrap.wrap(
                f"{label}: {text}",
                width,
                initial_indent="  ",
                subsequent_indent="    ",
                break_on_hyphens=False,
            )
        console.print(Text("\n".join(lines) + "\n"))
    console.print(Text("Details of one law: impactlab laws NAME (see docs/laws/)."))


def _laws(
    name: str | None, radius: str, body: str, flat: str, as_json: bool, body_option: str
) -> None:
    """The list of the laws (``name`` None) or one law with its numbers for ``body`` (given
    by the option ``body_option``) on ``flat``."""
    if name is None:
        data = {n: _described(get_law(n)) for n in law_names()}
        if as_json:
            emit(versioned(data), as_json=True, units=_UNITS)
            return
        if console.width < WIDE_TABLE:
            _law_blocks(console.width)
            return
        table = Table(title="Contact laws", show_header=True, header_style="bold", show_lines=True)
        table.add_column("name", no_wrap=True)
        for col in ("title", "reference / DOI", "validity", "parameters (default)"):
            table.add_column(col, overflow="fold")
        for n in law_names():
            law = get_law(n)
            table.add_row(
                n, law.title, f"{law.reference}\ndoi:{law.doi}", law.validity, _param_text(law)
            )
        console.print(table)
        console.print("Details of one law: impactlab laws NAME (see docs/laws/).")
        return
    law = get_law(name)
    R = positive(radius, "m", "--radius")
    assert R is not None
    pair = ContactPair(get_material(body, body_option), get_material(flat, "--flat"))
    info = _described(law)
    try:
        numbers = _numbers(law, pair, R)
    except ValueError as exc:
        if not isinstance(law, RegisteredLaw):  # a built-in law's refusal: the user's inputs
            raise
        raise UserError(_other_pair(name, law, body, flat, exc)) from None
    info["example"] = {"body": body, "flat": flat, **numbers}
    if as_json:
        emit(versioned(info), as_json=True, units=_UNITS)
        return
    head = {k: v for k, v in info.items() if k not in ("parameters", "example", "law_id")}
    if isinstance(head.get("references"), list):  # the citations, not their records
        head["references"] = [_citation(r) for r in head["references"]]
    if isinstance(head.get("fitted_range"), dict):  # the verified part is calibrated_range's
        head["fitted_range"] = _stand_in_text(head["fitted_range"])
    emit(head, as_json=False, title=f"contact law {name!r}")
    ptable = Table(title="parameters", show_header=True, header_style="bold")
    for col in ("name", "default", "unit", "meaning"):
        ptable.add_column(col, overflow="fold")
    for q in law.parameters:
        ptable.add_row(q.name, q.default_text, q.unit, q.description)
    if law.parameters:
        console.print(ptable)
    _n, r_text, r_unit = field_row("radius", R, "m")
    title = f"numbers for {body} on {flat}, R = {r_text} {r_unit}"
    emit(info["example"], as_json=False, title=title, units=_UNITS)


def _other_pair(name: str, law: RegisteredLaw, body: str, flat: str, exc: Exception) -> str:
    """Why a law of one's own shows no numbers for ``body`` on ``flat`` (by default the paper's
    pair): its curves are another pair's; which pairs they are, and how to ask for one."""
    pairs = "; ".join(f"E*/S_y = {c.e_star_over_sy:.4g}, nu = {c.nu:.3g}" for c in law.curves or ())
    if "no indentation curves" not in str(exc):
        return f"law {name!r}: {exc}"
    return (
        f"law {name!r} has no numbers for {body} on {flat} (the example pair unless --body and "
        f"--flat are given): its curves are for {pairs}; give --body and --flat of that pair "
        f"(impactlab --law-file FILE laws {name} --flat MATERIAL)"
    )
