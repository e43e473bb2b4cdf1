"""One id per friction model: every compiled ``FR_*`` constant, in every module of the package
that defines one (the kernels' layout, and the copies the flexible core keeps), equals
``impactlab.friction``'s id of that model, so a copy cannot drift from the table; and the
rigid core's input check (``kernels.setup``: ids ``FR_IMPULSE`` to ``FR_MINDLIN``) accepts
exactly the core's models (``FRICTION_IDS``)."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

from impactlab.dynamics.kernels import layout
from impactlab.friction import FRICTION_IDS, FRICTION_MODELS, FrictionKind

SRC = Path(__file__).resolve().parents[2] / "src"

#: The model each compiled id constant stands for; ``FR_NONE`` is the engine's own
#: (mu below ``MU_NEGLIGIBLE``: frictionless) and no model's id.
MODEL_OF = {
    "FR_IMPULSE": FrictionKind.IMPULSE_RATIO,
    "FR_COULOMB": FrictionKind.COULOMB,
    "FR_MINDLIN": FrictionKind.MINDLIN,
    "FR_PARTIAL": FrictionKind.PARTIAL_SLIP,
}
INTERNAL = {"FR_NONE"}

DEFINITION = re.compile(r"^(FR_[A-Z0-9_]+)\s*(?::[^=\n]*)?=", re.MULTILINE)


def _definitions() -> list[tuple[str, str]]:
    """(module, constant) of every module-level ``FR_*`` assignment under src/impactlab."""
    found: list[tuple[str, str]] = []
    for path in sorted((SRC / "impactlab").rglob("*.py")):
        module = ".".join(path.relative_to(SRC).with_suffix("").parts)
        found += [(module, n) for n in DEFINITION.findall(path.read_text(encoding="utf-8"))]
    return found


def test_every_compiled_friction_id_is_the_models_id() -> None:
    defs = _definitions()
    modules = {m for m, _ in defs}
    # the check can fail: the kernels' ids and the flexible core's copies are all found
    assert {"impactlab.dynamics.kernels.layout", "impactlab.dynamics.flexcore.batch"} <= modules
    assert "impactlab.dynamics.flexcore.layout" in modules and len(defs) >= 7
    ids = {m.friction_id for m in FRICTION_MODELS.values()}
    for module, name in defs:
        value = getattr(importlib.import_module(module), name)
        if name in INTERNAL:
            assert value not in ids, f"{module}.{name} = {value} is a friction model's id"
            continue
        assert name in MODEL_OF, f"{module}.{name}: name its model in MODEL_OF of this test"
        want = FRICTION_MODELS[MODEL_OF[name]].friction_id
        assert value == want, f"{module}.{name} = {value}, impactlab.friction says {want}"


def test_the_core_accepts_exactly_its_models() -> None:
    """``check_inputs`` refuses a friction id outside FR_IMPULSE..FR_MINDLIN: that range must
    be the core's models, no more (partial slip runs in slipcore) and no fewer."""
    accepted = list(range(layout.FR_IMPULSE, layout.FR_MINDLIN + 1))
    assert sorted(FRICTION_IDS.values()) == accepted
    assert FRICTION_MODELS[FrictionKind.PARTIAL_SLIP].friction_id not in accepted
