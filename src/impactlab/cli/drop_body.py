"""The rod of ``impactlab drop`` and ``impactlab simulate --flexible`` from their options:
the paper's sizes unless given, flexible (mode counts, damping) or rigid (its inertia), with
errors named by the option."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any, cast

from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod
from impactlab.bodies.flexible_rod import (
    AXIAL_CUTOFF_HZ,
    BENDING_CUTOFF_HZ,
    DEFAULT_N_AXIAL,
    DEFAULT_N_BENDING,
    check_mode_count,
)
from impactlab.cli._common import UserError, as_option
from impactlab.materials import Material

__all__ = ["MODES_ALIASES", "MODES_HELP", "drop_body", "flexible_rod", "paper_mass"]


#: The help of the mode counts (``impactlab simulate --flexible`` too), naming their other
#: spelling, FlexibleRod's keyword (``n_axial``: ``--n-axial``, a --config file's key too).
MODES_HELP = {
    "modes_axial": "Axial modes, n_axial (default: the fewest that reach "
    f"{AXIAL_CUTOFF_HZ / 1e3:g} kHz, at least {DEFAULT_N_AXIAL}; + 2 residual).",
    "modes_bending": "Bending modes, n_bending (default: the fewest that reach "
    f"{BENDING_CUTOFF_HZ / 1e3:g} kHz, at least {DEFAULT_N_BENDING}).",
}
#: The other spelling of each mode count's option (FlexibleRod's keyword).
MODES_ALIASES = {"modes_axial": ("--n-axial",), "modes_bending": ("--n-bending",)}


def _count(value: Any, name: str) -> int | None:
    """A mode count (an option or a config file's value): an integer in [0, MAX_MODES], else
    UserError naming ``name``; None (not given): FlexibleRod's default, by frequency."""
    if value is None:
        return None
    count = value
    if isinstance(value, str):  # a config file's integer text, "16", as the number
        try:
            count = int(value.strip())
        except ValueError:
            count = None
    if isinstance(count, bool) or not isinstance(count, int):  # 2.5, "x" or true in a file
        raise UserError(f"{name} must be an integer >= 0, got {value!r}")
    try:
        return check_mode_count(name, count)
    except ValueError as exc:
        raise UserError(str(exc)) from None


def _ratio(value: Any, name: str) -> float:
    """A damping ratio (an option or a config file's value): a number or numeric text, else
    UserError naming ``name`` (its range is FlexibleRod's to check)."""
    if value is None:
        return 0.0
    try:
        if isinstance(value, bool) or not isinstance(value, int | float | str):
            raise TypeError(value)
        return float(value)
    except (TypeError, ValueError):
        raise UserError(f"{name} must be a number in [0, 1), got {value!r}") from None


def flexible_rod(
    values: Mapping[str, Any],
    sizes: Mapping[str, float | None],
    material: Material,
    label: Any = None,
) -> FlexibleRod:
    """A FlexibleRod of the given ``sizes`` (length, tip_radius, and mass and/or diameter) and
    ``material`` with the mode counts and damping of ``values`` (``modes_axial``,
    ``modes_bending``, ``damping``; None: the defaults, the mode counts by frequency and the
    axial residual pseudo-modes with any axial mode). ``label(key)`` spells an option in
    errors."""
    name = label or (lambda key: "--" + key.replace("_", "-"))
    n_axial = _count(values.get("modes_axial"), name("modes_axial"))
    n_bending = _count(values.get("modes_bending"), name("modes_bending"))
    damping = _ratio(values.get("damping"), name("damping"))
    try:
        return FlexibleRod(
            length=cast(float, sizes["length"]),
            tip_radius=cast(float, sizes["tip_radius"]),
            mass=sizes.get("mass"),
            diameter=sizes.get("diameter"),
            material=material,
            n_axial=n_axial,
            n_bending=n_bending,
            damping=damping,
        )
    except ValueError as exc:  # "damping must lie in [0.0, 1.0)": the option's spelling
        option = {"tip_radius": "radius", "n_axial": "modes_axial", "n_bending": "modes_bending"}
        keys = ("length", "mass", "diameter", "damping", *option)
        raise UserError(as_option(str(exc), keys, lambda k: name(option.get(k, k)))) from None


def paper_mass(
    length_given: bool,
    mass: float | None,
    diameter: float | None,
    material: Material,
    label: Callable[..., str] | None = None,
    radius_given: bool = False,
) -> float | None:
    """The rod's mass [kg]: ``mass`` as given; None when only the ``diameter`` [m] is given (the
    mass follows from it); the paper's rod's mass when neither is, for the paper's rod only.
    UserError, naming ``label('mass', like)`` and ``label('diameter', like)``, for a rod of
    another ``material``, or a given length or tip radius, without either: the paper's mass
    would be silently wrong (a thinner tip under the paper's 0.46 kg: a rod wider than its tip,
    whose rim strikes first; ``like``: the option that made the rod another, for a config
    file's spelling)."""
    if mass is not None or diameter is not None:
        return mass
    if material == PAPER_ROD.material and not length_given and not radius_given:
        return PAPER_ROD.mass
    name = label or _option
    like = "length" if length_given else "radius" if radius_given else "material"
    raise UserError(
        f"{name('mass', like)} or {name('diameter', like)}: give one (or both) for a rod other "
        "than the paper's (its mass follows from the diameter, the length and the material's "
        "density)"
    )


def drop_body(
    rigid: bool,
    modes: Mapping[str, Any],
    sizes: Mapping[str, float | None],
    material: Material,
    inertia: float | None = None,
    label: Callable[..., str] | None = None,
) -> FlexibleRod | Rod:
    """The rod: the paper's sizes unless given (``sizes``: length, tip_radius, mass, diameter;
    None: not given), flexible with the given mode counts and damping, or rigid (with its
    moment of inertia ``inertia`` about the centre of mass, kg m^2; None: from its size).
    ``label(key, like)`` spells an option in errors (``--mass``, or ``mass (in case.toml)``
    for a config file's key; a key not given where the key ``like`` was; default ``--key``)."""
    name = label or _option
    length = sizes["length"] if sizes["length"] is not None else PAPER_ROD.length
    tip = sizes["tip_radius"] if sizes["tip_radius"] is not None else PAPER_ROD.tip_radius
    diameter = sizes["diameter"]
    mass = paper_mass(
        sizes["length"] is not None,
        sizes["mass"],
        diameter,
        material,
        name,
        sizes["tip_radius"] is not None and sizes["tip_radius"] != PAPER_ROD.tip_radius,
    )
    if rigid:
        given = [name(k) for k, v in modes.items() if v is not None]
        if given:
            raise UserError(
                f"{', '.join(given)}: a rigid rod has no modes; leave out {name('rigid')}"
            )
        try:
            return Rod(length=length, tip_radius=tip, mass=mass, material=material,  # type: ignore[arg-type]
                       diameter=diameter, inertia=inertia)  # fmt: skip
        except ValueError as exc:  # the Rod's words, named by the option that set the value
            rod_name = {"tip_radius": "radius"}
            words = as_option(str(exc), _ROD_KEYS, lambda k: name(rod_name.get(k, k)))
            raise UserError(words) from None
    if inertia is not None:
        raise UserError(
            f"{name('inertia')}: the flexible rod's inertia follows from its size and material; "
            f"give {name('rigid', 'inertia')} for a rigid rod of another inertia"
        )
    sizes_in = {"length": length, "tip_radius": tip, "mass": mass, "diameter": diameter}
    return flexible_rod(modes, sizes_in, material, name)


#: The rigid Rod's keywords that ``drop`` sets from an option of another spelling.
_ROD_KEYS = ("length", "tip_radius", "mass", "diameter", "inertia")


def _option(key: str, like: str | None = None) -> str:
    return "--" + key.replace("_", "-")
