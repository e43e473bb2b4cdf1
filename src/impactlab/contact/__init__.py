"""Normal contact laws for a sphere (or a rod's hemispherical tip) on a flat.

Usage::

    from impactlab.contact import get_law
    from impactlab.materials import AISI_201, AISI_1010, ContactPair

    model = get_law("ghaednia").build(ContactPair(AISI_201, AISI_1010), radius=8.8e-3)
    model.force(50e-6)            # loading force [N] at 50 um
    model.unload(50e-6).delta_r   # residual depth [m]

The compiled kernels for the engine live in ``impactlab.contact.kernels``.
"""

from impactlab.contact.base import ContactLaw, ContactModel, Parameter, UnloadingBranch
from impactlab.contact.energy import ReboundResult, loading_work, quasi_static_rebound
from impactlab.contact.registry import get_law, law_names
from impactlab.contact.thornton import thornton_restitution, thornton_yield_velocity

__all__ = [
    "ContactLaw",
    "ContactModel",
    "Parameter",
    "ReboundResult",
    "UnloadingBranch",
    "get_law",
    "law_names",
    "loading_work",
    "quasi_static_rebound",
    "thornton_restitution",
    "thornton_yield_velocity",
]
