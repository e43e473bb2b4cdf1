"""Layouts of the flexible-rod integrator: the constants vector, the per-end mode table, the
events, the dents, the contact records, the run state, the output vector and the history.

Imports only ``impactlab.schema`` (L0) and the status table of every engine (``kernels.status``):
the compiled modules of this package read the indices.

State vector (length 6 + 2 M + NQUAD + N_END_WORKS, M elastic modes):
``[dX, dY, phi, q_1..q_M, vx, vy, spin, q'_1..q'_M, W_n, W_t, W_d, (P_n, P_t, S, |S|) x NE,
Q_t x NE, (cells), (W_n, W_t) x NE]``;
dX, dY: displacement of the centre of mass C from its position at first touch [m] (the origin
of x is the first contact point), phi: rotation since first touch [rad], q: modal coordinates
[kg^1/2 m], W_n, W_t, W_d: work of the normal forces, of friction and of the modal damping [J];
per end: normal and tangential impulse [N s], signed and absolute slip integrals [m]; per end
the Mindlin tangential state Q_t (as the rigid core's ``S_Q``: the force [N] while the contact
grows, the elastic displacement [m] while it shrinks; 0 for the other friction models). With
``partial_slip`` NCS cell forces [N] per end follow (``cells``). Last, per end the works of its
normal force and of its friction force [J], the contact records' works: integrated with the
state but left out of the error norm (their sums are W_n and W_t, which are in it), so that
they change no step (state length ``model.state_length``).
"""

from __future__ import annotations

from impactlab.dynamics.kernels import status as _status
from impactlab.schema import Field

NE = 2  #: number of ends (0: the tip that touches first, 1: the other end)
Q_TAN = 3 + 4 * NE  #: offset of the Mindlin states Q_t in the block after the modal velocities
NQUAD = Q_TAN + NE  #: quadratures and tangential states after the modal velocities
N_END_WORKS = 2 * NE  #: the ends' own works (W_n, W_t per end), the last entries of the state
FR_PARTIAL = 3  #: ``impactlab.friction`` id of ``partial_slip`` (Mindlin-Deresiewicz cells)

# ---- constants vector (``FC_*``) --------------------------------------------------------------
FC_D = 0  #: L/2 [m]
FC_R = 1  #: radius of the end spheres [m]
FC_M = 2  #: mass [kg]
FC_I = 3  #: I_C [kg m^2]
FC_G = 4  #: gravity [m/s^2]
FC_TH0 = 5  #: angle at first touch [rad]
FC_MU = 6  #: friction coefficient [1]
FC_DLIM = 7  #: the law's validity limit [m]
FC_DSW = 8  #: the law's elastic -> plastic switch interference [m] (inf: none)
FC_S0 = 9  #: sin(angle)
FC_C0 = 10  #: cos(angle)
FC_FRIC = 11  #: friction model id (``impactlab.friction``: 0 impulse_ratio, 1 coulomb, 2 mindlin)
FC_GS = 12  #: G* of the pair [Pa] (Mindlin tangential stiffness k_t = 8 G* a)
FC_CP = 13  #: partial slip: the cell parameters of end k at FC_CP + k NFCP (``cells.CP_*``)
NFCP = 4
FC_MAX_STEPS = (
    FC_CP + NE * NFCP
)  #: the step limit of the run (``DROP_MAX_STEPS``, or less: partial slip)
NFC = FC_MAX_STEPS + 1

# ---- per-end mode table (``MD_*``) ------------------------------------------------------------
MD_IN = 0  #: 1 in contact
MD_PH = 1  #: 0 loading curve, 1 unloading / reloading curve
MD_DM = 2  #: delta_m of the branch [m]
MD_DR = 3  #: delta_r [m] (out of contact: the touch threshold, the dent's delta_r under the end)
MD_RR = 4  #: R_r of the unloading curve [m]
MD_FM = 5  #: friction: 0 stick (Mindlin: no gross slip), +-1 slip direction (sign of v_t)
MD_COMP = 6  #: 1 while delta increases
MD_DSW = 7  #: pending elastic -> plastic switch interference [m] (inf when passed)
MD_DENT = 8  #: index of the dent under the end (-1: virgin flat)
MD_SIR = 9  #: impulse_ratio: F_t = MD_SIR mu F_n over the contact (sign fixed at touch)
MD_AF = 10  #: Mindlin: unloading contact-radius factor (k_t continuous at the turning point)
NCS = 64  #: partial slip: cell slots per end (4 x the 16 cells over the estimated largest radius)
MD_CM = 11  #: partial slip: cell modes (``cells.OUT``, ``STICK``, ``SLIP``), NCS columns
MD_SG = MD_CM + NCS  #: partial slip: slip directions of the cells, NCS columns
NMD = MD_SG + NCS

