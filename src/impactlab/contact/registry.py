"""The explicit registry of contact laws, keyed by name (a :class:`Law` or a plain string).

The built-in laws are keyed by :class:`Law`; a user's law (``register_law``: the tabulated law
of the user's tables or callables, ``contact.registered``) by its own name. No name ever stands
in for another law: a built-in name cannot be registered, and a registered name keeps its data
for the life of the process (registering it again with the same data does nothing; with other
data it is refused), so nothing built from it ever goes stale.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from typing import Any

from impactlab._validation import check_positive, did_you_mean
from impactlab.contact.base import ContactLaw
from impactlab.contact.brake import Brake
from impactlab.contact.ghaednia import Ghaednia
from impactlab.contact.hertz import Hertz
from impactlab.contact.indentation_data import IndentationCurves
from impactlab.contact.jackson_green import JacksonGreen
from impactlab.contact.kogut_komvopoulos import KogutKomvopoulos
from impactlab.contact.names import Law
from impactlab.contact.ranges import alias_range
from impactlab.contact.registered import (
    DEFAULT_POINTS,
    DEFAULT_TOLERANCE,
    RegisteredLaw,
    check_law_name,
    law_from_record,
    sample_law,
)
from impactlab.contact.tabulated import Tabulated
from impactlab.contact.thornton import Thornton
from impactlab.materials import ContactPair
from impactlab.schema import warn_renamed

_LAWS: dict[str, ContactLaw] = {
    law.law: law
    for law in (
        Hertz(),
        Ghaednia(),
        JacksonGreen(),
        KogutKomvopoulos(),
        Brake(),
        Thornton(),
        Tabulated(),
    )
}
#: The user's laws now registered, by name.
_USER: dict[str, RegisteredLaw] = {}
#: Every name registered in this process -> the fingerprint of its data (kept after
#: ``unregister_law``: a name never changes its meaning within a process).
_TAKEN: dict[str, str] = {}


def law_names() -> tuple[str, ...]:
    """Names of the registered laws: the built-in ones in registration order, then the user's
    (``register_law``)."""
    return tuple(str(law) for law in _LAWS) + tuple(_USER)


def builtin_law_names() -> tuple[str, ...]:
    """Names of the laws that ship with impactlab (:class:`Law`)."""
    return tuple(str(law) for law in _LAWS)


def get_law(name: str | Law) -> ContactLaw:
    """The law registered under ``name`` (a :class:`Law` or its string value, or a user law's
    name); ValueError listing the known names otherwise."""
    try:
        return _LAWS[name]
    except (KeyError, TypeError):
        pass
    try:
        return _USER[name]  # type: ignore[index]
    except (KeyError, TypeError):
        raise ValueError(
            f"unknown contact law {name!r}{did_you_mean(name, law_names())}; known laws: "
            f"{', '.join(law_names())} (a law of "
            f"one's own: impactlab.contact.register_law, or `impactlab --law-file FILE`)"
        ) from None


def _check_twin(name: str) -> None:
    """ValueError where a registered user law's name reads as ``name`` with '_' for '-' (or
    '-' for '_'): two such names would read as one law (built-in names: ``check_law_name``)."""
    key = name.replace("_", "-")
    twin = next((n for n in _USER if n != name and n.replace("_", "-") == key), None)
    if twin is not None:
        raise ValueError(
            f"law name {name!r} reads as the registered law {twin!r} ('_' for '-') and cannot be "
            f"registered: choose another name (or use {twin!r}, to mean that law)"
        )


def add_law(law: RegisteredLaw) -> RegisteredLaw:
    """Register the built law ``law`` under its name (see ``register_law``); returns the law
    registered under that name (the one given, or the equal one already there)."""
    if not isinstance(law, RegisteredLaw):
        raise ValueError(f"law must be a RegisteredLaw, got {type(law).__name__}")
    name = law.name
    if name in _LAWS:
        raise ValueError(
            f"law name {name!r} is a built-in law's and cannot be registered again; "
            f"built-in: {', '.join(builtin_law_names())}"
        )
    _check_twin(name)
    fingerprint = law.fingerprint()
    taken = _TAKEN.get(name)
    if taken is not None and taken != fingerprint:
        raise ValueError(
            f"law name {name!r} is already registered with other data in this process "
            f"(pid {os.getpid()}; a sweep's worker keeps the laws of the studies it ran); "
            "register the new data under another name, or restart that process (a Dask "
            "cluster's workers: client.restart())"
        )
    if name in _USER:
        return _USER[name]
    _TAKEN[name] = fingerprint
    alias_range(name, Law.TABULATED)
    _USER[name] = law
    return law


def register_law(
    name: str,
    curves: IndentationCurves | None = None,
    *,
    loading: Callable[[float], Any] | None = None,
    unloading: Callable[[float], Any] | None = None,
    pair: ContactPair | None = None,
    radius: Any = None,
    delta_max: Any = None,
    switch_interference: Any = None,
    points: int | None = None,
    tolerance: float | None = None,
    title: str = "",
    source: str = "",
    elastic_limit: Any = None,
) -> RegisteredLaw:
    """Register a contact law of one's own under ``name``; afterwards ``name`` works wherever
    a law is asked for (``simulate``, ``simulate_batch``, ``simulate_drop``, sweeps and study
    files, ``impactlab laws``).

    Give either ``curves`` (tables: ``IndentationCurves``, e.g. measured data through
    ``IndentationCurves.from_arrays`` or ``from_csv``) or the callables ``loading`` (F [N] at
    delta [m]) and ``unloading`` (delta_r [m] after loading to delta_max [m]) of ``pair`` and
    a sphere of ``radius`` [m], sampled on ``points`` interferences (default 64) up to
    ``delta_max`` [m] and refused beyond ``tolerance`` (default 0.01;
    ``contact.registered.sample_law``); with ``curves`` these sampling arguments are refused,
    ``source`` replaces the curves' source, and a loading fit farther than 2.5 % from a point
    of the tables is refused (``contact.registered.check_table_fit``). The law is the
    tabulated law of those curves (``law_id`` TABULATED): valid for pairs with the curves'
    E*/S_y and nu in which the same body yields first (``IndentationCurves.yielding``), up to
    the last tabulated interference. ValueError for a built-in name (or
    one with '_' for its '-'), a name already registered with other data, bad tables or
    callables (naming the value), and a name that reads as a registered one's with '_' for
    '-' (``ok_law`` beside ``ok-law``).
    ``switch_interference`` [m]: where the sampled law leaves Hertz (default: the pair's
    Jackson-Green delta_c); ``elastic_limit`` is its name before 0.3 (a DeprecationWarning;
    ``IndentationCurves.elastic_limit`` is the same point as delta/delta_c). The lengths
    (``radius``, ``delta_max``, ``switch_interference``) are numbers in m, strings with units
    (``"300 um"``) or pint Quantities, as every length of the Python API.
    """
    if elastic_limit is not None:
        warn_renamed("elastic_limit", "switch_interference", "register_law keyword")
        elastic_limit = check_positive("elastic_limit", elastic_limit, "m")
        if switch_interference is not None:
            switch_interference = check_positive("switch_interference", switch_interference, "m")
        if switch_interference is not None and switch_interference != elastic_limit:
            raise ValueError(
                f"switch_interference ({switch_interference!r} m) and its former name "
                f"elastic_limit ({elastic_limit!r} m) differ: give switch_interference only"
            )
        switch_interference = elastic_limit
    check_law_name(name)
    if name in _LAWS:  # before any sampling: the cheap refusal first
        raise ValueError(
            f"law name {name!r} is a built-in law's and cannot be registered again; "
            f"built-in: {', '.join(builtin_law_names())}"
        )
    _check_twin(name)
    sampled = loading is not None or unloading is not None
    if curves is not None and sampled:
        raise ValueError("give either curves or loading and unloading callables, not both")
    if curves is not None:
        if switch_interference is not None:
            raise ValueError(
                "switch_interference applies to sampled callables; curves carry their own "
                "elastic limit (IndentationCurves.elastic_limit, in delta/delta_c)"
            )
        sampling = {"pair": pair, "radius": radius, "delta_max": delta_max}
        sampling |= {"points": points, "tolerance": tolerance}
        given = [key for key, value in sampling.items() if value is not None]
        if given:
            verb = "applies" if len(given) == 1 else "apply"
            raise ValueError(
                f"{', '.join(given)} {verb} to sampled callables; curves carry their own pair "
                f"(E*/S_y, nu), range and fit: leave {', '.join(given)} out (source and title "
                f"apply to both)"
            )
        if not isinstance(curves, IndentationCurves):
            raise ValueError(f"curves must be IndentationCurves, got {type(curves).__name__}")
        if source:
            curves = curves.with_source(source)
        return add_law(RegisteredLaw(name, curves, title=title))
    if loading is None or unloading is None or pair is None or radius is None:
        raise ValueError(
            "register_law needs curves, or loading and unloading callables with the pair, "
            "radius and delta_max they describe"
        )
    if delta_max is None:
        raise ValueError("delta_max [m] (the largest interference to sample) is required")
    law = sample_law(
        name,
        loading,
        unloading,
        pair,
        radius,
        delta_max,
        switch_interference=switch_interference,
        points=DEFAULT_POINTS if points is None else points,
        tolerance=DEFAULT_TOLERANCE if tolerance is None else tolerance,
        title=title,
        source=source,
    )
    return add_law(law)


def unregister_law(name: str) -> None:
    """Remove the user's law ``name`` from the registry (its name stays tied to its data for
    the life of the process). ValueError for a built-in or unknown name."""
    if name in _LAWS:
        raise ValueError(f"law {name!r} is built in and cannot be unregistered")
    if _USER.pop(name, None) is None:
        raise ValueError(f"no user law {name!r} is registered; registered: {sorted(_USER)}")


def registered_laws() -> dict[str, RegisteredLaw]:
    """The user's laws now registered, by name."""
    return dict(_USER)


def law_records(names: Any) -> dict[str, dict[str, Any]]:
    """The records (``RegisteredLaw.record``) of the user's laws among ``names`` (others
    are left out): what a sweep carries to its workers."""
    return {str(n): _USER[n].record() for n in names if isinstance(n, str) and n in _USER}


def ensure_laws(records: Mapping[str, Any]) -> None:
    """Register the laws of ``records`` (name -> ``RegisteredLaw.record``) where they are not
    registered yet (a worker process), checking that each name means the same data."""
    for name, record in records.items():
        if name in _USER and _USER[name].record() == record:
            continue  # the common case in a worker: already registered (cheaper than a build)
        law = law_from_record(record)
        if law.name != name:
            raise ValueError(f"law record {name!r} names the law {law.name!r}")
        add_law(law)


__all__ = [
    "add_law",
    "builtin_law_names",
    "ensure_laws",
    "get_law",
    "law_names",
    "law_records",
    "register_law",
    "registered_laws",
    "unregister_law",
]
