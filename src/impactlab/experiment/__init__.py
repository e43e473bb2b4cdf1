"""Experiment processing: marker tracks and dent scans -> e, mu, delta_p, L_s, T and F.

The pipeline of the paper's Secs. 4-5 (doi:10.1007/s00419-015-1108-2): three markers on the rod
tracked at 500 fps give the rod's velocities before and after the impact (e, mu by Eq. 28, the
impact angle, v_i); an optical profilometer scan of the dent gives delta_p (maximum depth) and
the sliding length L_s (maximum length minus the width at the deepest point); the analytic inversion
(``impactlab.analytic.invert``) turns them into the impact duration T and the mean force F.

Public API::

    analyze(markers_path, scan_path, rod=..., ...) -> ExperimentResult
    read_markers / read_c3d / read_csv_markers -> MarkerTracks
    measure_impact(tracks, rod, geometry=..., up=...) -> ImpactKinematics
    read_scan(path, pixel_size=..., height_unit=...) -> HeightMap
    measure_dent(height_map) -> DentMetrics
    check_dent(dent, tip_radius=..., rod_length=...) -> warnings (ScanError if impossible)
    plot_dent, plot_kinematics (impactlab.experiment.plots)

Synthetic drops and dents with a known truth (for tests and examples): ``impactlab.testing``.

See docs/experiment.md for file formats, fits, uncertainties and a worked example.
"""

from impactlab.experiment.analysis import ExperimentResult, analyze, default_rod, rod_properties
from impactlab.experiment.errors import (
    DentCutOffError,
    DentNotFoundError,
    ExperimentError,
    FileFormatError,
    ImpactNotFoundError,
    MarkerError,
    MissingDependencyError,
    RigidityError,
    ScanError,
    TooFewFramesError,
)
from impactlab.experiment.kinematics import ImpactKinematics, SegmentFit, measure_impact, parse_up
from impactlab.experiment.markers import (
    MarkerTracks,
    read_c3d,
    read_csv_markers,
    read_markers,
    write_csv_markers,
)
from impactlab.experiment.profilometry import (
    DentMetrics,
    HeightMap,
    Levelled,
    check_dent,
    level_plane,
    measure_dent,
    read_scan,
)
from impactlab.experiment.rigid import (
    MarkerGeometry,
    Poses,
    RigidityReport,
    check_rigidity,
    fit_poses,
    kabsch,
    reference_cluster,
)
from impactlab.experiment.uncertainty import Estimate, propagate

__all__ = [
    "DentCutOffError",
    "DentMetrics",
    "DentNotFoundError",
    "Estimate",
    "ExperimentError",
    "ExperimentResult",
    "FileFormatError",
    "HeightMap",
    "ImpactKinematics",
    "ImpactNotFoundError",
    "Levelled",
    "MarkerError",
    "MarkerGeometry",
    "MarkerTracks",
    "MissingDependencyError",
    "Poses",
    "RigidityError",
    "RigidityReport",
    "ScanError",
    "SegmentFit",
    "TooFewFramesError",
    "analyze",
    "check_dent",
    "check_rigidity",
    "default_rod",
    "fit_poses",
    "kabsch",
    "level_plane",
    "measure_dent",
    "measure_impact",
    "parse_up",
    "propagate",
    "read_c3d",
    "read_csv_markers",
    "read_markers",
    "read_scan",
    "reference_cluster",
    "rod_properties",
    "write_csv_markers",
]
