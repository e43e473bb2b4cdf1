"""Normal contact laws for a sphere (or a rod's hemispherical tip) on a flat."""

from impactlab.contact.base import ContactLaw, ContactModel, Parameter, UnloadingBranch
from impactlab.contact.registry import get_law, law_names

__all__ = ["ContactLaw", "ContactModel", "Parameter", "UnloadingBranch", "get_law", "law_names"]
