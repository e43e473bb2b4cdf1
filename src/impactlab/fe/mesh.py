"""The axisymmetric mesh of the sphere and the flat, graded self-similarly from the contact point.

Coordinates are CalculiX's axisymmetric ones: x = r (radial, m), y = z (axial, m), the first
contact point at the origin, the flat below (y <= 0) and the sphere above (centre at y = R).
The element size grows linearly with the distance d from the contact point,
h(d) = h0 + g d, so the contact edge is resolved by about the same number of elements (1 / g)
at every contact radius from microns to millimetres (a self-similar mesh). Meshed with gmsh
(imported inside :func:`build_mesh`: ``import impactlab.fe`` works without it), 4-node quads.
"""

from __future__ import annotations

import inspect
import math
import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any

import numpy as np

from impactlab._validation import MissingExtraError

#: CAX4 faces as pairs of local corner indices (CalculiX/Abaqus face numbering S1..S4).
_FACES = ((0, 1), (1, 2), (2, 3), (3, 0))


@dataclass(frozen=True)
class MeshSpec:
    """What the mesh is built from (SI units).

    radius: sphere radius R [m]; h0: element size at the contact point [m]; growth: g, the
    element size per unit distance from the contact point [-]; flat_size: depth and radius of
    the flat's block [m]; contact_extent: radius of the surfaces that may touch [m];
    sphere_height: height of the meshed part of the sphere above the contact point [m]
    (<= R: a cap cut at that height, R: the hemisphere).
    """

    radius: float
    h0: float
    growth: float
    flat_size: float
    contact_extent: float
    sphere_height: float


@dataclass(frozen=True)
class Mesh:
    """A mesh of the two bodies: node coordinates (x = r, y = z) [m], CAX4 connectivity
    (0-based node indices, counter-clockwise), the element sets and the node and face sets
    used by the input deck (faces as (element index, face number 1..4))."""

    spec: MeshSpec
    nodes: np.ndarray
    elements: np.ndarray
    flat_elements: np.ndarray
    sphere_elements: np.ndarray
    flat_surface_faces: np.ndarray
    sphere_surface_faces: np.ndarray
    flat_surface_nodes: np.ndarray
    sphere_surface_nodes: np.ndarray
    flat_bottom_nodes: np.ndarray
    axis_nodes: np.ndarray
    sphere_top_nodes: np.ndarray
    sphere_nodes: np.ndarray

    @property
    def n_elements(self) -> int:
        """Number of elements of both bodies."""
        return int(self.elements.shape[0])

    def face_distance(self, faces: np.ndarray) -> np.ndarray:
        """Distance of each face's midpoint from the contact point [m]."""
        a, b = self._face_nodes(faces)
        mid = 0.5 * (self.nodes[a] + self.nodes[b])
        return np.asarray(np.hypot(*mid.T))

    def _face_nodes(self, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        el = self.elements[faces[:, 0]]
        k = faces[:, 1] - 1
        ia = np.array([f[0] for f in _FACES])[k]
        ib = np.array([f[1] for f in _FACES])[k]
        rows = np.arange(len(faces))
        return el[rows, ia], el[rows, ib]


def _mesh_body(gmsh: object, spec: MeshSpec, kind: str) -> tuple[np.ndarray, np.ndarray]:
    """Mesh one body alone (a fresh gmsh model); return (node coordinates, quads)."""
    g = gmsh  # the module, typed loosely: gmsh ships no stubs
    g.model.add(kind)  # type: ignore[attr-defined]
    geo = g.model.geo  # type: ignore[attr-defined]
    R, L = spec.radius, spec.flat_size
    if kind == "flat":
        p = [geo.addPoint(x, y, 0.0) for x, y in ((0, 0), (L, 0), (L, -L), (0, -L))]
        lines = [geo.addLine(p[i], p[(i + 1) % 4]) for i in range(4)]
    else:
        hs = spec.sphere_height
        xs = math.sqrt(max(R * R - (R - hs) ** 2, 0.0))
        c = geo.addPoint(0.0, R, 0.0)
        p0 = geo.addPoint(0.0, 0.0, 0.0)
        p1 = geo.addPoint(xs, hs, 0.0)
        p2 = geo.addPoint(0.0, hs, 0.0)
        lines = [geo.addCircleArc(p0, c, p1), geo.addLine(p1, p2), geo.addLine(p2, p0)]
    loop = geo.addCurveLoop(lines)
    geo.addPlaneSurface([loop])
    geo.synchronize()
    field = g.model.mesh.field  # type: ignore[attr-defined]
    f = field.add("MathEval")
    field.setString(f, "F", f"{float(spec.h0)!r} + {float(spec.growth)!r}*Sqrt(x*x + y*y)")
    field.setAsBackgroundMesh(f)
    g.model.mesh.generate(2)  # type: ignore[attr-defined]
    tags, coords, _ = g.model.mesh.getNodes()  # type: ignore[attr-defined]
    xy = np.asarray(coords, dtype=np.float64).reshape(-1, 3)[:, :2]
    index = {int(t): i for i, t in enumerate(tags)}
    types, _, conn = g.model.mesh.getElements(2)  # type: ignore[attr-defined]
    quads = [
        np.asarray(c, dtype=np.int64).reshape(-1, 4)
        for t, c in zip(types, conn, strict=True)
        if t == 3
    ]
    if len(quads) != 1 or any(t != 3 for t in types):
        raise RuntimeError("gmsh did not return an all-quad mesh")
    q = np.vectorize(index.__getitem__)(quads[0])
    g.model.remove()  # type: ignore[attr-defined]
    return xy, q


def _orient(nodes: np.ndarray, quads: np.ndarray) -> np.ndarray:
    """Quads with counter-clockwise corners (positive area in the x-y plane)."""
    x, y = nodes[quads, 0], nodes[quads, 1]
    area = 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
    out = quads.copy()
    out[area < 0] = out[area < 0][:, ::-1]
    return out


def _boundary_faces(quads: np.ndarray) -> np.ndarray:
    """(element, face number 1..4) of every face that belongs to one element only."""
    count: dict[tuple[int, int], list[tuple[int, int]]] = {}
    for e, q in enumerate(quads):
        for k, (i, j) in enumerate(_FACES):
            key = (min(q[i], q[j]), max(q[i], q[j]))
            count.setdefault(key, []).append((e, k + 1))
    return np.array([v[0] for v in count.values() if len(v) == 1], dtype=np.int64)


def build_mesh(spec: MeshSpec) -> Mesh:
    """Mesh the flat and the sphere with gmsh (ImportError with how to install it if missing)."""
    try:
        import gmsh
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise MissingExtraError(
            "impactlab.fe needs the gmsh Python package: pip install 'impactlab[fe]' "
            f"(or pip install gmsh); import failed: {exc}"
        ) from None
    with _sigint_kept():
        return _build(gmsh, spec)


@contextmanager
def _sigint_kept() -> Iterator[None]:
    """Keep Python's Ctrl-C handler as it was around gmsh's life: ``gmsh.initialize`` sets
    SIGINT to the system default (4.15: unless ``interruptible=False``) and ``finalize`` does
    not restore it, after which a Ctrl-C would end the interpreter instead of raising
    KeyboardInterrupt. Only the main thread can set a handler: elsewhere nothing is put back."""
    main = threading.current_thread() is threading.main_thread()
    handler = signal.getsignal(signal.SIGINT) if main else None
    try:
        yield
    finally:
        if handler is not None and signal.getsignal(signal.SIGINT) is not handler:
            signal.signal(signal.SIGINT, handler)


def _build(gmsh: Any, spec: MeshSpec) -> Mesh:
    """:func:`build_mesh` with gmsh imported."""
    if "interruptible" in inspect.signature(gmsh.initialize).parameters:
        gmsh.initialize(readConfigFiles=False, interruptible=False)
    else:  # a gmsh without the keyword: _sigint_kept puts the handler back
        gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.NumThreads", 1)
        gmsh.option.setNumber("Mesh.Algorithm", 8)
        gmsh.option.setNumber("Mesh.RecombineAll", 1)
        gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 3)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
        gmsh.option.setNumber("Mesh.Smoothing", 5)
        gmsh.option.setNumber("Mesh.RandomSeed", 1)
        flat_xy, flat_q = _mesh_body(gmsh, spec, "flat")
        sph_xy, sph_q = _mesh_body(gmsh, spec, "sphere")
    finally:
        gmsh.finalize()
    nodes = np.vstack([flat_xy, sph_xy])
    quads = np.vstack([_orient(flat_xy, flat_q), _orient(sph_xy, sph_q) + len(flat_xy)])
    n_flat = len(flat_q)
    return _classify(spec, nodes, quads, n_flat, len(flat_xy))