# ---- per-end event functions (``FEV_*``; event j of end k is k * NFEVK + FEV_*) -----------------
FEV_TOUCH = 0
FEV_VN = 1  #: turning point of delta (compression <-> restitution)
FEV_RELOAD = 2  #: reloading past the earlier delta_m: back on the loading curve
FEV_SEP = 3
FEV_LIMIT = 4  #: the law's validity limit
FEV_FRIC = 5  #: slip -> stick (v_t = 0) or stick -> slip (|F_t| = mu F_n)
FEV_SWITCH = 6  #: elastic -> plastic switch of the loading curve
NFEVK = 7
NFEV = NE * NFEVK
#: Partial slip: per end NFEVC cell events after the NFEV above (end k's at NFEV + k NFEVC):
#: birth of the next cell, release of the outermost, then one stick/slip switch per cell.
FG_BIRTH = 0
FG_REL = 1
FG_CELL = 2
NFEVC = FG_CELL + NCS

# ---- per-end evaluated quantities (``EK_*``, a (NE, NEK) array) -------------------------------
EK_DELTA = 0  #: interference [m]
EK_X = 1  #: x of the contact point (below the sphere centre) [m]
EK_VN = 2  #: normal velocity of the contact point [m/s]
EK_VT = 3  #: slip velocity v_t [m/s]
EK_FN = 4  #: normal force [N]
EK_FT = 5  #: tangential force [N]
EK_JDOT = 6  #: dJ_t/dt z' (the velocity-dependent tangential acceleration) [m/s^2]
EK_KT = 7  #: Mindlin tangential stiffness k_t [N/m] (0 for the other models)
EK_A = 8  #: partial slip: contact radius a [m]
EK_AD = 9  #: partial slip: da/dt [m/s]
EK_L = 10  #: partial slip: the cells' limits L_i [N] (NCS columns)
EK_LD = EK_L + NCS  #: their rates dL_i/dt [N/s]
EK_F = EK_LD + NCS  #: the cells' forces f_i [N]
NEK = EK_F + NCS

# ---- dents on the flat (``DT_*``) -------------------------------------------------------------
DT_END = 0  #: the end that made it
DT_XLO = 1  #: extent of the contact-point path [m]
DT_XHI = 2
DT_AM = 3  #: largest contact radius [m]
DT_DM = 4  #: delta_m [m]
DT_DR = 5  #: delta_r [m]
DT_RR = 6  #: R_r [m]
DT_FM = 7  #: F_m [N]
DT_NC = 8  #: number of contacts on it
NDT = 9
MAX_DENTS = 256

# ---- contact records (``CR_*``) ---------------------------------------------------------------
CR_END = 0
CR_T0 = 1  #: start [s] (from the first touch)
CR_DUR = 2  #: duration [s]
CR_DMAX = 3  #: largest interference [m]
CR_FMAX = 4  #: largest normal force [N]
CR_PN = 5  #: normal impulse [N s]
CR_PT = 6  #: tangential impulse [N s]
CR_SLIP = 7  #: int v_t dt (signed) [m]
CR_ASLIP = 8  #: int |v_t| dt [m]
CR_X0 = 9  #: contact point at touch [m]
CR_X1 = 10  #: contact point at separation [m]
CR_DENT = 11  #: index of its dent
CR_RELOAD = 12  #: 1 if it started on an existing dent
CR_DR = 13  #: the dent's delta_r after the contact [m]
CR_WN = 14  #: work of the normal force [J]
CR_WT = 15  #: work of friction [J]
CR_STICK = 16  #: time spent sticking [s]
#: the angle of the end's section to the flat at touch [rad]: the rod's plus the section's
#: elastic rotation (``kinematics.section_angle``; the rim check; not a record field)
CR_TH0 = 17
CR_TH1 = 18  #: ... at separation (at touch until then) [rad]
#: 1 if the contact began after the end test of stop="sequence" would have passed (a
#: ``stop="flight"`` drop's contacts beyond the tip's sequence; not a record field)
CR_PAST = 19
#: impulse_ratio: the largest slip velocity of the contact point along the contact's friction
#: force, max(s v_t) [m/s] (0 for the other models; ``batch.friction_gained``; not a record
#: field)
CR_VALONG = 20
CR_VNIN = 21  #: |v_n| of the end at touch [m/s] (the scale of CR_VALONG; not a record field)
NCR = 22
MAX_CONTACTS = 4096

