"""Energy balances shared by the tests of the flexible drop's energy check."""

from __future__ import annotations

#: A closed balance after the last contact [J]: 1 J in, 0.25 J lost to the contact, 0.05 J in
#: vibration, 0.7 J of rigid kinetic energy left.
CLOSED = {
    "rigid_kinetic_energy": 0.7,
    "vibration_energy": 0.05,
    "potential_energy": 0.0,
    "work_normal": -0.25,
    "work_friction": 0.0,
    "work_damping": 0.0,
    "energy_error": 1e-9,
}
