"""The paper's three drops as a calibration: the drops with their assumed uncertainties, the
configurations of :mod:`impactlab.paper.physics` as candidate models, the prior of the flexible
rod's modal damping ratio zeta, and the run (``calibrate_paper``).

The measured values (e, delta_p, L_s at 20, 45 and 70 deg, Sec. 5.1.3) come without stated
uncertainties; ``PAPER_SIGMAS`` are this module's assumption (e +- 0.03; delta_p and L_s +- 10 %),
stated in the section (:mod:`impactlab.paper.calibration_report`). L_s is compared with the
extent of the mark the tip left (``scar_length``: the contact point's travel of a rigid impact, a
drop's scar length over all its contacts; not the slip integral); e with the gravity impulse of
the contact removed, for the rigid rod as for the drops (``dynamics.derived.e_gravity_removed``).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from impactlab.calibrate import Calibration, CandidateModel, Measurements, calibrate
from impactlab.calibrate import parse_parameter as _prior
from impactlab.calibrate.sampler import ProgressFn
from impactlab.paper import data as D
from impactlab.paper.physics import FE_TABULATED, FRICTION, HARDENED_LAW, ROWS

__all__ = [
    "HARDENED_LAW_NAME",
    "PAPER_SIGMAS",
    "SHIPPED_PPC",
    "SHIPPED_STEPS",
    "SHIPPED_WALKERS",
    "ZETA_PRIOR",
    "calibrate_paper",
    "hardened_law",
    "paper_measurements",
    "paper_models",
]

#: The sampler of the shipped run: the chains' autocorrelation time is about 25 steps, so 50
#: of them after a burn-in of half the chain need about 2500 steps (2400: 45-49 of them).
SHIPPED_WALKERS = 8
SHIPPED_STEPS = 2400
#: The posterior draws of the shipped run's predictive check (the shipped summary, written
#: before the summary recorded it, used calibrate_paper's default).
SHIPPED_PPC = 30

#: Assumed standard uncertainties: e absolute, delta_p and L_s relative.
PAPER_SIGMAS = {"e": 0.03, "delta_p": 0.10, "scar_length": 0.10}
#: The prior of the flexible rod's modal damping ratio (the hand fit's scan range).
ZETA_PRIOR = "uniform(0, 0.6)"


#: The name under which the FE-tabulated law of the hardening flat is registered for the
#: calibration (a candidate model names its law; ``contact.register_law``).
HARDENED_LAW_NAME = "paper-fe-hardened"


@contextmanager
def hardened_law() -> Iterator[str]:
    """The FE-tabulated law of the hardening flat registered under :data:`HARDENED_LAW_NAME`
    while the block runs (the same curves as the physics section's), unregistered after it
    unless it was registered before: a calibration leaves the process's laws as it found them."""
    from impactlab.contact import law_names, register_law, unregister_law
    from impactlab.fe.tabulated import hardened_curves

    ours = HARDENED_LAW_NAME not in law_names()
    if ours:
        register_law(HARDENED_LAW_NAME, hardened_curves(), title=FE_TABULATED.name)
    try:
        yield HARDENED_LAW_NAME
    finally:
        if ours:
            unregister_law(HARDENED_LAW_NAME)


def paper_models(hardened: str) -> tuple[CandidateModel, ...]:
    """Every configuration of the physics section as a candidate model (its law, friction,
    body and rate), the FE-tabulated one under the registered law ``hardened``
    (``with hardened_law() as name: paper_models(name)``)."""
    return tuple(
        CandidateModel(
            hardened if c.law == HARDENED_LAW else c.law,
            FRICTION,
            "flexible_rod" if c.flexible else None,
            name=c.name,
            rate=c.rate,
        )
        for c in ROWS
    )


def paper_measurements(sigmas: dict[str, float] | None = None) -> Measurements:
    """The three drops: the paper's rod on AISI 1010, angle, drop velocity (0, v_i) and
    measured mu of each; measured e, delta_p and |L_s| with the ``PAPER_SIGMAS``."""
    s = {**PAPER_SIGMAS, **(sigmas or {})}
    records = []
    for ang, x in D.EXPERIMENTS.items():
        dp, ls = abs(x.delta_p), abs(x.L_s)
        records.append(
            {
                "label": f"{ang} deg",
                "angle": f"{x.angle_deg} deg",
                "vy": x.v_i,
                "mu": x.mu,
                "e": x.e,
                "e_sigma": s["e"],
                "delta_p": dp,
                "delta_p_sigma": s["delta_p"] * dp,
                "scar_length": ls,
                "scar_length_sigma": s["scar_length"] * ls,
            }
        )
    return Measurements.from_records(records)


def calibrate_paper(
    models: Sequence[CandidateModel] | None = None,
    *,
    walkers: int = SHIPPED_WALKERS,
    steps: int = SHIPPED_STEPS,
    seed: int = 0,
    n_ppc: int = SHIPPED_PPC,
    progress: ProgressFn | None = None,
    state_dir: Any = None,
) -> Calibration:
    """zeta ~ ``ZETA_PRIOR`` for every configuration (``models``; None: ``paper_models``)
    on the three drops. A flexible drop costs about 0.1 s here (its modes are rebuilt for each
    zeta): the defaults (the shipped run's) take about 40 minutes on 2 cores; the rigid rod
    does not use zeta (a CalibrationWarning says so)."""
    import warnings

    from impactlab.calibrate import CalibrationWarning

    with warnings.catch_warnings(), hardened_law() as hardened:
        warnings.simplefilter("ignore", CalibrationWarning)  # reported in cal.warnings
        return calibrate(
            paper_measurements(),
            [_prior("damping", ZETA_PRIOR)],
            list(paper_models(hardened) if models is None else models),
            walkers=walkers,
            steps=steps,
            seed=seed,
            n_ppc=n_ppc,
            progress=progress,
            state_dir=state_dir,
        )
