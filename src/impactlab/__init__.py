"""impactlab: elastic-plastic oblique impacts with friction."""

from impactlab.contact import get_law, law_names
from impactlab.materials import AISI_201, AISI_1010, ContactPair, Material, get_material

__version__ = "0.1.0"

__all__ = [
    "AISI_1010",
    "AISI_201",
    "ContactPair",
    "Material",
    "__version__",
    "get_law",
    "get_material",
    "law_names",
]
