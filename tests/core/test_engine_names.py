"""One name, one meaning across the compiled engines: a constant (a layout index, an event or
status code, a limit) defined by two engine modules has the same value in both, so a grep for
it never finds two meanings."""

from __future__ import annotations

import importlib
import pkgutil
from collections import defaultdict

#: The compiled packages: the shared kernels and the three drivers, every module of each.
COMPILED_PACKAGES = (
    "impactlab.dynamics.kernels",
    "impactlab.dynamics.core",
    "impactlab.dynamics.slipcore",
    "impactlab.dynamics.flexcore",
)
LOW_MODULES = (
    "impactlab.contact.kernels",
    "impactlab.contact.history_kernels",
    "impactlab.contact.table",
    "impactlab.bodies.layout",
)


def _package_modules(package: str) -> list[str]:
    path = importlib.import_module(package).__path__
    return [f"{package}.{m.name}" for m in pkgutil.iter_modules(path)]


ENGINE_MODULES = LOW_MODULES + tuple(m for p in COMPILED_PACKAGES for m in _package_modules(p))


def _constants(module: str) -> dict[str, object]:
    mod = importlib.import_module(module)
    return {
        name: value
        for name, value in vars(mod).items()
        if name.isupper() and isinstance(value, int | float | str | tuple) and value is not None
    }


def test_no_constant_name_has_two_values() -> None:
    seen: dict[str, dict[str, object]] = defaultdict(dict)
    for module in ENGINE_MODULES:
        for name, value in _constants(module).items():
            seen[name][module] = value
    clashes = {
        name: where
        for name, where in seen.items()
        if len({float(v) if isinstance(v, int | float) else repr(v) for v in where.values()}) > 1
    }
    assert not clashes, f"one name with two meanings: {clashes}"


def test_every_compiled_package_is_listed() -> None:
    """The walk finds the shared kernels' modules (a renamed package would leave it empty)."""
    names = set(ENGINE_MODULES)
    for module in ("layout", "status", "cells", "dormand_prince", "roots", "step_control"):
        assert f"impactlab.dynamics.kernels.{module}" in names
