"""Motion-capture marker tracks: C3D and CSV readers (positions in metres, occlusions masked).

- :class:`MarkerTracks` and :func:`length_factor` (``.tracks``);
- :func:`read_c3d` (``.c3d``: ezc3d, else the pure-Python ``c3d`` package);
- :func:`read_csv_markers`, :func:`write_csv_markers` (``.csv_format``: the CSV layout of
  docs/experiment.md);
- :func:`read_markers`: the reader chosen by the file's extension (``.read``).
"""

from impactlab.experiment.markers.c3d import read_c3d
from impactlab.experiment.markers.csv_format import read_csv_markers, write_csv_markers
from impactlab.experiment.markers.read import read_markers
from impactlab.experiment.markers.tracks import MarkerTracks, length_factor

__all__ = [
    "MarkerTracks",
    "length_factor",
    "read_c3d",
    "read_csv_markers",
    "read_markers",
    "write_csv_markers",
]
