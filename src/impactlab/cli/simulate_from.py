"""``impactlab simulate --from result.json``: a recorded impact or drop run again, with the
options of the command line on top of its recorded input.

The rule (``FROM_RULE``, said in ``--help`` and docs/tutorials/simulate.md): the recorded input
is the default of every option; the options of the impact override it (the kinematics, mu, the
law, the friction model, the flat, gravity, and ``--constant-angle`` for a rigid impact or
``--rate`` for a drop); the options that make the body (the body argument, its material, sizes,
inertia, modes and damping, ``--flexible`` or ``--rigid``) and ``--config`` are refused, since
the body is the recorded one. ``--vx`` or ``--vy`` replaces that component of the recorded velocity,
``--speed`` with ``--incidence`` replaces the velocity; a new ``--law`` drops the recorded law
parameters (they are the recorded law's).
"""

from __future__ import annotations

import json
import warnings
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import Any

from impactlab._validation import read_text_file
from impactlab.cli._common import (
    UserError,
    angle_quantity,
    as_option,
    check_rate_flat,
    check_rate_law,
    positive,
    quantity,
    rate_name,
    velocity_input,
)
from impactlab.dynamics import ImpactResult
from impactlab.dynamics.drop_checks import DropError
from impactlab.dynamics.drop_result import DropResult
from impactlab.materials import get_material

__all__ = [
    "FROM_BODY_OPTIONS",
    "FROM_RULE",
    "from_changes",
    "load_record",
    "option_error",
    "run_from",
]

#: What ``--from`` takes beside it, in one sentence (``--help``, the docs).
FROM_RULE = (
    "Simulate again the impact or drop recorded in a result's JSON (--json output of simulate "
    "or drop, or impact_result.json: its 'input'); the recorded input is the default of every "
    "option: the kinematics (--angle, --vx or --vy replace that component, --speed with "
    "--incidence the velocity), --spin, --mu, --law (a new law drops the recorded law "
    "parameters), --friction, --flat, --gravity/--no-gravity, --rtol, --constant-angle/"
    "--no-constant-angle and --partial-slip-cells (rigid impact), and --rate, --stop and "
    "--time-limit (drop) override it; the body's options "
    "(body, --material, sizes, --inertia, modes, --damping, --flexible/--rigid) and --config "
    "are refused: the body is the recorded one."
)

#: Options (keys of ``impactlab simulate``, and ``drop``'s ``rigid``) that make the body:
#: refused with ``--from``.
FROM_BODY_OPTIONS = (
    "body",
    "rigid",
    "material",
    "radius",
    "length",
    "mass",
    "diameter",
    "inertia",
    "flexible",
    "modes_axial",
    "modes_bending",
    "damping",
)


def load_record(path: Path) -> dict[str, Any]:
    """The JSON object in ``path``; UserError when it cannot be read, is not UTF-8 text or
    holds no object."""
    try:
        record = json.loads(read_text_file(path, "JSON", f"--from {str(path)!r}"))
    except OSError as exc:
        raise UserError(f"--from: cannot read {str(path)!r}: {exc.strerror}") from None
    except json.JSONDecodeError as exc:
        why = f"{exc.msg}, line {exc.lineno}"
        raise UserError(f"--from: {str(path)!r} is not JSON ({why})") from None
    except ValueError as exc:  # not UTF-8 text
        raise UserError(str(exc)) from None
    if not isinstance(record, dict):
        raise UserError(f"--from: {str(path)!r} holds no result (a JSON object is needed)")
    return record


def _recorded(record: Mapping[str, Any], path: Path) -> tuple[str, dict[str, Any]]:
    """(the recorded function, its arguments) of ``record``; UserError when it is not one. The
    version's warning is left to the rerun (said once)."""
    from impactlab.dynamics.provenance import RecordVersionWarning, from_record, record_function

    try:
        function = record_function(record)
        _check_recorded_keys(record)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RecordVersionWarning)
            return function, from_record(record)
    except (ValueError, TypeError) as exc:
        raise UserError(f"--from {str(path)!r}: {exc}") from None


#: The keys every recorded impact has (``impactlab.dynamics.provenance.input_record``).
_RECORDED_KEYS = ("body", "flat", "law", "velocity")


