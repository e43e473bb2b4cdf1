"""Motion-capture marker tracks: C3D and CSV readers (positions in metres, occlusions masked).

- :class:`MarkerTracks` and :func:`length_factor` (``.tracks``);
- :func:`read_c3d` (``.c3d``: ezc3d, else the pure-Python ``c3d`` package);
- :func:`read_csv_markers`, :func:`write_csv_markers` (``.csv_format``: the CSV layout of
  docs/experiment.md);
- :func:`read_qtm_tsv` (``.qualisys_tsv``: a Qualisys QTM TSV export of 3D data);
- :func:`read_vicon_csv` (``.vicon_csv``: a Vicon Nexus CSV export, its Trajectories);
- :func:`read_markers`: the reader chosen by the file's extension and, for text, its content
  (``.read``).
"""

from impactlab.experiment.markers.c3d import read_c3d
from impactlab.experiment.markers.csv_format import read_csv_markers, write_csv_markers
from impactlab.experiment.markers.qualisys_tsv import read_qtm_tsv
from impactlab.experiment.markers.read import read_markers
from impactlab.experiment.markers.tracks import MarkerTracks, length_factor
from impactlab.experiment.markers.vicon_csv import read_vicon_csv

__all__ = [
    "MarkerTracks",
    "length_factor",
    "read_c3d",
    "read_csv_markers",
    "read_markers",
    "read_qtm_tsv",
    "read_vicon_csv",
    "write_csv_markers",
]
