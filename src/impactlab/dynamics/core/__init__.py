"""The compiled rigid impact: planar rigid body (rod or sphere) on a flat, one contact.

Everything here runs in numba ``nopython`` mode on the shared kernels of
``impactlab.dynamics.kernels`` (layout, status codes, normal contact, friction, right-hand side,
transitions, the Dormand-Prince tableau and dense output, the event search): the normal contact
history (loading / unloading / reloading), the friction models and all phase switches,
integrated by an embedded Dormand-Prince 5(4) pair with its 4th-order dense output and event
location on the dense output. The equations, conventions and event logic are documented in
``docs/engine/index.md``. It imports only numpy, numba, math, L0, the kernels,
``impactlab.contact.kernels``, ``contact.history_kernels`` and ``impactlab.bodies.layout``;
never the partial-slip or flexible drivers.

Modules, lowest first:

- ``integrator``: the step written out for the rigid state (``dp_step``), event location,
  the integration over an exact interval.
- ``history``: recording of the time history.
- ``accumulate``: running extremes and the normal work (the accumulator array).
- ``approach``, ``ends``: the two ends of the contact integrated in w = sqrt(delta - delta_0).
- ``events``: the actions at an event.
- ``driver``: ``impact`` (one impact: initialisation, step loop, results at separation).
- ``atomic``: ``fetch_add``, the atomic counter of the batch's work queue.
- ``batch``: ``impact_batch`` (parallel, dynamically scheduled blocks) and ``residual_caps``.
"""

from __future__ import annotations

from impactlab.dynamics.core.batch import impact_batch, residual_caps
from impactlab.dynamics.core.driver import impact

__all__ = ["impact", "impact_batch", "residual_caps"]
