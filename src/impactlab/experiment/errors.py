"""Errors of the experiment pipeline: each names the file (or stage) and the problem.

All derive from :class:`ExperimentError`, a ``ValueError``, so the command line reports them as one
line (``impactlab.cli.main``) and callers can catch one type.
"""

from __future__ import annotations

from pathlib import Path


class ExperimentError(ValueError):
    """A problem with the experimental data (a file, a fit, a measurement).

    ``warnings``: what the failed step had found before it failed (``measure_impact``: frames
    left out, a marker off the rigid cluster, ...), which ``analyze`` keeps among the result's
    warnings."""

    warnings: tuple[str, ...] = ()


class FileFormatError(ExperimentError):
    """A file is missing, corrupt, truncated or not in the expected format."""

    def __init__(self, path: str | Path, problem: str) -> None:
        self.path = str(path)
        self.problem = problem
        super().__init__(f"{self.path}: {problem}")


class MarkerError(ExperimentError):
    """The marker tracks cannot give the rod's motion (rigidity, too few frames, no impact...)."""


class RigidityError(MarkerError):
    """Inter-marker distances drift beyond the tolerance: markers are not rigidly attached."""


class TooFewFramesError(MarkerError):
    """Too few valid free-flight frames before or after the impact for the ballistic fits."""


class ImpactNotFoundError(MarkerError):
    """No impact (jump of the vertical velocity) in the marker tracks."""


class ScanError(ExperimentError):
    """The profilometer scan cannot give the dent metrics."""


class DentNotFoundError(ScanError):
    """No dent deeper than the detection threshold in the scan."""


class DentCutOffError(ScanError):
    """The dent reaches the edge of the scan (or of its valid data): its length is unknown."""


class MissingDependencyError(ExperimentError):
    """An optional package is needed (e.g. SurfaceTopography for instrument scan formats)."""


__all__ = [
    "DentCutOffError",
    "DentNotFoundError",
    "ExperimentError",
    "FileFormatError",
    "ImpactNotFoundError",
    "MarkerError",
    "MissingDependencyError",
    "RigidityError",
    "ScanError",
    "TooFewFramesError",
]
