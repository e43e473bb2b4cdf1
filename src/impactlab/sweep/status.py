"""Status codes the sweep itself assigns: cases the engine never sees (rejected inputs) and
cases not computed yet. The engine's own codes are small non-negative integers
(``impactlab.dynamics.kernels.status``); these are kept apart."""

from __future__ import annotations

import enum


class SweepStatus(enum.IntEnum):
    """A sweep status code with the sentence that explains it (``.message``)."""

    message: str

    def __new__(cls, code: int, message: str) -> SweepStatus:
        member = int.__new__(cls, code)
        member._value_ = code
        member.message = message
        return member

    NOT_RUN = (-1, "not computed (chunk missing: the sweep was interrupted)")
    BAD_MATERIAL = (
        101,
        "material rejected (impactlab.materials.Material: e.g. nu outside (-1, 0.5), S_y >= E, "
        "non-positive value)",
    )
    BAD_BODY = (
        102,
        "body rejected (impactlab.bodies: a non-positive length, radius, mass or inertia; a tip "
        "radius above half the length; a diameter wider than twice the tip radius, or mass and "
        "diameter more than 2 % off the density; both mass and density given)",
    )
    BAD_LAW = (103, "contact law rejected its parameters (outside the law's validity)")
    BAD_INPUT = (104, "non-finite kinematic input (angle, vx, vy, spin or mu)")


STATUS_NOT_RUN = int(SweepStatus.NOT_RUN)
STATUS_BAD_MATERIAL = int(SweepStatus.BAD_MATERIAL)
STATUS_BAD_BODY = int(SweepStatus.BAD_BODY)
STATUS_BAD_LAW = int(SweepStatus.BAD_LAW)
STATUS_BAD_INPUT = int(SweepStatus.BAD_INPUT)

#: code -> message of every sweep status code.
SWEEP_STATUS_MESSAGES: dict[int, str] = {int(s): s.message for s in SweepStatus}
