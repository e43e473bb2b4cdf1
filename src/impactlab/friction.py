"""Tangential (friction) models of the impact engine: names, compiled ids and references.

The equations of ``impulse_ratio``, ``coulomb`` and ``mindlin`` are in ``docs/engine/index.md``
("Friction models"); those of ``partial_slip``, with its measured accuracy, in
``docs/verification/index.md`` (section "Partial slip"). The compiled implementation is in
``impactlab.dynamics.core`` (``partial_slip``: ``impactlab.dynamics.slipcore``). A name never
stands in for another model. The registry is keyed by :class:`FrictionKind` members; plain
strings (``"coulomb"``) work wherever a kind is asked for.

- ``impulse_ratio``: the paper's Eq. 7 (doi:10.1007/s00419-015-1108-2): F_t = mu F_n against the
  initial slip direction of the contact point, constant over the impact. When the initial
  tangential velocity of the contact point is zero, against the slip that the normal force alone
  starts (sign of -a b for the rod); no tangential force when neither gives a direction.
- ``coulomb``: exact Coulomb stick/slip for a rigid contact point: slip F_t = -mu F_n sign(v_slip);
  stick (v_slip = 0) while the force the constraint needs, computed from the rigid-body equations,
  satisfies |F_t*| <= mu F_n. Transitions are located as events (no regularisation).
  Reference: W. J. Stronge, Impact Mechanics (2000), Ch. 5, doi:10.1017/CBO9780511626432.
  It is also the energy-consistent completion of the paper's Eq. 7: Eq. 7 is the slip branch of
  Coulomb's law, so ``coulomb`` equals ``impulse_ratio`` exactly while the contact point slips;
  where the slip stops, the friction impulse stops growing (stick, or slip the other way) and no
  energy is created, whereas ``impulse_ratio`` keeps pushing and can (flagged ENERGY_GAIN).
- ``mindlin``: tangential compliance of Mindlin type with stiffness k_t = 8 G* a following the
  contact radius a, an elastic tangential state, capped by Coulomb mu F_n (gross slip on the cap).
  Incremental (no-slip) loading dF_t = -k_t dxi; on unloading the force is scaled with k_t
  (constant elastic displacement), the Mindlin-Deresiewicz-type scheme of Di Renzo & Di Maio
  (2004) doi:10.1016/j.ces.2003.09.037 and Thornton, Cummins & Cleary (2011, Powder Technol.
  210, 189); theory: Mindlin & Deresiewicz, J. Appl. Mech. 20 (1953) 327; oblique impact
  behaviour: Maw, Barber & Fawcett, Wear 38 (1976) 101, doi:10.1016/0043-1648(76)90201-5.
- ``partial_slip``: Mindlin-Deresiewicz partial slip with arbitrary normal and tangential load
  history (R. D. Mindlin, J. Appl. Mech. 16 (1949) 259, doi:10.1115/1.4009973; R. D. Mindlin,
  H. Deresiewicz, J. Appl. Mech. 20 (1953) 327, doi:10.1115/1.4010702), solved in its exact
  one-dimensional form by the method of dimensionality reduction (V. L. Popov, M. Hess, Facta
  Universitatis Mech. Eng. 12 (2014) 1) and discretised into ``PARTIAL_SLIP_CELLS`` cells with
  stick/slip events: microslip spreading in from the contact edge, Masing unloading, births of
  unstressed annuli, the tangential stiffness 8 G* a of the actual (plastic) contact radius.
  Compiled in ``impactlab.dynamics.slipcore``; ``simulate``, the batch engine and sweeps.
  Accuracy of the 16 cells against the exact solution (elastic spheres, nu = 0.1-0.45): each
  cell sticks or slips as a whole, so a slip annulus thinner than a cell (a_max/16) is not
  resolved. It is that thin near normal incidence, psi1 = 4 G* |v_t,in| / (mu E* |v_n|) below
  about 0.2: there |e_t - exact| reaches 2.7e-3 (psi1 ~ 0.05) and falls more slowly than N^-2,
  and the contact point's v_t,out/v_t,in is up to 0.0095 too far forward, so a ratio under 0.01
  in size can have the wrong sign (nu = 0.45, psi1 = 0.03: exact -0.006, 16 cells +0.002).
  From psi1 ~ 0.2 the error falls like N^-2: |e_t - exact| < 8e-4 (< 3e-4 from psi1 = 1).
  psi2 = 4 G* v_t,out / (mu E* |v_n|) is within 1.5e-3 throughout, every error towards a more
  forward rebound (tests/dynamics/test_partial_slip_accuracy.py). More cells converge it:
  ``partial_slip_cells`` (4 to 64; ``simulate``, ``simulate_batch``, a sweep's ``[engine]``,
  ``--partial-slip-cells``) takes the error in e_t at psi1 = 0.05 (nu = 0.45) from 2.7e-3
  (16) to 8.0e-4 (32) and 1.7e-4 (64) for 2 to 5 times the cost.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from impactlab._validation import did_you_mean
from impactlab.references import PAPER, Reference, cite

DEFAULT_MU = 0.0
"""The friction coefficient [-] used when none is given (Python API and CLI alike)."""

IMPULSE_RATIO = 0
COULOMB = 1
MINDLIN = 2
PARTIAL_SLIP = 3
PARTIAL_SLIP_CELLS = 16
"""Default number of cells of the ``partial_slip`` model over the largest contact radius (the
``partial_slip_cells`` option of ``simulate``, ``simulate_batch`` and sweeps). Elastic spheres:
max |e_t - exact| 2.7e-3 near normal incidence (psi1 < 0.2, where a slip annulus thinner than a
cell is not resolved and the error falls more slowly than N^-2), 8e-4 from psi1 = 0.2 on
(falling like N^-2); see the module docstring."""
PARTIAL_SLIP_CELLS_MIN = 4
"""Fewest ``partial_slip_cells`` allowed (4 cells: |e_t - exact| 3.6e-3 at psi1 = 1.4)."""
PARTIAL_SLIP_CELLS_MAX = 64
"""Most ``partial_slip_cells`` allowed: 64 cells bring the error in e_t at psi1 = 0.05 (nu =
0.45) from 2.7e-3 (16 cells) to 1.7e-4 and cost 4 to 5 times as much per impact (a rigid
rod's batch on one core: 0.28 ms at 16, 0.65 ms at 32, 1.5 ms at 64); the flexible rod's drop
keeps its compiled 16 cells per end."""


class FrictionKind(enum.StrEnum):
    """The friction models, each member carrying its compiled id and its sources."""

    IMPULSE_RATIO = ("impulse_ratio", IMPULSE_RATIO, (PAPER,))
    COULOMB = ("coulomb", COULOMB, ("stronge-2000",))
    MINDLIN = (
        "mindlin",
        MINDLIN,
        (
            "mindlin-deresiewicz-1953",
            "di-renzo-di-maio-2004",
            "thornton-cummins-cleary-2011",
            "thornton-cummins-cleary-2013",
            "maw-barber-fawcett-1976",
        ),
    )
    PARTIAL_SLIP = (
        "partial_slip",
        PARTIAL_SLIP,
        (
            "mindlin-1949",
            "mindlin-deresiewicz-1953",
            "popov-hess-2014",
            "maw-barber-fawcett-1976",
            "thornton-cummins-cleary-2013",
        ),
    )

    friction_id: int
    reference_keys: tuple[str, ...]

    def __new__(cls, value: str, friction_id: int, keys: tuple[str, ...]) -> FrictionKind:
        member = str.__new__(cls, value)
        member._value_ = value
        member.friction_id = friction_id
        member.reference_keys = keys
        return member

    @property
    def references(self) -> tuple[Reference, ...]:
        """The sources of this model (``impactlab.references``)."""
        return cite(*self.reference_keys)


@dataclass(frozen=True)
class FrictionModel:
    """A registered friction model: name, compiled id, description, reference text and the
    cited sources (``references``)."""

    name: str
    friction_id: int
    description: str
    reference: str
    kind: FrictionKind

    @property
    def references(self) -> tuple[Reference, ...]:
        """The sources of this model (``impactlab.references``)."""
        return self.kind.references


def _model(kind: FrictionKind, description: str) -> FrictionModel:
    text = "; ".join(str(r) for r in kind.references)
    return FrictionModel(str(kind), kind.friction_id, description, text, kind)


FRICTION_MODELS: dict[FrictionKind, FrictionModel] = {
    m.kind: m
    for m in (
        _model(
            FrictionKind.IMPULSE_RATIO,
            "F_t = mu F_n against the initial slip direction, constant (paper Eq. 7)",
        ),
        _model(
            FrictionKind.COULOMB,
            "exact Coulomb stick/slip of the rigid contact point, transitions as events",
        ),
        _model(
            FrictionKind.MINDLIN,
            "Mindlin-type tangential compliance k_t = 8 G* a, capped by mu F_n",
        ),
        _model(
            FrictionKind.PARTIAL_SLIP,
            "Mindlin-Deresiewicz partial slip with load history (microslip, exact MDR form in "
            f"{PARTIAL_SLIP_CELLS} cells)",
        ),
    )
}

FRICTION_IDS: dict[str, int] = {
    str(kind): m.friction_id for kind, m in FRICTION_MODELS.items() if kind != "partial_slip"
}
"""name -> compiled id of the rigid-body core's models (``impactlab.dynamics.core``).
``partial_slip`` (id ``PARTIAL_SLIP``) has its own engine (``impactlab.dynamics.slipcore``)."""

BATCH_FRICTION_IDS: dict[str, int] = {
    str(kind): m.friction_id for kind, m in FRICTION_MODELS.items()
}
"""name -> compiled id of every model the batch engine (``run_arrays``, ``simulate_batch``,
sweeps) runs: the core's ``FRICTION_IDS`` and ``partial_slip``."""


def friction_names() -> tuple[str, ...]:
    """Names of the friction models."""
    return tuple(str(kind) for kind in FRICTION_MODELS)


def get_friction(name: str | FrictionKind) -> FrictionModel:
    """The friction model called ``name``; ValueError listing the known names otherwise."""
    try:
        return FRICTION_MODELS[name]  # type: ignore[index]
    except (KeyError, TypeError):
        raise ValueError(
            f"unknown friction model {name!r}{did_you_mean(name, map(str, FRICTION_MODELS))}; "
            f"known models: {', '.join(FRICTION_MODELS)}"
        ) from None


__all__ = [
    "BATCH_FRICTION_IDS",
    "COULOMB",
    "DEFAULT_MU",
    "FRICTION_IDS",
    "FRICTION_MODELS",
    "IMPULSE_RATIO",
    "MINDLIN",
    "PARTIAL_SLIP",
    "PARTIAL_SLIP_CELLS",
    "PARTIAL_SLIP_CELLS_MAX",
    "PARTIAL_SLIP_CELLS_MIN",
    "FrictionKind",
    "FrictionModel",
    "friction_names",
    "get_friction",
]
