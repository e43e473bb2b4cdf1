"""Tangential (friction) models of the impact engine: names, compiled ids and references.

The equations are in ``docs/engine/index.md``; the compiled implementation is in
``impactlab.dynamics.engine``. A name never stands in for another model.

- ``impulse_ratio``: the paper's Eq. 7 (doi:10.1007/s00419-015-1108-2): F_t = mu F_n against the
  initial slip direction of the contact point, constant over the impact. When the initial
  tangential velocity of the contact point is zero, against the slip that the normal force alone
  starts (sign of -a b for the rod); no tangential force when neither gives a direction.
- ``coulomb``: exact Coulomb stick/slip for a rigid contact point: slip F_t = -mu F_n sign(v_slip);
  stick (v_slip = 0) while the force the constraint needs, computed from the rigid-body equations,
  satisfies |F_t*| <= mu F_n. Transitions are located as events (no regularisation).
  Reference: W. J. Stronge, Impact Mechanics (2000), Ch. 5, doi:10.1017/CBO9780511626432.
- ``mindlin``: tangential compliance of Mindlin type with stiffness k_t = 8 G* a following the
  contact radius a, an elastic tangential state, capped by Coulomb mu F_n (gross slip on the cap).
  Incremental (no-slip) loading dF_t = -k_t dxi; on unloading the force is scaled with k_t
  (constant elastic displacement), the Mindlin-Deresiewicz-type scheme of Di Renzo & Di Maio
  (2004) doi:10.1016/j.ces.2003.09.037 and Thornton, Cummins & Cleary (2011, Powder Technol.
  210, 189); theory: Mindlin & Deresiewicz, J. Appl. Mech. 20 (1953) 327; oblique impact
  behaviour: Maw, Barber & Fawcett, Wear 38 (1976) 101, doi:10.1016/0043-1648(76)90063-6.
"""

from __future__ import annotations

from dataclasses import dataclass

IMPULSE_RATIO = 0
COULOMB = 1
MINDLIN = 2


@dataclass(frozen=True)
class FrictionModel:
    """A registered friction model: name, compiled id, one-line description and reference."""

    name: str
    friction_id: int
    description: str
    reference: str


FRICTION_MODELS: dict[str, FrictionModel] = {
    m.name: m
    for m in (
        FrictionModel(
            "impulse_ratio", IMPULSE_RATIO,
            "F_t = mu F_n against the initial slip direction, constant (paper Eq. 7)",
            "Ghaednia et al., Arch. Appl. Mech. (2015), doi:10.1007/s00419-015-1108-2",
        ),
        FrictionModel(
            "coulomb", COULOMB,
            "exact Coulomb stick/slip of the rigid contact point, transitions as events",
            "Stronge, Impact Mechanics (2000), doi:10.1017/CBO9780511626432",
        ),
        FrictionModel(
            "mindlin", MINDLIN,
            "Mindlin-type tangential compliance k_t = 8 G* a, capped by mu F_n",
            "Mindlin & Deresiewicz (1953); Di Renzo & Di Maio (2004), "
            "doi:10.1016/j.ces.2003.09.037; Maw, Barber & Fawcett (1976), "
            "doi:10.1016/0043-1648(76)90063-6",
        ),
    )
}

#: name -> compiled id
FRICTION_IDS: dict[str, int] = {name: m.friction_id for name, m in FRICTION_MODELS.items()}


def friction_names() -> tuple[str, ...]:
    """Names of the friction models."""
    return tuple(FRICTION_MODELS)


def get_friction(name: str) -> FrictionModel:
    """The friction model called ``name``; ValueError listing the known names otherwise."""
    try:
        return FRICTION_MODELS[name]
    except (KeyError, TypeError):
        raise ValueError(
            f"unknown friction model {name!r}; known models: {', '.join(FRICTION_MODELS)}"
        ) from None


def friction_id(name: str) -> int:
    """Compiled id of the friction model ``name`` (ValueError for unknown names)."""
    return get_friction(name).friction_id
