"""Normal contact laws for a sphere (or a rod's hemispherical tip) on a flat.

Usage::

    from impactlab.contact import Law, get_law
    from impactlab.materials import AISI_201, AISI_1010, ContactPair

    model = get_law(Law.GHAEDNIA).build(ContactPair(AISI_201, AISI_1010), radius=8.8e-3)
    model.force(50e-6)            # loading force [N] at 50 um
    model.unload(50e-6).delta_r   # residual depth [m]

Laws are keyed by :class:`Law` (``Law.GHAEDNIA == "ghaednia"``; plain names work too); each law
and each built model carries its sources in ``.references``. The compiled kernels for the engine
live in ``impactlab.contact.kernels``.
"""

from impactlab.contact.base import ContactLaw, ContactModel, Parameter, UnloadingBranch
from impactlab.contact.energy import ReboundResult, loading_work, quasi_static_rebound
from impactlab.contact.indentation_data import IndentationCurves, shipped_curves
from impactlab.contact.names import Law
from impactlab.contact.registry import get_law, law_names
from impactlab.contact.tabulated import Tabulated, tabulated_model
from impactlab.contact.thornton import thornton_restitution, thornton_yield_velocity

__all__ = [
    "ContactLaw",
    "ContactModel",
    "IndentationCurves",
    "Law",
    "Parameter",
    "ReboundResult",
    "Tabulated",
    "UnloadingBranch",
    "get_law",
    "law_names",
    "loading_work",
    "quasi_static_rebound",
    "shipped_curves",
    "tabulated_model",
    "thornton_restitution",
    "thornton_yield_velocity",
]