def _check_recorded_keys(record: Mapping[str, Any]) -> None:
    """ValueError when ``record`` (or its ``input``) lacks a key of every recorded impact,
    naming what --from reads: the JSON output of ``impactlab simulate`` or ``impactlab drop``."""
    recorded = record.get("input")
    recorded = recorded if isinstance(recorded, Mapping) else record
    missing = [k for k in _RECORDED_KEYS if k not in recorded]
    if missing:
        raise ValueError(
            f"the file records no impact (no {', '.join(missing)}): give "
            "the output of 'impactlab simulate ... --json' or 'impactlab drop ... --json', or "
            "the 'input' of a result's to_dict()"
        )


def _velocity(given: Mapping[str, Any], recorded: Any, label: Callable[[str], str]) -> Any:
    """The velocity: the recorded (vx, vy) with the given component(s) replaced, or the one
    of --speed and --incidence (``velocity_input``'s rules and errors)."""
    vx, vy = (given.get(k) for k in ("vx", "vy"))
    speed, incidence = (given.get(k) for k in ("speed", "incidence"))
    if speed is not None or incidence is not None:
        return velocity_input(vx, vy, speed, incidence, label)
    old_vx, old_vy = recorded
    new_vx = old_vx if vx is None else quantity(vx, "m/s", label("vx"))
    new_vy = old_vy if vy is None else quantity(vy, "m/s", label("vy"))
    return (new_vx, new_vy)


def _label(key: str) -> str:
    return "--" + key.replace("_", "-")


def option_error(exc: ValueError, options: Iterable[str]) -> UserError:
    """The API's error ``exc`` for the command line: a keyword it names (``time_limit``,
    ``rtol``, its leading parameter) spelled as the option (``--time-limit``) where the
    command's ``options`` (its keys) have it (``DropError.worded``, ``_common.as_option``)."""
    if isinstance(exc, UserError):
        return exc
    keys = frozenset(options)

    def label(key: str) -> str:
        return _label(key) if key in keys else key

    if isinstance(exc, DropError):
        return UserError(exc.worded(label))
    return UserError(as_option(str(exc), keys, label))


def _refuse_body_options(given: Mapping[str, Any]) -> None:
    """UserError naming the given options that make the body (``FROM_BODY_OPTIONS``)."""
    switched = {("flexible", False): "--rigid", ("rigid", False): "--flexible"}
    body_options = [
        "the body" if k == "body" else switched.get((k, given[k]), _label(k))
        for k in FROM_BODY_OPTIONS
        if given.get(k) is not None
    ]
    if body_options:
        raise UserError(
            f"{', '.join(body_options)}: --from simulates the recorded body; leave "
            f"{'it' if len(body_options) == 1 else 'them'} out (or simulate a new body "
            "without --from)"
        )


def _kinematics(given: Mapping[str, Any], recorded: Mapping[str, Any]) -> dict[str, Any]:
    """The changed angle, velocity and spin."""
    changes: dict[str, Any] = {}
    if given.get("angle") is not None:
        if recorded.get("angle") is None:
            raise UserError(
                f"--angle: the recorded body is a {type(recorded['body']).__name__}, which has "
                "no angle to the flat; leave it out"
            )
        changes["angle"] = angle_quantity(given["angle"], "--angle")
    if any(given.get(k) is not None for k in ("vx", "vy", "speed", "incidence")):
        changes["velocity"] = _velocity(given, recorded["velocity"], _label)
    if given.get("spin") is not None:
        changes["spin"] = quantity(given["spin"], "rad/s", "--spin")
    return changes


