"""One name, one meaning across the compiled engines: a constant (a layout index, an event or
status code, a limit) defined by two engine modules has the same value in both, so a grep for
it never finds two meanings."""

from __future__ import annotations

import importlib
from collections import defaultdict

ENGINE_MODULES = (
    "impactlab.contact.kernels",
    "impactlab.contact.table",
    "impactlab.bodies.layout",
    "impactlab.dynamics.core.layout",
    "impactlab.dynamics.core.status",
    "impactlab.dynamics.core.friction",
    "impactlab.dynamics.slipcore.layout",
    "impactlab.dynamics.flexcore.layout",
    "impactlab.dynamics.flexcore.cells",
)


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
