"""The compiled impact engine: planar rigid body (rod or sphere) on a flat, one contact.

Everything here runs in numba ``nopython`` mode: the equations of motion, the normal contact
history (loading / unloading / reloading), the friction models and all phase switches,
integrated by an embedded Dormand-Prince 5(4) pair with its 4th-order dense output and event
location on the dense output. The equations, conventions and event logic are documented in
``docs/engine/index.md``. The core imports only numpy, numba, math, ``impactlab.schema``,
``impactlab.flags``, ``impactlab.contact.kernels`` and ``impactlab.bodies.layout``.

Modules, lowest first:

- ``layout``: indices of the state, constants, mode, event, output and history vectors; limits.
- ``status``: status codes and messages, friction regime codes.
- ``tuples``: the state and mode as tuples.
- ``normal``: contact-point kinematics, the normal force and contact radius on the current branch.
- ``friction``: friction kernels (stick force, Coulomb decision, switches, Mindlin trial rate).
- ``rhs``: right-hand side, event functions, total energy.
- ``integrator``: Dormand-Prince tableau, the step, dense output, event location.
- ``history``: recording of the time history.
- ``quality``: the result flags at separation (energy gain, gravity dominance).
- ``setup``: input checks, constants, initial mode, error scales.
- ``transitions``: mode transitions at events and the restart after a switch.
- ``driver``: ``impact`` (one impact: initialisation, step loop, results at separation).
- ``atomic``: ``fetch_add``, the atomic counter of the batch's work queue.
- ``batch``: ``impact_batch`` (parallel, dynamically scheduled blocks) and ``residual_caps``.
"""

from __future__ import annotations

from impactlab.dynamics.core.batch import impact_batch, residual_caps
from impactlab.dynamics.core.driver import impact

__all__ = ["impact", "impact_batch", "residual_caps"]
