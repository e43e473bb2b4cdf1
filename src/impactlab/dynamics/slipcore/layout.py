"""Index layout of the partial-slip engine: the cell-parameter vector beyond the shared cell
parameters, the event vector and the defaults (the cell modes, the shared cell parameters
``CP_G1`` ... ``CP_FTOL`` and ``N_CELLS`` are those of ``impactlab.dynamics.kernels.cells``; the
rigid-body part of the state, the normal mode tuple and the outputs those of
``impactlab.dynamics.kernels.layout``)."""

from __future__ import annotations

from impactlab.dynamics.kernels.cells import CP_FTOL
from impactlab.dynamics.kernels.layout import NEV, NS

# --- cell parameters (a float vector cp): kernels.cells.CP_G1 ... CP_FTOL (0 .. 3), then -------
CP_FSC = CP_FTOL + 1  # error scale of one cell force [N]
NCP = CP_FSC + 1

# --- events: the core's EV_* (0 .. NEV-1; EV_FRIC unused) then the cells' -----------------------
G_BIRTH = NEV  # the contact radius reaches the next cell (while growing)
G_REL = NEV + 1  # the contact radius recedes past the outermost cell
G_CELL = NEV + 2  # + i: stick -> slip or slip -> stick of cell i
#: First cell force in the state vector (the rigid-body state comes first).
Y_CELL = NS

# --- defaults ----------------------------------------------------------------------------------
EXTRA = 4  # cell slots per cell of the estimate (the contact may outgrow it)
