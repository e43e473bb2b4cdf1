"""How far a tangentially compliant contact moves the inversion's T: the measured threshold of
mu/mu_c and its warning.

Eq. 12 assumes Coulomb friction on a rigid contact: the tip slides throughout. A real contact is
tangentially compliant (Mindlin): it sticks at first, while the tangential load builds up, and
again where the slip reverses, so the material point slides less than Eq. 12 says for the same
duration, and the inversion reads the scar as a longer contact (T too long, F too small). The
threshold below comes from impactlab's own simulations (docs/analytic.md, Sec. 7).
"""

from __future__ import annotations

import contextlib
import math
import re
import warnings
from collections.abc import Iterator

import numpy as np

from impactlab._validation import ImplausibleInputWarning, warn_implausible

__all__ = [
    "COMPLIANCE_ADVICE",
    "COMPLIANCE_ANGLES",
    "COMPLIANCE_LEVEL",
    "COMPLIANCE_SPEEDS",
    "COMPLIANCE_THRESHOLD",
    "check_compliance",
    "compliance_advice_hidden",
    "compliance_threshold",
]

#: The error of T [%] that draws the warning: twice the largest neglected effect the inversion
#: leaves unwarned (the constant angle, 4 % at 20 deg) and where the effect outgrows the
#: inversion's stated uncertainty (docs/analytic.md, Sec. 7).
COMPLIANCE_LEVEL = 10.0
#: The rod-to-flat angles [deg] of the measured table.
COMPLIANCE_ANGLES = (5.0, 10.0, 15.0, 20.0, 30.0, 45.0, 60.0, 75.0, 85.0)
#: The drop speeds |v_i| [m/s] of the measured table.
COMPLIANCE_SPEEDS = (0.5, 1.41, 4.0)
#: mu/mu_c at which the inverted T [s] of a simulated impact (the paper's rod, ghaednia law,
#: constant angle, no gravity, inverted with the contact's mu) first comes out
#: ``COMPLIANCE_LEVEL`` % too long, by speed (rows, ``COMPLIANCE_SPEEDS``) and angle (columns,
#: ``COMPLIANCE_ANGLES``): the least over friction "mindlin" and "partial_slip" and the flats
#: aisi-1010 and aisi-201 (docs/analytic.md, Sec. 7).
COMPLIANCE_THRESHOLD = (
    (0.208, 0.221, 0.240, 0.263, 0.312, 0.384, 0.437, 0.471, 0.483),
    (0.224, 0.239, 0.259, 0.282, 0.332, 0.411, 0.466, 0.505, 0.513),
    (0.244, 0.259, 0.280, 0.305, 0.358, 0.439, 0.505, 0.536, 0.547),
)


def compliance_threshold(angle: float, speed: float) -> float:
    """The mu/mu_c of ``COMPLIANCE_THRESHOLD`` at ``angle`` [rad] and ``speed`` = |v_i| [m/s]:
    linear in the angle and in log(speed) between the measured points, the nearest edge's
    value outside them."""
    deg = math.degrees(angle)
    by_speed = [float(np.interp(deg, COMPLIANCE_ANGLES, row)) for row in COMPLIANCE_THRESHOLD]
    logs = np.log(COMPLIANCE_SPEEDS)
    return float(np.interp(math.log(max(speed, 1e-12)), logs, by_speed))


def check_compliance(mu: float, mu_c: float, angle: float, speed: float) -> None:
    """ImplausibleInputWarning (advice: it does not make the result doubtful) where mu/mu_c
    reaches ``compliance_threshold``: on a tangentially compliant contact the inverted T would be
    ``COMPLIANCE_LEVEL`` % or more too long (F too small). ``mu``, ``mu_c`` at ``angle`` [rad],
    ``speed`` = |v_i| [m/s]."""
    if not mu_c > 0:
        return
    limit = compliance_threshold(angle, speed)
    ratio = mu / mu_c
    if ratio < limit:
        return
    warn_implausible(
        f"mu = {mu:.4g} is {ratio:.3g} mu_c (mu_c = {mu_c:.4g} at {math.degrees(angle):.4g} "
        f"deg): {COMPLIANCE_ADVICE} sticks at "
        "first and where its slip reverses, which Eq. 12 (Coulomb friction on a rigid contact, "
        "the tip sliding throughout) does not describe; on impactlab's simulations of such "
        f"contacts T comes out {COMPLIANCE_LEVEL:g} % or more too long, and F too small, from "
        f"mu/mu_c = {limit:.3g} at this angle and |v_i| = {speed:.3g} m/s, more towards mu_c "
        "(less with mu from Eq. 28, the impulse ratio, than with the contact's Coulomb "
        "coefficient); see docs/analytic.md, Sec. 7"
    )


#: The words of ``check_compliance``'s advice that a filter names (``compliance_advice_hidden``).
COMPLIANCE_ADVICE = "a tangentially compliant contact (Mindlin's; every real contact is)"


@contextlib.contextmanager
def compliance_advice_hidden() -> Iterator[None]:
    """Within: ``check_compliance``'s advice is not shown (an inversion's result still lists
    it in ``warnings``); for inversions of hypothetical inputs, such as a curve over e."""
    with warnings.catch_warnings():
        warnings.filterwarnings(
            "ignore", message=".*" + re.escape(COMPLIANCE_ADVICE), category=ImplausibleInputWarning
        )
        yield