# ---- run state (``SV_*``, a float vector shared by the driver's helpers) ----------------------
SV_NSTEPS = 0
SV_NJUMPS = 1
SV_NEVENTS = 2
SV_STATUS = 3
SV_EERR = 4  #: largest |T + V - E0 - W| [J]
SV_FMAX = 5
SV_DMAX = 6
SV_STICK = 7
SV_LAST_END = 8  #: the end of the last touch or separation
SV_T_LAST_SEP = 9
SV_T_CHECK = 10  #: time of the last end-of-sequence test
SV_FINISHED = 11
SV_NEXT_END = 12
SV_NEXT_TIME = 13
SV_ND = 14  #: number of dents
SV_NCON = 15  #: number of contacts
SV_TOL_V = 16  #: tolerances of simultaneous events: velocity [m/s]
SV_TOL_D = 17  #: interference [m]
SV_TOL_F = 18  #: force [N]
SV_HMAX = 19
SV_HMIN = 20
SV_CHECK_DT = 21  #: interval of the end-of-sequence test in free flight [s]
SV_EPS_CLEAR = 22  #: clearance margin of the end-of-sequence test [m]
SV_E0 = 23  #: initial energy [J]
SV_VN0 = 24  #: normal velocity of the tip at first touch [m/s]
SV_TSTAR = 25  #: Hertzian time scale [s]
SV_FSCALE = 26  #: tangential force scale [N] (error scale of Q_t as a force)
SV_DSTAR = 27  #: Hertzian interference scale [m] (error scale of Q_t as a displacement)
#: Contact invariant: out of contact an end may lie below its touch threshold (the dent's
#: surface, or the flat) by at most this much [m]: MISS_TOL_FACTOR max(1e-6, rtol) delta*.
SV_TOL_MISS = 28
#: 1 once the end test of stop="sequence" would have passed (``stop="flight"``: ``CR_PAST``)
SV_SEQ_PASSED = 29
#: the period of the body's lowest mode [s] (a rigid Rod, without modes: the clear flight's
#: NEW_IMPACT_CHECKS intervals): the shortest flight after which a rigid arc of the end last in
#: contact, risen above the flat and coming down, ends the sequence (``flight.falling_back``)
SV_T_RING = 30
NSV = 31
#: The tolerance of the contact invariant in units of max(1e-6, rtol) times the Hertzian
#: interference scale delta* (``SV_TOL_MISS``).
MISS_TOL_FACTOR = 1.0

# ---- status: the one table of every engine (``kernels.status``), named here for this package ----
ST_INACCURATE = _status.ST_INACCURATE
ST_LAW_LIMIT = _status.ST_LAW_LIMIT
ST_MAX_STEPS = _status.ST_MAX_STEPS
ST_MISSED_CONTACT = _status.ST_MISSED_CONTACT
ST_NAN = _status.ST_NAN
ST_OK = _status.ST_OK
ST_STEP_UNDERFLOW = _status.ST_STEP_UNDERFLOW
ST_TMAX = _status.ST_TMAX
ST_TOO_MANY_CONTACTS = _status.ST_TOO_MANY_CONTACTS
ST_TOO_MANY_EVENTS = _status.ST_TOO_MANY_EVENTS
STATUS_MESSAGES = _status.STATUS_MESSAGES

DROP_DEFAULT_RTOL = 1e-7  #: default relative tolerance of the flexible drop
DROP_MAX_STEPS = 2_000_000
#: Partial slip: the step limit is PARTIAL_STEP_FACTOR times the steps of the drop's Mindlin
#: pre-pass, at least PARTIAL_MIN_STEPS (a drop whose cells need more than that is a long,
#: creeping contact: it fails in seconds, not after the 2e6 steps of DROP_MAX_STEPS, ~50 s).
PARTIAL_STEP_FACTOR = 100
PARTIAL_MIN_STEPS = 50_000
DROP_MAX_EVENTS = 200_000
HORIZON_CAP = 0.5  #: longest look-ahead of the end-of-sequence test [s]
#: A flight of the end that was in contact clear of the flat for at least this many of the
#: end-of-sequence test's intervals (``SV_CHECK_DT``: 0.1 period of the basis's first mode, its
#: first axial mode when it has one; 1.2 ms in all for the paper's rod) ends the sequence even
#: if that end's path comes back down: its return, after the rod turned in free flight, is a
#: new impact of that end (``next_end``), not a re-contact of a ringing rod, whose re-contacts
#: come within a few periods (a return the bound on the vibration hides: ``SV_T_RING``).
NEW_IMPACT_CHECKS = 100.0

