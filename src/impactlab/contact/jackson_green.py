"""Jackson & Green (2005): elasto-plastic hemispherical contact against a rigid flat.

Loading (delta* = delta / delta_c; delta_c, F_c and C(nu) as in the paper's Eqs. 15 and 17):

- elastic: Hertz;
- elastic-plastic: F = F_c [exp(-(1/4) delta*^(5/12)) delta*^1.5
  + 4 H_G/(C S_y) (1 - exp(-delta*^(5/9) / 25)) delta*],
  H_G/S_y = 2.84 [1 - exp(-0.82 (a/R)^-0.7)], a = sqrt(R delta (delta/(1.9 delta_c))^B),
  B = 0.14 exp(23 S_y/E*).

The coefficient of the first exponential (``elastic_decay``, default 1/4) is the one JG 2005 is
cited with by Ghaednia, Brake, Berryhill & Jackson (J. Tribol. 2019); the paper's Eq. 16 has
0.17 in its place (Ghaednia's modification). The JG 2005 curve is 0.5 % above Hertz at
delta* = 1.9 (8.4 % if 0.17 is used). Switch and unloading as for Ghaednia: the default
switches where the curves cross (continuous), ``published_switch=1`` at delta* = 1.9; unloading
is Hertzian with R_r from continuity and Ghaednia's residual depth (paper Eqs. 18-19), as the
project's brief asks (JG 2005 itself has no unloading law).

Reference: R. L. Jackson, I. Green, A finite element study of elasto-plastic hemispherical
contact against a rigid flat, J. Tribol. 127 (2005) 343-354, doi:10.1115/1.1866166.
See docs/laws/jackson-green.md.
"""

from __future__ import annotations

import numpy as np

from impactlab._validation import check_range
from impactlab.contact import kernels as k
from impactlab.contact._common import check_switch
from impactlab.contact._jackson_family import fill_jackson_family
from impactlab.contact.base import ContactLaw, Parameter
from impactlab.contact.names import Law
from impactlab.materials import ContactPair


class JacksonGreen(ContactLaw):
    law = Law.JACKSON_GREEN
    title = "Jackson-Green 2005 (original constants)"
    reference = "Jackson, Green, J. Tribol. 127 (2005) 343-354"
    validity = (
        "elastic-perfectly plastic hemisphere on a rigid flat, frictionless, quasi-static; hard "
        "limit: the fitted contact radius reaches R or delta = R"
    )
    parameters = (
        Parameter(
            "published_switch",
            0.0,
            "1",
            "0: switch from Hertz to the JG formula where the curves cross (continuous, "
            "default); 1: switch at delta* = 1.9 as published (force jumps +0.5 %)",
        ),
        Parameter(
            "elastic_decay",
            0.25,
            "1",
            "coefficient k of exp(-k delta*^(5/12)) in the first term (JG 2005: 1/4; the "
            "paper's Eq. 16 uses 0.17)",
        ),
    )

    def _fill(self, p: np.ndarray, pair: ContactPair, values: dict[str, float]) -> dict[str, float]:
        published = check_switch(values["published_switch"])
        k1 = check_range("elastic_decay", values["elastic_decay"], 0.0, 1.0)
        return fill_jackson_family(
            p,
            pair,
            k1=k1,
            k2=1.0 / 25.0,
            m=1.0,
            hardness_model=k.JG_HARDNESS_JG2005,
            published=published,
            law=self.law,
        )
