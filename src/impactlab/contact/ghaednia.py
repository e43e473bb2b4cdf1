"""Ghaednia et al. (2016): the modified Jackson-Green law used by the paper (Sec. 3.2).

Loading (paper Eqs. 15-17, delta* = delta / delta_c):

- delta_c = (pi C S_y / (2 E*))^2 R, C = 1.295 exp(0.736 nu), F_c = 4/3 (R/E*)^2 (pi C S_y/2)^3
  (F_c is the Hertz force at delta_c);
- elastic: Hertz, F = 4/3 E* sqrt(R) delta^1.5;
- elastic-plastic (Eq. 16): F = F_c [exp(-0.17 delta*^(5/12)) delta*^1.5
  + 4 H_G/(C S_y) (1 - exp(-delta*^(5/9) / 78)) delta*^1.1],
  H_G/S_y = 2.84 - 0.92 [1 - cos(pi r/R)], r = sqrt(R delta (delta/(1.9 delta_c))^B),
  B = 0.14 exp(23 S_y/E*) (the paper prints delta_y instead of delta under the root).

Switch: Eq. 16 lies ~10 % below Hertz at delta* = 1.9, the published switch point. By default
the law switches from Hertz to Eq. 16 where the two curves cross (continuous loading curve);
``published_switch=1`` keeps the published switch at delta* = 1.9 with its force jump.
Unloading: Hertzian with R_r from continuity (Eq. 18), residual depth Eq. 19:
delta_r/delta_m = 0.8 [1 - ((delta_m/delta_c + 5.5)/6.5)^-2] (0 for delta_m <= delta_c).

Reference: H. Ghaednia, S. A. Pope, R. L. Jackson, D. B. Marghitu, A comprehensive study of
the elasto-plastic contact of a sphere and a flat, Tribology International 93 (2016) 78-90,
doi:10.1016/j.triboint.2015.09.005 (the paper's ref. [4]). See docs/laws/ghaednia.md.
"""

from __future__ import annotations

import numpy as np

from impactlab.contact import kernels as k
from impactlab.contact._common import check_switch
from impactlab.contact._jackson_family import fill_jackson_family
from impactlab.contact.base import ContactLaw, Parameter
from impactlab.contact.names import Law
from impactlab.materials import ContactPair


class Ghaednia(ContactLaw):
    law = Law.GHAEDNIA
    title = "Ghaednia et al. (modified Jackson-Green), the paper's Sec. 3.2"
    reference = (
        "Ghaednia, Pope, Jackson, Marghitu, Tribology International 93 (2016) 78-90; "
        "paper Eqs. 15-19"
    )
    validity = (
        "elastic-perfectly plastic sphere on a flat, frictionless, quasi-static; hard limit: the "
        "fitted contact radius reaches R (delta^(1+B) = R (1.9 delta_c)^B) or delta = R"
    )
    parameters = (
        Parameter(
            "published_switch",
            0.0,
            "1",
            "0: switch from Hertz to Eq. 16 where the curves cross (continuous, default); "
            "1: switch at delta* = 1.9 as published (force drops ~10 %)",
        ),
    )

    def _fill(self, p: np.ndarray, pair: ContactPair, values: dict[str, float]) -> dict[str, float]:
        published = check_switch(values["published_switch"])
        return fill_jackson_family(
            p,
            pair,
            k1=0.17,
            k2=1.0 / 78.0,
            m=1.1,
            hardness_model=k.JG_HARDNESS_GHAEDNIA,
            published=published,
            law=self.law,
        )