#: The integrator's outputs, in the order of its ``out`` vector. "After the last contact" means
#: the state at the last separation; velocities are those of the floating frame (rigid body).
DROP_FIELDS: tuple[Field, ...] = (
    Field("e", "1", "-v_n,out / v_n,in of the tip's rigid-body normal velocity, gravity removed"),
    Field("e_raw", "1", "the same with the gravity impulse of the sequence kept"),
    Field("vx_out", "m/s", "x velocity of the centre of mass after the last contact"),
    Field("vy_out", "m/s", "y velocity of the centre of mass after the last contact"),
    Field("spin_out", "rad/s", "angular velocity after the last contact"),
    Field("duration", "s", "first touch to last separation"),
    Field("n_contacts", "1", "number of contacts"),
    Field("delta_p", "m", "permanent depth of the tip's deepest dent"),
    Field("scar_length", "m", "x-extent of the tip's contact-point path over all its contacts"),
    Field("sliding_length", "m", "sum over the tip's contacts of int v_t dt (signed)"),
    Field("slip_path", "m", "sum over the tip's contacts of int |v_t| dt"),
    Field("delta_max", "m", "largest interference"),
    Field("max_force", "N", "largest normal force"),
    Field("normal_impulse", "N s", "total normal impulse"),
    Field("tangential_impulse", "N s", "total tangential impulse"),
    Field("mu_apparent", "1", "|dvx / (dvy + g T)|: the paper's Eq. 28 on the frame velocities"),
    Field("vibration_energy", "J", "elastic (modal) energy after the last contact"),
    Field("rigid_kinetic_energy", "J", "rigid-body kinetic energy after the last contact"),
    Field("work_normal", "J", "work of the normal forces (negative: dissipated)"),
    Field("work_friction", "J", "work of friction (negative: dissipated)"),
    Field("work_damping", "J", "work of the modal damping (negative: dissipated)"),
    Field("energy_error", "1", "largest |T + V - E0 - W| / E0 over the run"),
    Field("next_end", "1", "the end that can land next (-1: none within the horizon)"),
    Field("next_time", "s", "lower bound of that landing, from the last separation"),
    Field("n_steps", "1", "Dormand-Prince steps"),
    Field("n_jumps", "1", "closed-form free-flight jumps"),
    Field("n_dents", "1", "number of dents"),
    Field("stick_time", "s", "total time spent sticking"),
    Field("angle_out", "rad", "rod angle at the last separation"),
    Field("t_final", "s", "time at which the end-of-sequence test was passed"),
    Field("potential_energy", "J", "gravity potential after the last contact (0 at first touch)"),
)
DROP_OUTPUT_FIELDS = tuple(f.name for f in DROP_FIELDS)
N_DROP_OUT = len(DROP_OUTPUT_FIELDS)
O = {name: i for i, name in enumerate(DROP_OUTPUT_FIELDS)}
(
    O_E,
    O_E_RAW,
    O_VX_OUT,
    O_VY_OUT,
    O_SPIN_OUT,
    O_DURATION,
    O_N_CONTACTS,
    O_DELTA_P,
    O_SCAR_LENGTH,
    O_SLIDING_LENGTH,
    O_SLIP_PATH,
    O_DELTA_MAX,
    O_MAX_FORCE,
    O_NORMAL_IMPULSE,
    O_TANGENTIAL_IMPULSE,
    O_MU_APPARENT,
    O_VIBRATION_ENERGY,
    O_RIGID_KINETIC_ENERGY,
    O_WORK_NORMAL,
    O_WORK_FRICTION,
    O_WORK_DAMPING,
    O_ENERGY_ERROR,
    O_NEXT_END,
    O_NEXT_TIME,
    O_N_STEPS,
    O_N_JUMPS,
    O_N_DENTS,
    O_STICK_TIME,
    O_ANGLE_OUT,
    O_T_FINAL,
    O_POTENTIAL_ENERGY,
) = range(N_DROP_OUT)

#: History columns: per end, interference [m], normal and tangential force [N], x of the
#: sphere's lowest point and height of its centre above the flat (R - delta) [m]; the centre of
#: mass (x, y) [m], the rotation phi [rad], the
#: tip's slip velocity [m/s] and the relative energy error [1].
DROP_HISTORY_FIELDS = (
    "t",
    "delta0",
    "fn0",
    "ft0",
    "x0",
    "y0",
    "delta1",
    "fn1",
    "ft1",
    "x1",
    "y1",
    "xc",
    "yc",
    "phi",
    "vt0",
    "energy_err",
)
N_DROP_HISTORY = len(DROP_HISTORY_FIELDS)
