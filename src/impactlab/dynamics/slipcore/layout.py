"""Index layout of the partial-slip engine: cell modes, the cell-parameter vector, the event
vector and the defaults (the rigid-body part of the state, the normal mode tuple and the outputs
are those of ``impactlab.dynamics.core.layout``)."""

from __future__ import annotations

from impactlab.dynamics.core.layout import NEV, NS

# --- cell modes ------------------------------------------------------------------------------
OUT = 0  # not (or no longer) in contact: f = 0
STICK = 1  # df/dt = 2 G_1 l v_slip (+ the share of a receding edge cell)
SLIP = 2  # f = s L (on its moving Coulomb limit)

# --- cell parameters (a float vector cp) -------------------------------------------------------
CP_G1 = 0  # G_1 = 4 G* [Pa]: tangential stiffness per unit length of the MDR line
CP_DX = 1  # cell width [m] (a_est / N)
CP_VTOL = 2  # slip-rate hysteresis of the slip -> stick test [m/s]
CP_FTOL = 3  # force hysteresis of the stick -> slip test [N]
CP_FSC = 4  # error scale of one cell force [N]
NCP = 5

# --- events: the core's EV_* (0 .. NEV-1; EV_FRIC unused) then the cells' -----------------------
G_BIRTH = NEV  # the contact radius reaches the next cell (while growing)
G_REL = NEV + 1  # the contact radius recedes past the outermost cell
G_CELL = NEV + 2  # + i: stick -> slip or slip -> stick of cell i
#: First cell force in the state vector (the rigid-body state comes first).
Y_CELL = NS

# --- defaults ----------------------------------------------------------------------------------
N_CELLS = 16  # cells over the largest contact radius (max |e_t - exact| ~ 1e-3, 2nd order)
EXTRA = 4  # cell slots per cell of the estimate (the contact may outgrow it)
SLIP_HYST = 1e-9  # relative hysteresis of the stick -> slip test
