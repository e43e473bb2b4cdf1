"""The two materials of a contact: :class:`ContactPair` (SI units)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from impactlab._html import dataclass_html, dataclass_rows
from impactlab.materials.core import Material, reduced_modulus, reduced_shear_modulus, summary_line
from impactlab.materials.inputs import get_material

__all__ = ["ContactPair", "body_yields_first", "first_yield_factor"]


def first_yield_factor(nu: float) -> float:
    """Green's C(nu) = 1.295 exp(0.736 nu) [1]: the Hertz peak pressure at a material's first
    yield over its S_y (von Mises; Jackson & Green 2005, doi:10.1115/1.1866166; the paper's
    Eq. 15)."""
    return 1.295 * math.exp(0.736 * nu)


def body_yields_first(body: Material, flat: Material) -> bool:
    """Whether ``body`` yields before ``flat``: both carry the same Hertz pressure, so the one
    whose first-yield peak pressure C(nu) S_y (:func:`first_yield_factor`) is the smaller yields
    first. On a tie the smaller S_y yields first, the flat where the S_y are equal too. The one
    rule of impactlab for which body's S_y and nu a contact law takes."""
    p_body = first_yield_factor(body.nu) * body.yield_strength
    p_flat = first_yield_factor(flat.nu) * flat.yield_strength
    if p_body != p_flat:
        return p_body < p_flat
    return body.yield_strength < flat.yield_strength


@dataclass(frozen=True)
class ContactPair:
    """The two materials in contact: the impacting body's and the flat's.

    The quantities each contact law takes from the pair (documented per law in ``docs/laws``):

    - ``E_star``: reduced modulus, all laws.
    - ``yield_strength``: S_y of the material that yields first, the one with the smaller
      C(nu) S_y (:func:`body_yields_first`; for the paper's pair the flat's, 305 MPa), used by
      Ghaednia, Jackson-Green, Kogut-Komvopoulos and Brake. Thornton takes its limiting
      pressure p_y as a parameter (default C(nu) S_y of the same material).
    - ``nu``: Poisson's ratio of the material that yields first (Jackson-Green's C(nu), Brake's
      yield function).
    - Brinell hardness of both bodies: Brake combines them (Eq. 25, see its law page).
    """

    body: Material
    flat: Material

    def __post_init__(self) -> None:
        for side in ("body", "flat"):
            value = getattr(self, side)
            if type(value) is not Material:  # a name, values, a file (materials.inputs)
                object.__setattr__(self, side, get_material(value, f"ContactPair {side}"))

    @property
    def E_star(self) -> float:
        """Reduced modulus E* [Pa]."""
        return reduced_modulus(self.body, self.flat)

    @property
    def G_star(self) -> float:
        """Effective shear modulus G* [Pa]."""
        return reduced_shear_modulus(self.body, self.flat)

    @property
    def weaker(self) -> Material:
        """The material that yields first: the smaller C(nu) S_y (:func:`body_yields_first`)."""
        return self.body if body_yields_first(self.body, self.flat) else self.flat

    @property
    def yield_strength(self) -> float:
        """Yield strength of the material that yields first [Pa]."""
        return self.weaker.yield_strength

    @property
    def nu(self) -> float:
        """Poisson's ratio of the material that yields first."""
        return self.weaker.nu

    def _derived(self) -> dict[str, float]:
        return {"E_star": self.E_star, "G_star": self.G_star, "yield_strength": self.yield_strength}

    def _repr_html_(self) -> str:
        return dataclass_html(self, self._derived())

    def __str__(self) -> str:
        """One line in display units: the two materials by name, E*, G* and the yield strength
        of the material that yields first."""
        return summary_line("ContactPair", dataclass_rows(self, self._derived()))
