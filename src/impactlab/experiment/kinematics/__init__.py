"""From marker tracks to the impact kinematics: velocities before/after, e, mu, the rod angle.

Pipeline (details and the uncertainty model in docs/experiment.md):

1. rigidity check of the marker cluster, then its pose per frame (Kabsch,
   :mod:`impactlab.experiment.rigid`; ``.cluster``), frames with a marker far off the rigid
   cluster left out; the options checked first (``.options``);
2. the centre of mass C and the rod axis from the marker geometry (given, or estimated: the axis
   from the cluster's principal direction, C as the body point that flies ballistically;
   ``.com``, ``.body`` with the impact frame);
3. impact detection: the first impact-sized jump of the velocity and rate of turn of the
   cluster, from straight-line fits to ``window`` frames on either side of each frame (gravity
   removed; ``.detect``); the next one (a second bounce) ends the flight after it;
4. the free fall before the impact (all the record holds) fitted with a free acceleration: the
   time base, the length unit and ``up`` checked before any fit that assumes g, a warning where
   the fall is too short to check them (``.gravity``);
5. free-flight segments before and after, ``guard`` frames away from the impact frame, at most
   ``max_fit_frames`` long, trimmed at their far end where the data stop being ballistic (the rod
   still held before the release, a second bounce after; ``.fits``);
6. per segment one least-squares fit, common design matrix [1, tau]: the horizontal and out-of-
   plane coordinates of C linear in time, the vertical one quadratic with the known gravity, the
   rod angle linear; covariance of the coefficients = S (x) (A^T A)^-1 with S the residual
   covariance of the four coordinates (multivariate regression);
7. the impact instant: where the extrapolated tip heights of the two fits cross (``.derive``);
8. at that instant: v_C, the spin and the angle before and after, the tip velocities, e and mu;
   all with first-order uncertainties propagated from the two fits (numerical Jacobian), the
   impact instant included (``.estimates``, run by ``.measure``; result in ``.result``); an e
   outside [0, 1] is refused and a given geometry is checked against the rigid-body impulse
   relations (``.impulse``), a mirrored one named as such (``.mirror``).

Frame of the results (the paper's, Fig. 1): y up (``up``), x horizontal in the vertical plane of
the rod axis at impact, positive from the tip towards C; z = x cross y. The angle is that of the
vector tip -> C above the horizontal (the rod angle to the flat); the spin is its rate
d(angle)/dt (counter-clockwise about z).
"""

from impactlab.experiment.kinematics.fits import SegmentFit
from impactlab.experiment.kinematics.frame import G0, parse_up, rod_dimensions
from impactlab.experiment.kinematics.measure import measure_impact
from impactlab.experiment.kinematics.result import ImpactKinematics

__all__ = [
    "G0",
    "ImpactKinematics",
    "SegmentFit",
    "measure_impact",
    "parse_up",
    "rod_dimensions",
]
