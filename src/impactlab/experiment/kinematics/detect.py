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
from typing import Any

import numpy as np

from impactlab.experiment.errors import ImpactNotFoundError, TooFewFramesError
from impactlab.experiment.kinematics.fits import robust_sigma, velocity_jumps
from impactlab.experiment.markers import MarkerTracks
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
#: The noise of the jumps comes from the flight before the largest one when it holds at least
#: this many samples.
MIN_NOISE_SAMPLES = 15


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


def _separations(t: np.ndarray, window: int) -> np.ndarray:
    """Per sample, the slope jump that a unit constant acceleration leaves (that of t^2 / 2:
    about the time between the centres of the two windows, changed by gaps in the record)."""
    return velocity_jumps(t, 0.5 * (t - t[0]) ** 2, window)


def _remove_constant_acceleration(jumps: np.ndarray, sep: np.ndarray) -> None:
    """A wrong time base leaves gravity's residue, a constant acceleration, in every frame of
    the origin's channels: its jump (the acceleration times ``sep``, which gaps in the record
    change) is removed where the median acceleration stands out of its spread."""
    with np.errstate(invalid="ignore", divide="ignore"):
        acc = jumps[:, :3] / sep[:, None]
    for c in range(3):
        med = float(np.nanmedian(acc[:, c])) if np.any(np.isfinite(acc[:, c])) else 0.0
        if abs(med) > 3.0 * robust_sigma(acc[:, c]):
            jumps[:, c] -= med * sep


def _flight_noise(
    jumps: np.ndarray, stat: np.ndarray, sig_c: np.ndarray, window: int
) -> np.ndarray:
    """The noise of each channel's jumps from the flight before the largest jump (the rod
    turning after an impact spreads the jumps of the whole record), when that flight holds
    enough samples; never above the whole record's (``sig_c``). Used only when the whole
    record's noise hides every jump: its peaks can shift into the turn after the impact."""
    i_max = int(np.nanargmax(stat))
    before = jumps[: max(i_max - window, 0)]
    if np.sum(np.isfinite(before[:, 0])) < MIN_NOISE_SAMPLES:
        return sig_c
    pre = np.array([max(robust_sigma(before[:, c]), 1e-9) for c in range(jumps.shape[1])])
    return np.minimum(sig_c, pre)


