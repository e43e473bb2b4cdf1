"""Status codes of one impact (``impact`` returns one; never an exception) and friction
regime codes (the ``regime`` output)."""

from __future__ import annotations

ST_OK = 0
ST_LAW_LIMIT = 1
ST_NOT_APPROACHING = 2
ST_NO_SEPARATION = 3
ST_BAD_INPUT = 4
ST_NAN = 5
ST_STEP_UNDERFLOW = 6
ST_BAD_ANGLE = 7
ST_RADIUS_MISMATCH = 8
ST_TOO_MANY_EVENTS = 9
ST_BAD_FRICTION = 10

STATUS_MESSAGES: dict[int, str] = {
    ST_OK: "ok",
    ST_LAW_LIMIT: "the interference exceeded the contact law's validity range (delta > P_DLIM)",
    ST_NOT_APPROACHING: "the contact point does not approach the flat (normal velocity >= 0)",
    ST_NO_SEPARATION: "no separation within the step limit",
    ST_BAD_INPUT: "invalid input: a body, law, initial-state, mu or tolerance value is not finite "
    "or out of range",
    ST_NAN: "the contact law returned a non-finite value (law not available or outside its domain)",
    ST_STEP_UNDERFLOW: "step-size underflow: the integrator could not meet the tolerance",
    ST_BAD_ANGLE: "angle outside (0, pi/2] radians",
    ST_RADIUS_MISMATCH: "the law's radius P_R differs from the body's tip radius",
    ST_TOO_MANY_EVENTS: "too many phase or stick/slip switches (chattering)",
    ST_BAD_FRICTION: "unknown friction id, or the Mindlin model without G* in the body vector",
}

#: Friction regime codes (the ``regime`` output) and their names, in code order.
REGIME_NAMES: dict[int, str] = dict(enumerate(("frictionless", "slip", "stick", "reversal")))
REGIME_FRICTIONLESS, REGIME_SLIP, REGIME_STICK, REGIME_REVERSAL = REGIME_NAMES
