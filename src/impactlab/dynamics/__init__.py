"""The impact engine: a compiled planar rigid-body impact of a rod or sphere on a flat.

    from impactlab.bodies import Rod
    from impactlab.dynamics import simulate
    r = simulate(Rod.paper(), law="ghaednia", friction="coulomb", mu=0.2,
                 angle=math.radians(20), velocity=(0.0, -1.41))

See docs/engine/index.md for the equations, conventions and models.
"""

from impactlab.dynamics.batch import (
    BATCH_FRICTION_IDS,
    FRICTION_IDS,
    OUTPUT_FIELDS,
    REGIME_NAMES,
    STATUS_MESSAGES,
    run_arrays,
)
from impactlab.dynamics.batch_result import BatchResult
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_batch import DropBatchResult, simulate_drops
from impactlab.dynamics.drop_result import ContactRecord, DropResult
from impactlab.dynamics.flex_simulate import ModeConvergence, mode_convergence
from impactlab.dynamics.kernels.layout import DEFAULT_RTOL, HISTORY_FIELDS
from impactlab.dynamics.models import contact_model
from impactlab.dynamics.results import DentMap, History, ImpactResult
from impactlab.dynamics.simulate import rerun, simulate
from impactlab.dynamics.simulate_many import simulate_batch

__all__ = [
    "BATCH_FRICTION_IDS",
    "DEFAULT_RTOL",
    "FRICTION_IDS",
    "HISTORY_FIELDS",
    "OUTPUT_FIELDS",
    "REGIME_NAMES",
    "STATUS_MESSAGES",
    "BatchResult",
    "ContactRecord",
    "DentMap",
    "DropBatchResult",
    "DropResult",
    "History",
    "ImpactResult",
    "ModeConvergence",
    "contact_model",
    "mode_convergence",
    "rerun",
    "run_arrays",
    "simulate",
    "simulate_batch",
    "simulate_drop",
    "simulate_drops",
]
