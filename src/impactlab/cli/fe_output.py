"""What ``impactlab fe indent`` prints and draws: what was indented (the JSON's ``case``), each
run's summary with its SI units, its table (lengths in um, run time in s) and the figure of
``--plot``."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from impactlab._display import field_row, format_value
from impactlab.cli.output_paths import save_figure
from impactlab.cli.printing import SI_UNITS
from impactlab.materials import Material

__all__ = [
    "FIGURE",
    "STOPPED_AT",
    "UNITS",
    "case_line",
    "case_record",
    "material_text",
    "plot_runs",
    "run_summary",
    "summary_rows",
]

#: The SI unit of each field of a run's summary and curves (over ``SI_UNITS``).
UNITS = {
    **dict.fromkeys(("delta_max", "delta_c", "residual_depth", "contact_radius_at_max"), "m"),
    **dict.fromkeys(("pile_up", "last_converged_delta", "loading_delta", "unloading_delta"), "m"),
    **dict.fromkeys(("contact_radius", "dent_r", "dent_z"), "m"),
    **dict.fromkeys(("loading_force", "unloading_force", "max_force"), "N"),
    **dict.fromkeys(("delta_max_over_delta_c", "residual_ratio", "force_balance"), "1"),
    "run_time": "s",
}

#: The figure of --plot, in --out.
FIGURE = "fe_indent.png"


def case_record(bm: Material, fm: Material, table: Any, **inputs: Any) -> dict[str, Any]:
    """What was indented, every input (the form of the reference files' ``inputs``:
    ``fe.curves``): both materials' values (of one given by values only those given, the rest
    None), the hardening table's rows (None without one) and ``inputs`` (with
    ``sphere_material_used``: False for a rigid sphere, whose material is recorded only)."""
    from impactlab.fe.curves import material_record

    rows = None
    if table is not None:
        rows = {
            "true_stress": [float(r[0]) for r in table],
            "true_plastic_strain": [float(r[1]) for r in table],
        }
    return {
        "sphere_material": material_record(bm, by_values=bm.name.endswith("(custom)")),
        "flat": material_record(fm, by_values=fm.name.endswith("(custom)")),
        "flat_hardening": rows,
        **inputs,
    }


def case_line(
    bm: Material, fm: Material, table: Any, sphere: str, R: float, mu: float, mesh: int
) -> str:
    """The line above the tables: what was indented (R [m]). A rigid sphere's material is
    not used (delta_c is the flat's against a rigid sphere), and the line says so."""
    ball = f"{material_text(bm)} sphere ({sphere}, R = {R * 1e3:g} mm)"
    if sphere == "rigid":
        ball = (
            f"rigid sphere (R = {R * 1e3:g} mm; its material {material_text(bm)} not used: "
            "delta_c is the flat's against a rigid sphere)"
        )
    hardening = " (hardening table)" if table is not None else ""
    return f"{ball} on {material_text(fm)}{hardening}, mu = {mu:g}, mesh level {mesh}"


def material_text(m: Material) -> str:
    """A material's name, with its values when it was given by them."""
    if not m.name.endswith("(custom)"):
        return m.name
    return f"{m.name}: E = {m.E / 1e9:g} GPa, nu = {m.nu:g}, S_y = {m.yield_strength / 1e6:g} MPa"


def run_summary(res: Any) -> dict[str, Any]:
    return {
        "delta_max": res.delta_max,
        "delta_c": res.delta_c,
        "delta_max_over_delta_c": res.delta_max / res.delta_c,
        "max_force": res.max_force,
        "residual_depth": res.residual_depth,
        "residual_ratio": res.residual_ratio,
        "contact_radius_at_max": res.contact_radius_at_max,
        "pile_up": res.pile_up,
        "converged": res.converged,
        "status": res.status(),
        "last_converged_delta": res.last_converged_delta,
        "increments": res.increments,
        "cutbacks": res.cutbacks,
        "elements": res.n_elements,
        "force_balance": res.force_balance,
        "run_time": res.run_time,
    }


#: Display units of the table (the JSON stays in SI): every length of an indentation is
#: dent-scale, in um as every command shows dents; ccx's run time in s (runs take seconds to
#: minutes).
_TABLE_UNITS = {"m": ("um", 1e6), "s": ("s", 1.0)}
#: The table's label of ``last_converged_delta`` (shown only for a run that did not converge:
#: the interference of its last converged increment, where its curves end).
STOPPED_AT = "stopped at (last_converged_delta)"


def summary_rows(res: Any) -> list[tuple[str, str, str]]:
    """The table of one run: its summary (the JSON's fields) with lengths in um and the run
    time in s; ``last_converged_delta`` only when the run did not converge (a converged run's
    is where its unloading ended, which says nothing), as :data:`STOPPED_AT`."""
    data = run_summary(res)
    stopped = data.pop("last_converged_delta")
    if not res.converged:
        data[STOPPED_AT] = stopped
    si = {**SI_UNITS, **UNITS, STOPPED_AT: "m"}
    rows = []
    for name, value in data.items():
        unit = si.get(name)
        if unit in _TABLE_UNITS and isinstance(value, float):
            shown, scale = _TABLE_UNITS[unit]
            rows.append((name, format_value(value * scale), shown))
        else:
            rows.append(field_row(name, value, unit))
    return rows


def plot_runs(results: list[Any], out: Path) -> Path:
    """The loading and unloading curves and, when some run unloaded, the residual dents
    (a loading-only run has no dent: one panel)."""
    from impactlab._mpl import pyplot
    from impactlab.experiment.checks import output_folder

    plt = pyplot()
    dented = [r for r in results if r.dent_r.size]
    if dented:
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    else:
        fig, ax1 = plt.subplots(1, 1, figsize=(5.5, 4))
    for r in results:
        lab = f"{r.delta_max / r.delta_c:.3g} delta_c"
        ax1.plot(r.loading_delta * 1e6, r.loading_force, label=lab)
        if r.unloading_delta.size:
            color = ax1.lines[-1].get_color()
            ax1.plot(r.unloading_delta * 1e6, r.unloading_force, "--", color=color)
    title = "loading and unloading" if dented else "loading"
    ax1.set(xlabel="interference [um]", ylabel="force [N]", title=title)
    if dented:
        for r in dented:
            ax2.plot(r.dent_r * 1e3, r.dent_z * 1e6, label=f"{r.delta_max / r.delta_c:.3g} delta_c")
        ax2.set(xlabel="r [mm]", ylabel="surface height [um]", title="residual dent")
        ax2.set_xlim(0, max(3.0 * float(r.contact_radius[-1]) * 1e3 for r in dented))
    ax1.legend()
    fig.tight_layout()
    try:
        return save_figure(fig, output_folder(out, "--out") / FIGURE, "fe indent", dpi=120)
    finally:
        plt.close(fig)