def _options(given: Mapping[str, Any], drop: bool) -> dict[str, Any]:
    """The changed --constant-angle (a rigid impact), --rate or --stop (a drop)."""
    changes: dict[str, Any] = {}
    if given.get("constant_angle") is not None:  # --constant-angle or --no-constant-angle
        if drop:
            if given["constant_angle"]:
                raise UserError(
                    "--constant-angle: the recorded drop follows the rod's rotation (no frozen "
                    "lever arms); leave it out"
                )
        else:
            changes["constant_angle"] = bool(given["constant_angle"])
    if given.get("rate") is not None:
        if not drop:
            raise UserError(
                "--rate: the recorded impact is not a drop (only the drop has a rate-dependent "
                "flat); leave it out"
            )
        changes["rate"] = rate_name(str(given["rate"]))
    if given.get("stop") is not None:
        if not drop:
            raise UserError(
                "--stop: the recorded impact is not a drop (only a drop has another end's "
                "impacts to follow); leave it out"
            )
        changes["stop"] = str(given["stop"])
    if given.get("time_limit") is not None:  # impactlab drop --time-limit
        if not drop:
            raise UserError("--time-limit: the recorded impact is not a drop; leave it out")
        changes["time_limit"] = positive(given["time_limit"], "s", "--time-limit")
    return changes


def from_changes(
    given: Mapping[str, Any], function: str, recorded: Mapping[str, Any]
) -> dict[str, Any]:
    """The arguments that the command-line options ``given`` (keys of ``impactlab simulate``,
    None: not given) change in the ``recorded`` arguments of ``function`` (module docstring);
    UserError for an option the rule refuses."""
    from impactlab.dynamics.provenance import SIMULATE_DROP

    _refuse_body_options(given)
    changes = _kinematics(given, recorded)
    if given.get("mu") is not None:
        changes["mu"] = float(given["mu"])
    if given.get("law") is not None:
        changes["law"] = str(given["law"])
        if changes["law"] != recorded.get("law"):
            changes["law_params"] = None  # the recorded ones are the recorded law's
    if given.get("friction") is not None:
        changes["friction"] = str(given["friction"])
    if given.get("flat") is not None:
        try:
            changes["flat"] = get_material(given["flat"], "--flat")
        except ValueError as exc:
            raise UserError(str(exc)) from None
    if given.get("gravity") is not None:  # --gravity or --no-gravity
        changes["gravity"] = bool(given["gravity"])
    if given.get("rtol") is not None:  # impactlab drop --rtol
        changes["rtol"] = float(given["rtol"])
    cells = given.get("partial_slip_cells")
    if cells is not None and function == SIMULATE_DROP and cells != 16:
        raise UserError(
            f"--partial-slip-cells {cells}: the recorded drop has its compiled cells (16 per "
            "end); leave it out"
        )
    if cells is not None and function != SIMULATE_DROP:  # checked by simulate
        changes["partial_slip_cells"] = cells
    return changes | _options(given, function == SIMULATE_DROP)


def run_from(
    path: Path, given: Mapping[str, Any] | None = None, *, drop_only: bool = False
) -> ImpactResult | DropResult:
    """The impact or drop recorded in ``path`` (``impactlab simulate --json`` or ``impactlab
    drop --json`` output, an ``impact_result.json`` or a result's ``to_dict()``) simulated
    again, with the command-line options ``given`` on top (:func:`from_changes`);
    ``drop_only`` (``impactlab drop --from``): UserError for a record of a rigid impact."""
    from impactlab.dynamics import rerun  # lazy: a fast CLI start
    from impactlab.dynamics.provenance import SIMULATE, SIMULATE_DROP

    record = load_record(path)
    function, recorded = _recorded(record, path)
    flexible = type(recorded["body"]).__name__ == "FlexibleRod"
    if drop_only and function == SIMULATE and not flexible:
        raise UserError(
            f"--from {str(path)!r} records an impact of impactlab simulate, not a drop: run it "
            "with 'impactlab simulate --from'"
        )
    changes = from_changes(given or {}, function, recorded)
    if function == SIMULATE_DROP or flexible:
        changes.setdefault("history", False)  # a drop: the command prints no history
        rate = changes.get("rate", recorded.get("rate"))
        blame = "--rate" if "rate" in changes else "the recorded rate"
        check_rate_flat(rate, changes.get("flat", recorded["flat"]), blame)
        law_blame = "--law" if "law" in changes else "the recorded law"
        check_rate_law(rate, changes.get("law", recorded.get("law")), blame, law_blame)
    try:
        return rerun(record, **changes)
    except ValueError as exc:  # the keyword it names (time_limit) as the command's option
        raise UserError(f"--from {str(path)!r}: {option_error(exc, given or {})}") from None
    except TypeError as exc:
        raise UserError(f"--from {str(path)!r}: {exc}") from None
