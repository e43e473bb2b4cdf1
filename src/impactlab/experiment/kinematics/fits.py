"""Free-flight fits of the rod's motion: impact detection jumps, ballistic segment fits.

A segment fit is one multivariate least-squares fit with the design [1, tau]: the horizontal and
out-of-plane coordinates of C linear in time, the vertical one quadratic with the known gravity,
the rod angle linear; the covariance of the coefficients is S (x) (A^T A)^-1 with S the residual
covariance of the four coordinates.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from impactlab.experiment.rigid import Poses

__all__ = [
    "SegmentFit",
    "fit_segment",
    "grow_segment",
    "robust_sigma",
    "segment_data",
    "trimmed_fit",
    "velocity_jumps",
]


@dataclass(frozen=True)
class SegmentFit:
    """One free-flight fit. ``frames``: indices into the tracks; ``tau`` [s] times relative to the
    reference instant; ``data`` (n, 4): X, Y, Z of C [m] and the rod angle [rad] in the impact
    frame; ``coef`` (2, 4): offset and rate per coordinate (Y with gravity removed:
    Y + g tau^2/2); ``cov`` (8, 8) covariance of coef.T.ravel() (order X0, X1, Y0, Y1, Z0, Z1,
    angle0, angle1); ``rms`` (4,) residual RMS; ``trimmed``: frames dropped at the far end."""

    frames: np.ndarray
    tau: np.ndarray
    data: np.ndarray
    coef: np.ndarray
    cov: np.ndarray
    rms: np.ndarray
    trimmed: int = 0

    @property
    def n(self) -> int:
        return int(self.frames.size)


def _line_slopes(t: np.ndarray, h: np.ndarray) -> float:
    tc = t - t.mean()
    return float(np.dot(tc, h - h.mean()) / np.dot(tc, tc))


def velocity_jumps(t: np.ndarray, h: np.ndarray, window: int) -> np.ndarray:
    """Jump of the slope of h at each sample: slope of the ``window`` samples after minus that of
    the ``window`` samples before (the sample itself excluded); NaN where a side is short."""
    n = t.size
    out = np.full(n, np.nan)
    for i in range(window, n - window):
        sb = _line_slopes(t[i - window : i], h[i - window : i])
        sa = _line_slopes(t[i + 1 : i + 1 + window], h[i + 1 : i + 1 + window])
        out[i] = sa - sb
    return out


def robust_sigma(x: np.ndarray) -> float:
    x = x[np.isfinite(x)]
    if x.size == 0:
        return 0.0
    return float(1.4826 * np.median(np.abs(x - np.median(x))))


def fit_segment(
    tau: np.ndarray, data: np.ndarray, g: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Multivariate least squares with design [1, tau]; Y gets + g tau^2 / 2 (known gravity).
    Returns (coef (2, 4), cov (8, 8), residuals (n, 4), rms (4,))."""
    D = data.copy()
    D[:, 1] = D[:, 1] + 0.5 * g * tau * tau
    A = np.column_stack([np.ones_like(tau), tau])
    AtA_inv = np.linalg.inv(A.T @ A)
    coef = AtA_inv @ A.T @ D
    E = D - A @ coef
    n = tau.size
    S = (E.T @ E) / max(n - 2, 1)
    cov = np.kron(S, AtA_inv)
    rms = np.sqrt(np.mean(E * E, axis=0))
    return coef, cov, E, rms


def segment_data(
    poses: Poses,
    frames: np.ndarray,
    com_body: np.ndarray,
    axis_body: np.ndarray,
    axes: np.ndarray,
    origin: np.ndarray,
) -> np.ndarray:
    """(n, 4): X, Y, Z of C in the impact frame [m], the rod angle [rad] (unwrapped)."""
    R = poses.rotation[frames]
    t = poses.translation[frames]
    c = np.einsum("nij,j->ni", R, com_body) + t - origin
    u = -np.einsum("nij,j->ni", R, axis_body)  # tip -> C
    xh, yh, zh = axes
    X, Y, Z = c @ xh, c @ yh, c @ zh
    th = np.unwrap(np.arctan2(u @ yh, u @ xh))
    return np.column_stack([X, Y, Z, th])


def _prediction_z(
    a: np.ndarray, d: np.ndarray, coef: np.ndarray, AtA_inv: np.ndarray, S: np.ndarray
) -> float:
    """Largest |residual| / prediction sigma over the coordinates of one new frame."""
    var = S * (1.0 + a @ AtA_inv @ a)
    return float(np.max(np.abs(d - a @ coef) / np.sqrt(var)))


def grow_segment(
    A_all: np.ndarray, D: np.ndarray, n0: int, threshold: float, floor: np.ndarray
) -> list[int]:
    """Rows of a segment grown outwards from its first ``n0`` rows (the design ``A_all`` and the
    data ``D``, ordered from the impact outwards): the next row is taken while every coordinate
    lies within ``threshold`` prediction sigmas of the fit so far (``floor``: the smallest
    residual variance per coordinate); a single disagreeing row is skipped as an outlier, two in
    a row end the segment."""
    keep = list(range(n0))
    j = n0
    while j < A_all.shape[0]:
        A = A_all[keep]
        AtA_inv = np.linalg.inv(A.T @ A)
        coef = AtA_inv @ A.T @ D[keep]
        E = D[keep] - A @ coef
        S = np.maximum(np.sum(E * E, axis=0) / max(len(keep) - A.shape[1], 1), floor)
        if _prediction_z(A_all[j], D[j], coef, AtA_inv, S) <= threshold:
            keep.append(j)
            j += 1
            continue
        if (
            j + 1 < A_all.shape[0]
            and _prediction_z(A_all[j + 1], D[j + 1], coef, AtA_inv, S) <= threshold
        ):
            j += 1  # a single outlier: skip it
            continue
        break
    return keep


def trimmed_fit(
    poses: Poses,
    frames: np.ndarray,
    far_end: str,
    t_ref: float,
    com_body: np.ndarray,
    axis_body: np.ndarray,
    axes: np.ndarray,
    origin: np.ndarray,
    g: float,
    min_frames: int,
    threshold: float = 5.0,
    n_start: int = 10,
) -> SegmentFit:
    """Fit a free-flight segment grown outwards from the impact (:func:`grow_segment`): start
    with the ``n_start`` frames nearest to it, then add one frame at a time while it agrees with
    the prediction of the current fit (every coordinate within ``threshold`` prediction sigmas).
    A single disagreeing frame is dropped as an outlier; two in a row end the segment (the rod
    still held before its release, a second bounce, the rod leaving the camera's volume)."""
    order = frames[::-1] if far_end == "start" else frames
    tau_all = poses.time[order] - t_ref
    data_all = segment_data(poses, order, com_body, axis_body, axes, origin)
    D = data_all.copy()
    D[:, 1] = D[:, 1] + 0.5 * g * tau_all * tau_all
    A_all = np.column_stack([np.ones_like(tau_all), tau_all])
    floor = np.array([1e-6, 1e-6, 1e-6, 1e-6]) ** 2
    n0 = min(max(min_frames, n_start), order.size)
    keep = grow_segment(A_all, D, n0, threshold, floor)
    sel = np.sort(order[keep])
    tau = poses.time[sel] - t_ref
    data = segment_data(poses, sel, com_body, axis_body, axes, origin)
    coef, cov, _, rms = fit_segment(tau, data, g)
    return SegmentFit(sel, tau, data, coef, cov, rms, int(order.size - len(keep)))
