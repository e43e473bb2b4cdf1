"""Convenience wrapper around the MDR reference (mdr.py)."""

from __future__ import annotations

import math

import numpy as np

import mdr


def mdr_impact(case, vt0, vn0, w0=0.0, nspr=600, nsteps=20000, nhist=0, margin=1.08):
    """Run the MDR reference for ``case``; returns dict of results (and history)."""
    T = case.hertz_time(vn0)
    dt = T / nsteps
    dmax, amax = mdr.normal_max(case.law_id, case.p, case.m, vn0, dt)
    xmax = margin * amax
    stride = max(1, int(1.2 * nsteps / max(nhist, 1)))
    out, hist = mdr.impact(case.law_id, case.p, case.R, case.m, case.I, case.Gs, case.mu,
                           vt0, vn0, w0, nspr, xmax, dt, nhist, stride)
    vx, vy, w = out[0], out[1], out[2]
    res = dict(vx=vx, vy=vy, w=w, e=out[3], T=out[4], dmax=out[5], erise=out[6],
               Et_end=out[7], diss=out[8], nsteps=int(out[9]), amax=amax, hist=hist)
    res["et"] = vx / vt0 if vt0 != 0 else math.nan
    res["vslip_out"] = vx + w * case.R
    return res
