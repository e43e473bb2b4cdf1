"""Index layout of the rigid-body vectors every engine reads: state, constants, mode, events,
outputs, history columns and the accumulator of running extremes, plus the friction ids and the
integration limits (the partial-slip layout, ``slipcore.layout``, extends it; the flexible
rod's modal layout is ``flexcore.layout``).

numba freezes these module constants into the machine code (the cache folder is keyed by a
hash of every engine source, ``impactlab._compiled_cache``). The output and
history names come from ``impactlab.schema``, the one table of result fields.
"""

from __future__ import annotations

from impactlab import schema


def _columns(fields: tuple[schema.Field, ...]) -> tuple[tuple[str, ...], int, dict[str, int]]:
    """(names, count, name -> column index) of a table of ``impactlab.schema`` fields."""
    names = tuple(f.name for f in fields)
    return names, len(names), {name: i for i, name in enumerate(names)}


# --- friction ids (the public ones are in impactlab.friction) -----------------------------------
FR_NONE = -1  # internal: mu below MU_NEGLIGIBLE
#: Friction coefficients below this run frictionless (FR_NONE, regime "frictionless"): the
#: friction force is below 1e-9 of the normal force, so no output moves by more than ~1e-9
#: relative (below any tolerance of the integration), while the stick/slip switches of so
#: small a force (Mindlin, partial slip, a contact point starting at rest) are decided by
#: round-off and chattered until MAX_EVENTS (found by hypothesis: mu = 1e-14).
MU_NEGLIGIBLE = 1e-9
FR_IMPULSE = 0
FR_COULOMB = 1
FR_MINDLIN = 2

# --- state vector y (SI) --------------------------------------------------------------------------
S_X = 0  # displacement of the centre of mass along x since first touch [m]
S_Y = 1  # displacement of the centre of mass along y since first touch [m]
S_PHI = 2  # rotation since first touch, counter-clockwise [rad]
S_VX = 3  # velocity of the centre of mass along x [m/s]
S_VY = 4  # velocity of the centre of mass along y [m/s]
S_SPIN = 5  # angular velocity, counter-clockwise [rad/s]
S_WORK = 6  # work of the normal force on the body, int F_n v_n dt [J]
S_Q = 7  # Mindlin tangential state: force [N] while the contact grows, displacement [m] else
NS = 8

# --- constants vector c (a tuple, built once per impact) -----------------------------------------
C_D = 0  # L/2 [m]
C_R = 1  # tip radius [m]
C_M = 2  # mass [kg]
C_I = 3  # inertia [kg m^2]
C_G = 4  # gravity [m/s^2]
C_TH0 = 5  # initial angle [rad]
C_S0 = 6  # sin th0
C_C0 = 7  # cos th0
C_MU = 8  # friction coefficient
C_GS = 9  # G* [Pa]
C_CONST = 10  # 1: constant-angle kinematics
C_A0 = 11  # a at th0
C_B0 = 12  # b at th0
C_DLIM = 13  # law validity limit [m]
C_DSW = 14  # interference where the loading curve leaves the elastic curve [m] (inf: none)
C_IM = 15  # 1/m [1/kg] (a multiplication in the right-hand side instead of a division)
C_II = 16  # 1/I [1/(kg m^2)]
NC = 17

# --- mode vector md (a tuple, rebuilt at every switch) --------------------------------------------
M_PHASE = 0  # 0 loading curve, 1 unloading/reloading curve
M_DM = 1  # delta_m of the current unloading branch [m]
M_DR = 2  # delta_r [m]
M_RR = 3  # R_r [m]
M_FM = 4  # friction mode: 0 stick (coulomb) / elastic (mindlin); +-1 slip direction
M_COMP = 5  # 1 while the contact point approaches the flat (delta increasing)
M_SIR = 6  # impulse_ratio: F_t = M_SIR * mu * F_n
M_AF = 7  # unloading contact-radius factor: continuity of k_t at the turning point (Mindlin)
NM = 8

