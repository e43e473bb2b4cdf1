"""What the flexible-rod integrator needs of a body: its rigid limit, inertia and modal data."""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import cast

import numpy as np

from impactlab.bodies import Rod
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.bodies.modal import MODAL_REFERENCES
from impactlab.references import Reference

__all__ = ["BodyModel", "body_model"]


@dataclass(frozen=True, eq=False)
class BodyModel:
    """What the integrator needs of a body: geometry, inertia, material and the modal data."""

    rigid: Rod
    inertia: float
    omega: np.ndarray
    zeta: np.ndarray
    U: np.ndarray
    W: np.ndarray
    Psi: np.ndarray
    geometric: tuple[np.ndarray, np.ndarray, np.ndarray] | None
    description: str
    references: tuple[Reference, ...]


@functools.lru_cache(maxsize=64)
def body_model(body: FlexibleRod | Rod) -> BodyModel:
    """The integrator's view of ``body`` (a rigid ``Rod``: no modes), cached per body."""
    if isinstance(body, Rod):
        empty = np.zeros((2, 0))
        desc = f"rigid Rod (L = {body.length:g} m, I_C = {body.inertia:.5g} kg m^2)"
        inertia = cast(float, body.inertia)  # a float after Rod.__post_init__
        return BodyModel(
            body, inertia, np.zeros(0), np.zeros(0), empty, empty, empty, None, desc, ()
        )
    b = body.basis()
    desc = (
        f"FlexibleRod ({body.theory}, {body.n_axial} axial"
        f"{' + 2 residual' if body.axial_residual else ''}, {body.n_bending} bending modes"
        f"{', geometric stiffness' if body.geometric else ''}, zeta = {body.damping:g})"
    )
    return BodyModel(
        body.rigid(),
        b.inertia,
        b.omega,
        np.full(b.n_modes, body.damping),
        b.U,
        b.W,
        b.Psi,
        body.geometric_tensor() if body.geometric else None,
        desc,
        MODAL_REFERENCES if b.n_modes else (),
    )
