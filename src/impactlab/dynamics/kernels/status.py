"""Status codes of every compiled engine (the rigid impact, the partial-slip impact and the
flexible-rod drop: one table, one meaning per code; an engine returns one, never an exception)
and friction regime codes (the ``regime`` output)."""

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
# the flexible-rod drop's own failures (``dynamics.flexcore``; ``ST_INACCURATE`` is set by
# ``simulate_drop`` after the run)
ST_TMAX = 11
ST_TOO_MANY_CONTACTS = 12
ST_MAX_STEPS = 13
ST_MISSED_CONTACT = 14
ST_INACCURATE = 15

STATUS_MESSAGES: dict[int, str] = {
    ST_OK: "ok",
    ST_LAW_LIMIT: "the interference exceeded the contact law's largest valid interference",
    ST_NOT_APPROACHING: "the contact point does not approach the flat (normal velocity >= 0)",
    ST_NO_SEPARATION: "no separation within the step limit",
    ST_BAD_INPUT: "invalid input: a body, law, initial-state, mu or tolerance value is not finite "
    "or out of range (mu in [0, 1e3], speeds up to 1e4 m/s, gravity in [0, 1e7] m/s^2, rtol in "
    "[1e-13, 1e-3])",
    ST_NAN: "the contact law returned a non-finite value (law not available or outside its domain)",
    ST_STEP_UNDERFLOW: "step-size underflow: the integrator could not meet the tolerance",
    ST_BAD_ANGLE: "angle outside (0, pi/2] radians",
    ST_RADIUS_MISMATCH: "the law's radius P_R differs from the body's tip radius",
    ST_TOO_MANY_EVENTS: "too many phase or stick/slip switches (chattering)",
    ST_BAD_FRICTION: "unknown friction id, or the Mindlin model without G* in the body vector",
    ST_TMAX: "time_limit reached before the rod left the flat for good",
    ST_TOO_MANY_CONTACTS: "too many contacts or dents",
    ST_MAX_STEPS: "step limit reached",
    ST_MISSED_CONTACT: "missed contact: an end lay below its dent's surface (or the flat) with "
    "zero force, beyond the contact invariant's tolerance max(1e-6, rtol) delta*",
    ST_INACCURATE: "integration not accurate to the tolerance",
}

#: Friction regime codes (the ``regime`` output) and their names, in code order.
REGIME_NAMES: dict[int, str] = dict(enumerate(("frictionless", "slip", "stick", "reversal")))
REGIME_FRICTIONLESS, REGIME_SLIP, REGIME_STICK, REGIME_REVERSAL = REGIME_NAMES
