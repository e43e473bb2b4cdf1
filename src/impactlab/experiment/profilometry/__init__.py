"""Profilometer scans of the dent: reading, levelling, and the dent metrics delta_p and L_s.

Definitions (paper Sec. 5, doi:10.1007/s00419-015-1108-2; details in docs/experiment.md):

* the *deformed area* is the connected region around the deepest point lying more than the edge
  threshold ``t_e`` below the levelled surface (``t_e`` = max(``edge_sigma`` x smoothed noise,
  ``edge_fraction`` x depth); its outline is the contour at -t_e, with sub-pixel interpolation);
* ``delta_p`` = maximum depth below the levelled plane (a local paraboloid fitted around the deepest
  pixel, so the noise does not bias the minimum);
* length = the maximum length of the deformed area (its largest Feret diameter); the sliding axis
  = the outline's long principal axis (second moments of area: the whole outline's noise
  averages out, where the Feret direction, set by two points, tilts on a nearly round dent);
  width = its width at the deepest point, perpendicular to that axis;
* ``sliding_length`` (L_s) = length - width;
* the sliding direction: along the sliding axis towards the *sharper* end, the end where the depth
  falls from 80 % to 20 % of delta_p over the shorter distance (the paper's Figs. 6-7: "wider at
  the centre and sharper at the end of the impact"); flagged ambiguous when both ends are within
  10 %;
* pile-up height = the highest point of the levelled surface in a band around the outline
  (``pileup_band`` x width wide).

Signs (docs/glossary.md): delta_p and the sliding length are magnitudes, delta_p > 0 and
L_s >= 0 (L_s is not clipped: a nearly round dent may measure slightly below 0 within its
uncertainty); the paper prints them negative (y up). The sliding direction is ``axis``.

Modules: ``heightmap`` (:class:`HeightMap`), ``reading`` (:func:`read_scan`; ``plain`` for
.npy/.csv maps, ``instrument`` for SurfaceTopography's formats), ``levelling``
(:func:`level_plane`), ``dent`` (:func:`measure_dent`; ``outline``, ``extent``, ``profiles``,
``bottom`` its geometry), ``metrics`` (:class:`DentMetrics`), ``surface`` (levelled surface,
detection, the sign check), ``plausibility`` (:func:`check_dent`: can the rod make this dent?).
"""

from impactlab.experiment.profilometry.dent import measure_dent
from impactlab.experiment.profilometry.heightmap import HeightMap
from impactlab.experiment.profilometry.levelling import Levelled, level_plane
from impactlab.experiment.profilometry.metrics import DentMetrics
from impactlab.experiment.profilometry.plausibility import check_dent
from impactlab.experiment.profilometry.reading import read_scan

__all__ = [
    "DentMetrics",
    "HeightMap",
    "Levelled",
    "check_dent",
    "level_plane",
    "measure_dent",
    "read_scan",
]