def _classify(spec: MeshSpec, nodes: np.ndarray, quads: np.ndarray, n_flat: int, nf: int) -> Mesh:
    """Node and face sets from the geometry of the boundary."""
    R, L = spec.radius, spec.flat_size
    tol = 1e-9 * max(R, L)
    x, y = nodes[:, 0], nodes[:, 1]
    faces = _boundary_faces(quads)
    el = quads[faces[:, 0]]
    k = faces[:, 1] - 1
    a = el[np.arange(len(faces)), np.array([f[0] for f in _FACES])[k]]
    b = el[np.arange(len(faces)), np.array([f[1] for f in _FACES])[k]]
    in_flat = faces[:, 0] < n_flat
    mid_x = 0.5 * (x[a] + x[b])
    ext = spec.contact_extent
    on_top = in_flat & (np.abs(y[a]) < tol) & (np.abs(y[b]) < tol) & (mid_x <= ext)
    on_arc = (
        ~in_flat
        & (np.abs(np.hypot(x[a], y[a] - R) - R) < 1e-6 * R)
        & (np.abs(np.hypot(x[b], y[b] - R) - R) < 1e-6 * R)
        & (mid_x <= ext)
    )
    flat_faces, sph_faces = faces[on_top], faces[on_arc]
    ids = np.arange(len(nodes))
    is_flat = ids < nf
    return Mesh(
        spec=spec,
        nodes=nodes,
        elements=quads,
        flat_elements=np.arange(n_flat),
        sphere_elements=np.arange(n_flat, len(quads)),
        flat_surface_faces=flat_faces,
        sphere_surface_faces=sph_faces,
        flat_surface_nodes=ids[is_flat & (np.abs(y) < tol)],
        sphere_surface_nodes=np.unique(np.concatenate([a[on_arc], b[on_arc]])),
        flat_bottom_nodes=ids[is_flat & (np.abs(y + L) < tol)],
        axis_nodes=ids[np.abs(x) < tol],
        sphere_top_nodes=ids[~is_flat & (np.abs(y - spec.sphere_height) < tol)],
        sphere_nodes=ids[~is_flat],
    )
