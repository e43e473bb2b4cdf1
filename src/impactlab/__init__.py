"""impactlab: elastic-plastic oblique impacts with friction.

The most used names are importable from the top level::

    import math
    import impactlab as il
    r = il.simulate(il.Rod.paper(), il.AISI_1010, law="ghaednia", friction="coulomb", mu=0.2,
                    angle=math.radians(20), velocity=(0.0, -1.41))

Subpackages: ``contact`` (laws), ``dynamics`` (engine), ``analytic`` (the paper's inversion),
``experiment`` (raw files), ``sweep`` (studies), ``calibrate`` (parameters and models from
measured drops), ``explain`` (which physics explains measured drops), ``paper`` (data and
reproduction), ``fe`` (the finite-element reference); the heavier ones are imported on first
use (``il.sweep``), so ``import impactlab`` stays quick.
"""

# first: numba's cache folder and the compile notice, before any compiled function is defined
from impactlab import _runtime  # noqa: F401
from impactlab._validation import ImplausibleInputWarning
from impactlab._version import __version__
from impactlab.analytic import InversionResult, Measured, invert
from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod, Sphere
from impactlab.contact import get_law, law_names
from impactlab.dynamics import (
    BatchResult,
    DropBatchResult,
    DropResult,
    ImpactResult,
    rerun,
    simulate,
    simulate_batch,
    simulate_drop,
    simulate_drops,
)
from impactlab.materials import AISI_201, AISI_1010, ContactPair, Material, get_material

#: Subpackages imported on first use as attributes (``il.sweep``), not by ``import impactlab``.
_LAZY_SUBPACKAGES = (
    "calibrate",
    "experiment",
    "explain",
    "fe",
    "paper",
    "sweep",
    "verification",
)


def __getattr__(name: str) -> object:
    """``impactlab.sweep`` and the others of ``_LAZY_SUBPACKAGES``, imported on first use."""
    if name in _LAZY_SUBPACKAGES:
        import importlib

        return importlib.import_module(f"impactlab.{name}")
    raise AttributeError(f"module 'impactlab' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), *_LAZY_SUBPACKAGES})


__all__ = [
    "AISI_201",
    "AISI_1010",
    "PAPER_ROD",
    "BatchResult",
    "ContactPair",
    "DropBatchResult",
    "DropResult",
    "FlexibleRod",
    "ImpactResult",
    "ImplausibleInputWarning",
    "InversionResult",
    "Material",
    "Measured",
    "Rod",
    "Sphere",
    "__version__",
    "get_law",
    "get_material",
    "invert",
    "law_names",
    "rerun",
    "simulate",
    "simulate_batch",
    "simulate_drop",
    "simulate_drops",
]
