"""Python side of the contact laws: a law builds a validated, compiled-ready ``ContactModel``."""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from impactlab._validation import check_nonnegative, check_positive
from impactlab.contact import kernels as k
from impactlab.materials import ContactPair


@dataclass(frozen=True)
class Parameter:
    """A law parameter with its default, unit and meaning (shown by ``impactlab laws``)."""

    name: str
    default: float
    unit: str
    description: str


@dataclass(frozen=True)
class UnloadingBranch:
    """Unloading from the maximum (delta_m [m], F_m [N]): Hertzian with radius R_r [m] about the
    residual depth delta_r [m]."""

    delta_m: float
    F_m: float
    delta_r: float
    R_r: float
    E_star: float

    def force(self, delta: Any) -> np.ndarray:
        """Unloading force [N] at interferences ``delta`` [m] (0 below delta_r)."""
        d = np.clip(np.asarray(delta, dtype=float) - self.delta_r, 0.0, None)
        return 4.0 / 3.0 * self.E_star * math.sqrt(self.R_r) * d**1.5

    def energy_returned(self) -> float:
        """Elastic energy recovered on unloading from delta_m to delta_r [J]."""
        d = self.delta_m - self.delta_r
        return 8.0 / 15.0 * self.E_star * math.sqrt(self.R_r) * d**2.5


@dataclass(frozen=True)
class ContactModel:
    """A contact law with all its parameters fixed: what the impact engine consumes.

    ``law_id`` and ``params`` are the compiled representation (see ``contact.kernels``).
    """

    name: str
    law_id: int
    params: np.ndarray = field(repr=False)

    def __post_init__(self) -> None:
        p = np.array(self.params, dtype=np.float64)
        p.setflags(write=False)
        object.__setattr__(self, "params", p)

    @property
    def E_star(self) -> float:
        """Reduced modulus [Pa]."""
        return float(self.params[k.P_ESTAR])

    @property
    def radius(self) -> float:
        """Sphere (tip) radius [m]."""
        return float(self.params[k.P_R])

    @property
    def yield_onset(self) -> tuple[float, float]:
        """(delta_y [m], F_y [N]) where the law leaves the Hertz curve (inf, inf for Hertz)."""
        return float(self.params[k.P_DY]), float(self.params[k.P_FY])

    @property
    def max_interference(self) -> float:
        """Largest interference for which the law is valid [m]."""
        return float(self.params[k.P_DLIM])

    def check_interference(self, delta: Any) -> np.ndarray:
        """Array of ``delta``; ValueError if any value is negative, NaN or past the validity limit."""
        d = np.asarray(delta, dtype=np.float64)
        if not np.all(np.isfinite(d)):
            raise ValueError("delta must be finite")
        if np.any(d < 0.0):
            raise ValueError(f"delta must be >= 0 m, got min {float(d.min())!r}")
        if np.any(d > self.max_interference):
            raise ValueError(
                f"delta = {float(d.max())!r} m is outside the validity range of the {self.name!r} "
                f"law (delta <= {self.max_interference!r} m)"
            )
        return d

    def force(self, delta: Any) -> np.ndarray:
        """Loading force [N] at interferences ``delta`` [m]."""
        d = self.check_interference(delta)
        return k.loading_force_array(self.law_id, self.params, np.atleast_1d(d)).reshape(d.shape)

    def unload(self, delta_m: float) -> UnloadingBranch:
        """The unloading branch after loading to ``delta_m`` [m]."""
        dm = float(self.check_interference(check_nonnegative("delta_m", delta_m, "m")))
        F_m = float(k.loading_force(self.law_id, self.params, dm))
        d_r = float(k.residual_depth(self.law_id, self.params, dm, F_m))
        R_r = float(k.unloading_radius(self.E_star, dm, F_m, d_r)) if dm > 0 else self.radius
        return UnloadingBranch(dm, F_m, d_r, R_r, self.E_star)


class ContactLaw(ABC):
    """A registered normal contact law for a sphere (radius R) on a flat.

    Subclasses declare their name, compiled id, literature reference and validity, and turn a
    contact pair plus parameters into a ``ContactModel``.
    """

    name: ClassVar[str]
    law_id: ClassVar[int]
    title: ClassVar[str]
    reference: ClassVar[str]
    doi: ClassVar[str]
    validity: ClassVar[str]
    parameters: ClassVar[tuple[Parameter, ...]] = ()

    def build(self, pair: ContactPair, radius: float, **params: float) -> ContactModel:
        """Validate ``params`` (unknown names are an error) and build the model for ``pair``."""
        R = check_positive("radius", radius, "m")
        known = {q.name: q for q in self.parameters}
        unknown = sorted(set(params) - set(known))
        if unknown:
            raise ValueError(
                f"unknown parameter(s) {unknown} for contact law {self.name!r}; "
                f"known: {sorted(known) or 'none'}"
            )
        values = {q.name: float(params.get(q.name, q.default)) for q in self.parameters}
        p = np.full(k.NPARAM, np.nan)
        p[k.P_ESTAR] = pair.E_star
        p[k.P_R] = R
        p[k.P_SY] = pair.yield_strength
        p[k.P_NU] = pair.nu
        p[k.P_DLIM] = R
        self._fill(p, pair, values)
        return ContactModel(self.name, self.law_id, p)

    @abstractmethod
    def _fill(self, p: np.ndarray, pair: ContactPair, values: dict[str, float]) -> None:
        """Fill the law-specific slots of ``p`` (and P_DY, P_FY, P_DLIM); validate ``values``."""
