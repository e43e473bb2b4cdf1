"""``explain``: which physics explains measured drops. Every drop of a measurements file runs
in each configuration (the rigid body, the flexible rod, the flexible rod on a rate-dependent
flat; ``explain.configurations``) with nothing tuned, and each measured quantity is set beside
its prediction, made as the calibration makes it (``explain.runs``)."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Iterable
from pathlib import Path

from impactlab.calibrate.measurements import Measurements, read_measurements
from impactlab.contact import get_law
from impactlab.dynamics.drop import ELASTIC_LAWS
from impactlab.explain.configurations import Configuration, configurations, rate_not_applicable
from impactlab.explain.correlated import drop_pairs
from impactlab.explain.modes import check_modes
from impactlab.explain.notes import explanation_notes
from impactlab.explain.result import Explanation
from impactlab.explain.runs import Outcome, drop_alone, drop_flat, run_on_drop
from impactlab.explain.tables import comparison_table, summary_table
from impactlab.explain.verdict import drop_modes, verdict

__all__ = ["ELASTIC_NOT_RUN", "FRICTION", "INERTIA_NOT_RUN", "SPHERE_NOT_RUN", "explain"]

#: The friction model of every configuration, with each drop's measured mu as its coefficient.
FRICTION = "coulomb"
#: Why a sphere's drop runs the rigid configuration only.
SPHERE_NOT_RUN = (
    "not run: the drop is a sphere's; the flexible rod and its rate-dependent flat model a "
    "rod's drop (the rigid configuration is the sphere's impact)"
)
#: Why a rod's drop that gives its moment of inertia runs the rigid configuration only.
INERTIA_NOT_RUN = (
    "not run: the drop gives the rod's moment of inertia (its 'inertia' column), an input the "
    "flexible rod does not have: its inertia follows from its length, mass and material as a "
    "beam's; leave the column out to run the flexible rows (the rigid rod uses it as given)"
)

#: Why a rate row does not run with an elastic contact law (``{law}``: its name).
ELASTIC_NOT_RUN = (
    "not run: the {law!r} law is elastic (no yield strength for the rate to raise); give no "
    "rate row (--rate none; rate_laws=[]), or an elastic-plastic law (--law; law=)"
)

Progress = Callable[[str, int, int], None]


def _measurements(measurements: str | Path | Measurements) -> Measurements:
    if isinstance(measurements, Measurements):
        meas = measurements
    elif isinstance(measurements, str | Path):
        meas = read_measurements(measurements)
    else:
        raise ValueError(
            "measurements must be a measurements file (CSV or TOML, docs/calibrate.md) or a "
            f"Measurements, got {type(measurements).__name__}"
        )
    _refuse_missing_mu(meas)
    if meas.n_values == 0:
        raise ValueError("the measurements hold no measured value: nothing to explain")
    return meas


def _refuse_missing_mu(meas: Measurements) -> None:
    """ValueError naming the drops without a measured mu (position and label, after the file
    they were read from: ``m.toml: drop 2 (b) gives no mu: ...``)."""
    mu = meas.inputs["mu"]
    missing = [d for d in range(meas.n_drops) if not math.isfinite(mu[d])]
    if not missing:
        return
    some = len(missing) < meas.n_drops  # the column is there, a cell of it empty
    suffix = Path(meas.source).suffix.lower() if meas.source else ""
    drops = ", ".join(f"{d + 1} ({meas.labels[d]})" for d in missing)
    where = f"drop {drops} gives" if len(missing) == 1 else f"drops {drops} give"
    if suffix == ".toml":
        how = "give each [[drop]] its mu key"
    elif suffix == ".csv":
        how = "fill in each drop's mu cell" if some else "add a mu column"
    else:
        how = "give each drop its mu"
    raise ValueError(
        f"{meas.source + ': ' if meas.source else ''}{where} no mu: explain runs every drop "
        f"with its measured mu as the Coulomb coefficient (nothing tuned); {how}"
    )


def _not_run(config: Configuration, meas: Measurements, d: int, law: str) -> str | None:
    """Why ``config`` with the contact ``law`` does not run on drop ``d`` (None: it runs)."""
    if not config.flexible:
        return None
    if config.rate is not None and law.strip().lower() in ELASTIC_LAWS:
        return ELASTIC_NOT_RUN.format(law=law)
    if meas.categories[d]["body"] == "sphere":
        return SPHERE_NOT_RUN
    inertia = meas.inputs.get("inertia")
    if inertia is not None and math.isfinite(inertia[d]):
        return INERTIA_NOT_RUN
    return rate_not_applicable(config, drop_flat(meas, d))


def explain(
    measurements: str | Path | Measurements,
    *,
    law: str = "ghaednia",
    rate_laws: Iterable[object] | None = None,
    progress: Progress | None = None,
) -> Explanation:
    """Which physics explains measured drops, nothing tuned: each drop of ``measurements`` (a
    measurements file, CSV or TOML, docs/calibrate.md, or a ``Measurements``) with the rigid
    body, the flexible rod and the flexible rod on a rate-dependent flat, each with the contact
    ``law`` and Coulomb friction of the drop's measured mu, every measured quantity beside its
    prediction (z, within 2 sigma) and per drop and configuration a summary.

    ``rate_laws``: the rate-dependent rows' laws; None: the library's Cowper-Symonds (upper
    estimate) and Johnson-Cook (lower) for a low-carbon steel flat, not run on another flat
    (the result says why); else rate laws as ``simulate``'s ``rate`` takes them
    (``"cowper-symonds(D=6500 1/s, q=4)"``, a ``RateLaw``), the flat's own constants, run on
    every rod's drop; ``[]`` (or ``["none"]``, ``[None]``): none; with an elastic ``law``
    (Hertz) the rate rows do not run. A sphere's drop, and a rod's drop that gives its
    ``inertia`` (an input the flexible rod does not have), run the rigid configuration only.
    Each ok flexible run is checked in its modes with twice its mode counts, at most 128
    (``explain.modes``: a row they move by more than half a sigma is marked, its numbers kept;
    a row at the limit is not checked, and says so).
    A drop's correlation coefficients make its chi2 z^T R^-1 z (``explain.correlated``).
    ``progress(configuration, done, total)`` is called after each run. ValueError for a drop
    without mu, a law or rate law not known, or a file the calibration's reader refuses."""
    get_law(law)  # ValueError naming the known laws
    meas = _measurements(measurements)
    configs = configurations(rate_laws)
    outcomes: dict[tuple[str, str], Outcome] = {}
    total, done = meas.n_drops * len(configs), 0
    for config in configs:
        for d, label in enumerate(meas.labels):
            reason = _not_run(config, meas, d, law)
            if reason is None:
                alone = drop_alone(meas, d)
                out = run_on_drop(config, alone, law, FRICTION)
                check = check_modes(config, alone, law, FRICTION, out)
                outcomes[(label, config.name)] = dataclasses.replace(out, modes=check)
            else:
                outcomes[(label, config.name)] = Outcome(reason, False, {})
            done += 1
            if progress is not None:
                progress(config.name, done, total)
    comparison = comparison_table(meas, configs, outcomes)
    summary = summary_table(meas, configs, outcomes, comparison)
    pairs = {label: drop_pairs(meas, d) for d, label in enumerate(meas.labels)}
    verdicts = [verdict(summary, comparison, label, pairs[label], drop_modes(outcomes, label))
                for label in meas.labels]  # fmt: skip
    notes = explanation_notes(outcomes, summary, verdicts, pairs)
    return Explanation(
        comparison, summary, configs, law, FRICTION, notes, meas.source, outcomes, pairs
    )  # fmt: skip
