"""The compiled partial-slip engine: a rigid body (rod or sphere) on a flat with
Mindlin-Deresiewicz partial-slip friction, one contact.

A driver beside ``impactlab.dynamics.core`` on the shared kernels of
``impactlab.dynamics.kernels`` (layout, normal contact, input checks, transitions, the
Dormand-Prince tableau and dense output, the partial-slip cells, the Anderson-Bjorck bracket
update of the event search); it never imports another
driver. The tangential contact is the exact
Mindlin-Deresiewicz model in its method-of-dimensionality-reduction form, discretised into cells
(``model``); every cell switch is an event located on the dense output, except the release of
a slipping cell (its force reaches zero continuously). The derivation, validity
and verification are in docs/verification/index.md ("Partial slip").

Modules, lowest first: ``layout`` (parameter and event indices, defaults), ``model``
(right-hand side, event functions), ``sums`` (the Dormand-Prince sums over the entries in
use), ``stepper`` (Dormand-Prince on arrays, event location),
``address_call`` (calls through addresses), ``switches`` (births, releases, stick/slip,
settle), ``outputs`` (bookkeeping, history, results), ``restart`` (the switch at an event),
``indirect`` (the addresses, read in Python), ``driver`` (``impact_slip``).
"""

from __future__ import annotations

from impactlab.dynamics.kernels.cells import N_CELLS
from impactlab.dynamics.slipcore.driver import impact_slip
from impactlab.dynamics.slipcore.indirect import addresses as slip_addresses

__all__ = ["N_CELLS", "impact_slip", "slip_addresses"]
