"""Impact detection in marker tracks and the free-flight segments around it.

Jumps of the cluster's velocity and rate of turn (straight-line fits to ``window`` frames on
either side of each frame, gravity removed and the velocity's median jump too, so that a wrong
time base, which leaves a jump in every frame, cannot fake one), in units of their robust noise,
are combined. The jumps above
``IMPACT_SIGMAS`` and ``OTHERS_FRACTION`` of the largest are the impacts: the first one is the
drop's impact, the others (a second bounce) bound the free flight.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from impactlab.experiment.errors import ImpactNotFoundError, TooFewFramesError
from impactlab.experiment.kinematics.fits import robust_sigma, velocity_jumps
from impactlab.experiment.rigid import Poses

__all__ = [
    "IMPACT_SIGMAS",
    "OTHERS_FRACTION",
    "Impact",
    "detect_impact",
    "free_flight",
    "later_impact_note",
    "several_impacts_hint",
]

#: A jump must exceed this many noise sigmas to be an impact.
IMPACT_SIGMAS = 12.0
#: ... and this fraction of the largest jump of the record.
OTHERS_FRACTION = 0.3


@dataclass(frozen=True)
class Impact:
    """The detected impact: frame ``k_star``, time ``t_ref`` [s], and the indices (into the
    frames with a pose) ``lo_i``, ``hi_i`` bounding the free flight (other impacts);
    ``jumps``: the times [s] of every impact-sized jump, this one included, in time order;
    ``largest``: the time of the largest."""

    k_star: int
    t_ref: float
    lo_i: int
    hi_i: int
    jumps: tuple[float, ...] = ()
    largest: float = 0.0


def _times(ts: tuple[float, ...] | list[float]) -> str:
    return ", ".join(f"{t:.4f}" for t in ts)


def _peaks(stat: np.ndarray, above: np.ndarray, t: np.ndarray, span: float) -> list[int]:
    """The impacts among the runs of ``above`` samples: the largest sample of each run, and of
    the runs' peaks less than ``span`` [s] after a group's first (one impact's neighbourhood:
    the rod's turn after it can lift the jumps above the threshold again) the largest."""
    idx = np.flatnonzero(above)
    if idx.size == 0:
        return []
    runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)
    peaks = [int(r[np.nanargmax(stat[r])]) for r in runs]
    groups: list[list[int]] = [[peaks[0]]]
    for q in peaks[1:]:
        if t[q] - t[groups[-1][0]] < span:
            groups[-1].append(q)
        else:
            groups.append([q])
    return [max(g, key=lambda q: float(stat[q])) for g in groups]


def detect_impact(
    poses: Poses,
    ok: np.ndarray,
    reference: np.ndarray,
    upv: np.ndarray,
    g: float,
    window: int,
    src: str,
) -> Impact:
    """Jumps of the velocity of the cluster origin and of the rate of turn of the cluster's
    principal axis, each in units of its robust noise, combined; the first of the impact-sized
    ones is the impact (module docstring)."""
    t_ok = poses.time[ok]
    _, _, vt_ref = np.linalg.svd(reference - reference.mean(axis=0))
    spread = float(np.ptp((reference - reference.mean(axis=0)) @ vt_ref[0]))
    chans = np.column_stack(
        [
            poses.translation[ok] + 0.5 * g * ((t_ok - t_ok[0]) ** 2)[:, None] * upv,
            np.einsum("nij,j->ni", poses.rotation[ok], vt_ref[0]) * spread,
        ]
    )
    jumps = np.column_stack([velocity_jumps(t_ok, chans[:, c], window) for c in range(6)])
    if not np.any(np.isfinite(jumps[:, 0])):
        raise TooFewFramesError(f"{src}: too few frames ({ok.size}) to find the impact")
    sig_c = np.array([max(robust_sigma(jumps[:, c]), 1e-9) for c in range(6)])
    # a wrong time base leaves gravity's jump in every frame: the median removes it
    median = np.nanmedian(jumps[:, :3], axis=0)
    jumps[:, :3] -= np.where(np.abs(median) > 3.0 * sig_c[:3], median, 0.0)
    stat = np.sqrt(np.sum((jumps / sig_c) ** 2, axis=1))
    i_max = int(np.nanargmax(stat))
    jmax = float(stat[i_max])
    if not jmax > IMPACT_SIGMAS:
        raise ImpactNotFoundError(
            f"{src}: no impact found: the largest jump of the rod's velocity is {jmax:.3g} "
            f"noise sigmas (need > {IMPACT_SIGMAS:g}); is there an impact in the record?"
        )
    with np.errstate(invalid="ignore"):
        big = stat > max(IMPACT_SIGMAS, OTHERS_FRACTION * jmax)
    dt = float(np.median(np.diff(t_ok)))
    peaks = _peaks(stat, big, t_ok, 2 * window * dt)
    i_star = peaks[0]
    k_star = int(ok[i_star])
    later = [p for p in peaks if p > i_star]
    lo_i = 0
    hi_i = ok.size - 1
    if later:  # the flight after ends a few frames before the next jump's peak (by time: gaps)
        t_cut = t_ok[later[0]] - (window // 2 + 1) * dt
        hi_i = max(int(np.searchsorted(t_ok, t_cut, side="right")) - 1, i_star)
    return Impact(
        k_star,
        float(poses.time[k_star]),
        lo_i,
        hi_i,
        tuple(float(t_ok[p]) for p in peaks),
        float(t_ok[i_max]),
    )


def later_impact_note(imp: Impact) -> str | None:
    """A warning when a larger jump follows the analysed (first) impact, else None."""
    if len(imp.jumps) < 2 or imp.largest <= imp.t_ref:
        return None
    return (
        f"a larger jump of the rod's velocity at t = {imp.largest:.4f} s (a second impact?) "
        f"follows the impact at t = {imp.t_ref:.4f} s; the first one is analysed and the fit "
        "after it ends before the next"
    )


def free_flight(
    poses: Poses,
    ok: np.ndarray,
    imp: Impact,
    guard: int,
    max_fit_frames: int,
    min_fit_frames: int,
    src: str,
) -> tuple[np.ndarray, np.ndarray]:
    """The frames of the free flight before and after the impact (at most ``max_fit_frames``)."""
    k_star = imp.k_star
    pre_all = ok[(ok <= k_star - guard) & (ok >= ok[min(imp.lo_i, ok.size - 1)])]
    post_all = ok[(ok >= k_star + guard) & (ok <= ok[max(imp.hi_i, 0)])]
    pre_fr = pre_all[-max_fit_frames:]
    post_fr = post_all[:max_fit_frames]
    for name, fr in (("before", pre_fr), ("after", post_fr)):
        if fr.size < min_fit_frames:
            raise TooFewFramesError(
                f"{src}: only {fr.size} free-flight frames with a pose {name} the impact at "
                f"t = {imp.t_ref:.4f} s (frame {k_star}); need at least {min_fit_frames}"
                + several_impacts_hint(imp)
            )
    return pre_fr, post_fr


def several_impacts_hint(imp: Impact) -> str:
    """For an error about the frames around the impact: the other jumps found and how to cut
    the record ("" when there is one jump only)."""
    if len(imp.jumps) < 2:
        return ""
    return (
        f"; several impact-sized jumps of the rod's velocity found, at t = {_times(imp.jumps)} "
        f"s, and the first is taken as the impact: if it is not the drop's impact, cut the "
        f"record so that it starts after t = {imp.t_ref:.4f} s, in the free fall before the "
        "impact"
    )