# --- events (a tuple g; an event fires when g goes from <= 0 to > 0) -----------------------------
EV_VN = 0  # normal velocity of the contact point changes sign
EV_RELOAD = 1  # reloading reaches delta_m: back to the loading curve
EV_SEP = 2  # separation: delta reaches delta_r while receding
EV_LIMIT = 3  # the law's validity limit
EV_FRIC = 4  # stick/slip switch
EV_SWITCH = 5  # the loading curve leaves the elastic curve (p[P_DSW]): restart the integration
NEV = 6

# --- outputs (columns of ``out``, in the order of impactlab.schema.OUTPUT_FIELDS) ----------------
OUTPUT_FIELDS, N_OUT, O = _columns(schema.OUTPUT_FIELDS)
O_E = O["e"]
O_EE = O["e_energy"]
O_VX = O["vx_out"]
O_VY = O["vy_out"]
O_SPIN = O["spin_out"]
O_DMAX = O["delta_max"]
O_DP = O["delta_p"]
O_SL = O["sliding_length"]
O_CT = O["contact_travel"]
O_T = O["duration"]
O_FMEAN = O["mean_force"]
O_FMAX = O["max_force"]
O_PN = O["normal_impulse"]
O_PT = O["tangential_impulse"]
O_ED = O["energy_dissipated"]
O_STICK = O["stick_time"]
O_REG = O["regime"]
O_VNIN = O["vn_in"]
O_VTIN = O["vt_in"]
O_VNOUT = O["vn_out"]
O_VTOUT = O["vt_out"]
O_ANG = O["angle_out"]
O_TMAX = O["t_max"]
O_NST = O["n_steps"]
O_ERISE = O["energy_rise"]
O_FEX = O["friction_excess"]
O_FLAGS = O["flags"]

# --- history columns (impactlab.schema.HISTORY_FIELDS) --------------------------------------------
HISTORY_FIELDS, NH, H = _columns(schema.HISTORY_FIELDS)
H_T = H["t"]
H_DELTA = H["penetration"]
H_FN = H["normal_force"]
H_FT = H["tangential_force"]
H_XC = H["contact_x"]
H_VSLIP = H["slip_velocity"]
H_X = H["x"]
H_Y = H["y"]
H_PHI = H["phi"]
H_VX = H["vx"]
H_VY = H["vy"]
H_SPIN = H["spin"]
H_VN = H["normal_velocity"]
H_PHASE = H["phase"]
H_STICK = H["stick"]
H_ENERGY = H["energy"]

# --- running extremes and work of one impact: the accumulator array ``acc`` of the rigid and the
# partial-slip drivers (each appends its own entries from A_OWN) ----------------------------------
A_EMIN = 0  # lowest total energy so far [J]
A_ERISE = 1  # largest rise of the total energy above that minimum [J]
A_FEX = 2  # largest |F_t| - mu F_n [N]
A_FMAX = 3  # largest normal force [N]
A_DMAX = 4  # largest interference [m]
A_TMAX = 5  # time of the largest interference [s]
A_VSPOS = 6  # largest slip velocity [m/s]
A_VSNEG = 7  # smallest slip velocity [m/s]
A_STICK = 8  # time in stick (partial slip: with at least one cell stuck) [s]
A_WMARK = 9  # normal work at the last v_n = 0 event [J]
A_WCOMP = 10  # normal work of compression [J]
A_WREST = 11  # normal work of restitution [J]
A_OWN = 12  # the first entry of a driver's own

# --- integration ----------------------------------------------------------------------------------
DEFAULT_RTOL = 2e-7
#: The partial-slip engine (``dynamics.slipcore``, without the w-integrated ends of ``approach``)
#: keeps the tolerance it was verified at.
PARTIAL_SLIP_RTOL = 3e-8
MAX_STEPS = 200_000
MAX_EVENTS = 20_000
HISTORY_SUBSTEPS = 4  # history rows per accepted step (dense output)
