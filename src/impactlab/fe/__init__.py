"""Finite-element reference for sphere-on-flat indentation (CalculiX, axisymmetric).

Usage::

    from impactlab.fe import indent
    from impactlab.materials import AISI_201, AISI_1010

    res = indent(AISI_1010, AISI_201, radius=8.8e-3, delta_max=[5e-6, 50e-6])
    res[0].loading_force, res[0].residual_depth

Needs ``ccx`` (Debian package ``calculix-ccx``) and the ``gmsh`` Python package (the ``fe``
extra); both are looked up only when a run starts, so ``import impactlab.fe`` works without
them. Method and verification: docs/fe.md; the dynamic impact (``impact``): docs/fe-dynamic.md.
"""

from impactlab.fe.cache import SCHEMA_VERSION, default_cache_dir
from impactlab.fe.ccx import (
    INSTALL_HINT,
    DamagedOutputError,
    NonFiniteOutputError,
    NotCalculixError,
    find_ccx,
)
from impactlab.fe.impact_result import ImpactResult
from impactlab.fe.impact_run import impact
from impactlab.fe.problem import MESH_GROWTH, SPHERE_KINDS, check_hardening, critical_interference
from impactlab.fe.result import SECTOR_FACTOR, IndentationResult
from impactlab.fe.run import DamagedRunsError, NotConvergedWarning, indent, indent_one
from impactlab.fe.tabulated import tabulated_law

__all__ = [
    "INSTALL_HINT",
    "MESH_GROWTH",
    "SCHEMA_VERSION",
    "SECTOR_FACTOR",
    "SPHERE_KINDS",
    "DamagedOutputError",
    "DamagedRunsError",
    "ImpactResult",
    "IndentationResult",
    "NonFiniteOutputError",
    "NotCalculixError",
    "NotConvergedWarning",
    "check_hardening",
    "critical_interference",
    "default_cache_dir",
    "find_ccx",
    "impact",
    "indent",
    "indent_one",
    "tabulated_law",
]