def _sharpest(z_velocity: np.ndarray, i: int, reach: int) -> int:
    """The impact's sample near the peak ``i`` of the combined jumps: where the origin's
    velocity jumps most (``z_velocity``, in noise sigmas) within ``reach`` samples, when that
    jump is impact-sized. The rate of turn keeps changing after the impact (the axis turning
    fast, its jumps large against a still rod's noise), which can move the combined peak a few
    frames late; the velocity's jump is sharp at the impact."""
    lo, hi = max(i - reach, 0), min(i + reach + 1, z_velocity.shape[0])
    size = np.sqrt(np.sum(z_velocity[lo:hi] ** 2, axis=1))
    if not np.any(np.isfinite(size)):
        return i
    j = lo + int(np.nanargmax(size))
    return j if size[j - lo] > IMPACT_SIGMAS else i


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
    _remove_constant_acceleration(jumps, _separations(t_ok, window))
    sig_c = np.array([max(robust_sigma(jumps[:, c]), 1e-9) for c in range(6)])
    stat = np.sqrt(np.sum((jumps / sig_c) ** 2, axis=1))
    if not np.nanmax(stat) > IMPACT_SIGMAS:  # a weak impact: the noise of the flight before
        stat = np.sqrt(np.sum((jumps / _flight_noise(jumps, stat, sig_c, window)) ** 2, axis=1))
    i_max = int(np.nanargmax(stat))
    jmax = float(stat[i_max])
    if not jmax > IMPACT_SIGMAS:
        raise ImpactNotFoundError(
            f"{src}: no impact found: the largest jump of the rod's velocity is {jmax:.3g} "
            f"noise sigmas (need > {IMPACT_SIGMAS:g}); is there an impact in the record? If "
            f"there is, it may be hidden by too little free flight before it in the record "
            f"(at least {window} frames are needed, {2 * window + MIN_NOISE_SAMPLES} let the "
            "noise be taken from that flight: the rod's turn after an impact spreads the "
            "jumps of the rest), by marker noise large for the impact's change of velocity, or "
            "by a wrong time base (times in another unit than seconds, a wrong frame rate)"
        )
    with np.errstate(invalid="ignore"):
        big = stat > max(IMPACT_SIGMAS, OTHERS_FRACTION * jmax)
    dt = float(np.median(np.diff(t_ok)))
    peaks = _peaks(stat, big, t_ok, 2 * window * dt)
    i_star = _sharpest(jumps[:, :3] / sig_c[:3], peaks[0], 2 * window)
    k_star = int(ok[i_star])
    later = peaks[1:]
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
        (float(t_ok[i_star]), *(float(t_ok[p]) for p in later)),
        float(t_ok[i_star] if i_max == peaks[0] else t_ok[i_max]),
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
    opts: dict[str, Any],
    src: str,
    tracks: MarkerTracks | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """The frames of the free flight before and after the impact; ``opts``: the options
    ``guard``, ``max_fit_frames``, ``min_fit_frames`` and ``window`` of ``measure_impact``. Too
    few after it where the record (or a marker of ``tracks``, the markers of the poses) ends:
    the error says so (:func:`record_end_note`)."""
    guard, max_fit_frames = opts["guard"], opts["max_fit_frames"]
    min_fit_frames = opts["min_fit_frames"]
    k_star = imp.k_star
    pre_all = ok[(ok <= k_star - guard) & (ok >= ok[min(imp.lo_i, ok.size - 1)])]
    post_all = ok[(ok >= k_star + guard) & (ok <= ok[max(imp.hi_i, 0)])]
    pre_fr = pre_all[-max_fit_frames:]
    post_fr = post_all[:max_fit_frames]
    for name, fr in (("before", pre_fr), ("after", post_fr)):
        if fr.size < min_fit_frames:
            ends = name == "after" and imp.hi_i >= ok.size - 1  # no later impact bounds it
            raise TooFewFramesError(
                f"{src}: only {fr.size} free-flight frames with a pose {name} the impact at "
                f"t = {imp.t_ref:.4f} s (frame {k_star}); need at least {min_fit_frames}"
                + (record_end_note(poses, ok, imp, opts["window"], tracks) if ends else "")
                + several_impacts_hint(imp)
            )
    return pre_fr, post_fr


def record_end_note(
    poses: Poses, ok: np.ndarray, imp: Impact, window: int, tracks: MarkerTracks | None
) -> str:
    """Why the free flight after the impact is short: where the record ends, where the poses
    end before it (the markers missing from then on, from ``tracks``), and that an impact this
    close to their end may lie later than found (the detector fits ``window`` frames after
    each frame: a jump in the last ones it cannot see)."""
    t, k_star, last = poses.time, imp.k_star, int(ok[-1])
    n = t.size
    if last == n - 1:
        note = (
            f": the record ends {n - 1 - k_star} frames after it (frame {n - 1}, t = {t[-1]:.4f} s)"
        )
        advice = "; record longer after the impact"
    else:
        note = (
            f": the markers' poses end {last - k_star} frames after it (frame {last}, t = "
            f"{t[last]:.4f} s; the record goes on to frame {n - 1})"
        )
        advice = "; the markers must be seen longer after the impact"
        if tracks is not None:
            seen = np.isfinite(tracks.positions[last + 1 :]).all(axis=2)
            gone = [lab for j, lab in enumerate(tracks.labels) if not seen[:, j].any()]
            if gone:
                note += f": marker {', '.join(gone)} is missing from frame {last + 1} on"
    between = int(np.count_nonzero(~poses.ok[k_star + 1 : last + 1]))
    if between:  # frames left out (a warning names them) or without 3 markers
        note += f"; {between} of the frames after it have no pose"
        advice = ""
    if last - k_star <= window + 1:
        note += (
            f"; an impact so close to the end of the poses is found from the frames before it "
            f"and may lie up to {last - k_star} frames later (at t = {t[k_star]:.4f} to "
            f"{t[last]:.4f} s)"
        )
    return note + advice


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
