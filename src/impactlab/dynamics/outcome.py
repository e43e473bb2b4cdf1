"""From a compiled impact's output row to an ``ImpactResult``, and the ValueError of a failed
impact: one place for ``simulate`` (the rigid core) and the partial-slip path (slipcore), which
write the same output row (``impactlab.schema.OUTPUT_FIELDS``) and status codes."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.bodies import Rod
from impactlab.contact import ContactModel
from impactlab.dynamics.checks import ImpactInputs
from impactlab.dynamics.core import layout as L
from impactlab.dynamics.core import status as S
from impactlab.dynamics.models import references_used
from impactlab.dynamics.results import History, ImpactResult

__all__ = ["impact_result", "status_error"]

#: Engine outputs that are ImpactResult fields of the same name and type (float), with their
#: column in the output row.
_SCALAR_COLUMNS = tuple(
    (n, L.O[n])
    for n in L.OUTPUT_FIELDS
    if n in ImpactResult.__dataclass_fields__ and n not in ("regime", "n_steps")
)


def status_error(status: int, model: ContactModel, prefix: str = "") -> ValueError:
    """The ValueError of an impact that ended with engine ``status`` (not ``ST_OK``)."""
    if status == S.ST_LAW_LIMIT:
        text = (
            f"the interference exceeded {model.max_interference:.6g} m, the validity limit of "
            f"the {model.name!r} law: lower the impact velocity or choose another law"
        )
    elif status == S.ST_NAN:
        text = (
            f"the {model.name!r} contact law returned a non-finite force or unloading branch "
            f"(law not available, or evaluated outside its domain)"
        )
    else:
        text = S.STATUS_MESSAGES.get(status, f"engine status {status}")
    return ValueError(prefix + text)


def impact_result(x: ImpactInputs, out: np.ndarray, history: np.ndarray | None) -> ImpactResult:
    """The ``ImpactResult`` of the checked inputs ``x`` from the output row ``out`` and the
    history rows (None: no history kept)."""
    o = out.tolist()
    scalars: dict[str, Any] = {name: o[j] for name, j in _SCALAR_COLUMNS}
    return ImpactResult(
        **scalars,
        velocity_out=(o[L.O_VX], o[L.O_VY]),
        regime=S.REGIME_NAMES[int(o[L.O_REG])],
        n_steps=int(o[L.O_NST]),
        law=x.model.name,
        friction=x.friction.name,
        mu=x.mu,
        angle=x.angle if isinstance(x.body, Rod) else math.nan,
        velocity_in=x.velocity,
        spin_in=x.spin,
        history=History(history) if history is not None else None,
        references=references_used(x.model, x.friction, x.mu > 0.0),
        _law_id=x.model.law_id,
        _law_params=x.model.params,
    )
