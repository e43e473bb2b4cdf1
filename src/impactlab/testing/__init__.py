"""Synthetic data for tests, examples and validation: drops and dents with a known truth.

No public raw files of the paper's experiment exist, so the tests, the worked example of
docs/experiment.md and the validation of the experiment pipeline (``impactlab.experiment``) make
realistic ones here:

- impacts (``.impacts``): :func:`rigid_impulse_impact` (the rigid-body impulse solution of
  ``impactlab.bodies.rigid_impulse``) and :func:`engine_impact` (the impact engine), as
  :class:`ImpactTruth`;
- marker tracks (``.markers``): :func:`marker_tracks` (three markers at 500 fps, gravity, noise,
  occlusions, optional hold-and-release and second bounce) and :func:`write_c3d`;
- dent scans (``.scans``): :func:`groove_surface` (an analytic sliding dent with exact metrics,
  :class:`GrooveTruth`), :func:`synthetic_scan` (tilted, noisy, with dropouts; :class:`ScanTruth`)
  and :func:`write_scan` (X3P, GWY, NetCDF, SDF, NPY, CSV).

Nothing in the library depends on this package.
"""

from impactlab.testing.impacts import ImpactTruth, engine_impact, rigid_impulse_impact
from impactlab.testing.markers import ALIGNED_MARKERS, DEFAULT_MARKERS, marker_tracks, write_c3d
from impactlab.testing.scans import (
    GrooveTruth,
    ScanTruth,
    groove_surface,
    synthetic_scan,
    write_scan,
)

__all__ = [
    "ALIGNED_MARKERS",
    "DEFAULT_MARKERS",
    "GrooveTruth",
    "ImpactTruth",
    "ScanTruth",
    "engine_impact",
    "groove_surface",
    "marker_tracks",
    "rigid_impulse_impact",
    "synthetic_scan",
    "write_c3d",
    "write_scan",
]
