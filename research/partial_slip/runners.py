"""One call per model for a sphere impact; every runner returns a dict with at least
vx, vy, w (final centre velocities / spin), e (normal COR), et (= vx/vt0), vslip_out."""

from __future__ import annotations

import math

import impactlab as il

from compact import Compact
from model import MDModel
from run_mdr import mdr_impact


def run_new(case, vt, vn, w0=0.0, n_springs=16, **kw):
    r = MDModel(case, n_springs, **kw).run(vt, vn, w0)
    r["vslip_out"] = r["vx"] + r["w"] * case.R
    return r


def run_exact(case, vt, vn, w0=0.0, nspr=600, nsteps=20000):
    return mdr_impact(case, vt, vn, w0, nspr=nspr, nsteps=nsteps)


def run_ty(case, vt, vn, w0=0.0):
    r = Compact(case, "TY").run(vt, vn, w0)
    r["vslip_out"] = r["vx"] + r["w"] * case.R
    return r


def run_tcc(case, vt, vn, w0=0.0):
    r = Compact(case, "TCC").run(vt, vn, w0)
    r["vslip_out"] = r["vx"] + r["w"] * case.R
    return r


def run_existing(case, vt, vn, w0=0.0, friction="mindlin"):
    """The frozen package's engine (friction='mindlin' by default)."""
    r = il.simulate(case.body, case.flat, law=case.law, law_params=case.law_params or None,
                    friction=friction, mu=case.mu, velocity=(vt, vn), spin=w0, gravity=False,
                    history=False)
    vx, vy = r.velocity_out
    return dict(vx=vx, vy=vy, w=r.spin_out, e=r.e, et=vx / vt if vt else math.nan,
                vslip_out=vx + r.spin_out * case.R)


def rigid_coulomb(case, vt, vn, e):
    """Rigid-body Coulomb (Stronge) for a sphere: slip throughout or slip-then-roll."""
    k = 1.0 + case.m * case.R**2 / case.I
    Pn = case.m * (1.0 + e) * abs(vn)
    if vt - k * case.mu * Pn / case.m >= 0.0:  # slides throughout
        Pt = -case.mu * Pn
    else:
        Pt = -case.m * vt / k
    vx = vt + Pt / case.m
    w = case.R * Pt / case.I
    return dict(vx=vx, w=w, et=vx / vt if vt else math.nan, vslip_out=vx + w * case.R, e=e)


RUNNERS = {"new": run_new, "exact": run_exact, "TY": run_ty, "TCC": run_tcc,
           "existing": run_existing}
