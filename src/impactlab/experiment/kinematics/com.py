"""The centre of mass from the flight: the body point that moves ballistically."""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

from impactlab.experiment.rigid import Poses

__all__ = ["estimate_com", "smoothed_rotations"]


def smoothed_rotations(poses: Poses, fr: np.ndarray, t_ref: float) -> np.ndarray:
    """Rotations of a free-flight segment smoothed by a constant-spin model: rotation vectors
    relative to the middle frame fitted linearly in time (torque-free planar flight)."""
    R = poses.rotation[fr]
    mid = fr.size // 2
    R0 = R[mid]
    rv = Rotation.from_matrix(np.einsum("nij,kj->nik", R, R0)).as_rotvec()  # R_k R0^T
    tau = poses.time[fr] - t_ref
    A = np.column_stack([np.ones_like(tau), tau])
    coef, *_ = np.linalg.lstsq(A, rv, rcond=None)
    return np.einsum("nij,jk->nik", Rotation.from_rotvec(A @ coef).as_matrix(), R0)


def estimate_com(
    poses: Poses,
    segments: list[np.ndarray],
    t_ref: float,
    up: np.ndarray,
    g: float,
    ridge: float = 1e-3,
    min_turn: float = 0.05,
) -> tuple[np.ndarray, np.ndarray]:
    """The body point (reference frame) that moves ballistically in every segment.

    Unknowns: p (3) and per segment c0, c1 (3 each); rows: R_k p - c0 - c1 tau_k = -t_k - g tau^2/2
    up. Only segments in which the rod turns by at least ``min_turn`` [rad] are used (a still
    rod says nothing about p), with their rotations smoothed by a constant-spin fit (noisy R_k
    would bias p towards the cluster centroid: errors in variables). The component of p along the
    spin axis does not change the motion (planar flight); a weak ridge term pulls it to the
    cluster centroid. Returns (p, covariance of p)."""
    used = []
    for fr in segments:
        if fr.size < 4:
            continue
        turn = Rotation.from_matrix(poses.rotation[fr[-1]] @ poses.rotation[fr[0]].T).magnitude()
        if turn >= min_turn:
            used.append(fr)
    if not used:
        return np.zeros(3), np.diag(np.full(3, np.inf))
    nseg = len(used)
    ncol = 3 + 6 * nseg
    rows: list[np.ndarray] = []
    rhs: list[np.ndarray] = []
    for s, fr in enumerate(used):
        tau = poses.time[fr] - t_ref
        Rs = smoothed_rotations(poses, fr, t_ref)
        for k, tk, Rk in zip(fr, tau, Rs, strict=True):
            blk = np.zeros((3, ncol))
            blk[:, :3] = Rk
            blk[:, 3 + 6 * s : 6 + 6 * s] = -np.eye(3)
            blk[:, 6 + 6 * s : 9 + 6 * s] = -tk * np.eye(3)
            rows.append(blk)
            rhs.append(-poses.translation[k] - 0.5 * g * tk * tk * up)
    A = np.vstack(rows)
    b = np.concatenate(rhs)
    reg = np.zeros((3, ncol))
    reg[:, :3] = ridge * np.eye(3)
    Ar = np.vstack([A, reg])
    br = np.concatenate([b, np.zeros(3)])
    x, *_ = np.linalg.lstsq(Ar, br, rcond=None)
    res = b - A @ x
    dof = max(A.shape[0] - ncol, 1)
    s2 = float(res @ res) / dof
    cov = s2 * np.linalg.pinv(Ar.T @ Ar)
    return x[:3], cov[:3, :3]
