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

A law of one's own (measured indentation tables, or Python callables F(delta) and
delta_r(delta_max)): ``register_law(name, ...)`` (``contact.registered``; the tabulated law under
its own name), then ``simulate(..., law=name)`` as for any law.
"""

from impactlab.contact.base import ContactLaw, ContactModel, Parameter, UnloadingBranch
from impactlab.contact.energy import ReboundResult, loading_work, quasi_static_rebound
from impactlab.contact.indentation_data import IndentationCurves, shipped_curves
from impactlab.contact.law_file import read_law_file
from impactlab.contact.names import Law
from impactlab.contact.registered import RegisteredLaw
from impactlab.contact.registry import (
    builtin_law_names,
    get_law,
    law_names,
    register_law,
    registered_laws,
    unregister_law,
)
from impactlab.contact.tabulated import Tabulated, tabulated_model
from impactlab.contact.thornton import thornton_restitution, thornton_yield_velocity

__all__ = [
    "ContactLaw",
    "ContactModel",
    "IndentationCurves",
    "Law",
    "Parameter",
    "ReboundResult",
    "RegisteredLaw",
    "Tabulated",
    "UnloadingBranch",
    "builtin_law_names",
    "get_law",
    "law_names",
    "loading_work",
    "quasi_static_rebound",
    "read_law_file",
    "register_law",
    "registered_laws",
    "shipped_curves",
    "tabulated_model",
    "thornton_restitution",
    "thornton_yield_velocity",
    "unregister_law",
]
