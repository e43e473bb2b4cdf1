"""Measurements of Kharaz, Gorham & Salman (2001): 5 mm alumina spheres on a thick soda-lime
glass anvil at 3.9 m/s, impact angle theta measured from the normal.

A.H. Kharaz, D.A. Gorham, A.D. Salman, "An experimental study of the elastic rebound of
spheres", Powder Technology 120 (2001) 281-291, doi:10.1016/S0032-5910(01)00283-2.

The paper's tables/figures could not be read here (paywalled, not in the search corpus). The
values below are second-hand digitisations, copied verbatim from public repositories:

KGS_ET, KGS_OMEGA, KGS_REBOUND_COM:
    chaos-polymtl/lethe, examples/dem/3d-oblique-wall-impact/oblique_wall_impact_postprocessing.py
    (commit 255b519263fbb22f758d40763a12290296d53200), lists theta_restitution_exp /
    restitution_exp (tangential coefficient of restitution of the centre of mass,
    v_t,out / v_t,in), theta_omega_exp / omega_exp (|rebound spin| [rad/s]) and
    theta_rebound_exp / theta_out_exp (rebound angle of the centre of mass [deg]), introduced as
    "Experimental data from A.H. Kharaz, D.A. Gorham, and A.D. Salman ... 2001". Who digitised
    them, and from which figure, is not stated there.

KGS_REBOUND_CONTACT:
    KratosMultiphysics/Kratos, applications/DEMApplication/tests/DEM3D_chung_ooi_tests/
    test4_data/paper_data/benchmark4_graph3.dat (commit f678879c5465efeaae8328b72b3fea70897e4721),
    block "#Experiment": rebound angle of the contact patch [deg] (tan = v_slip,out / v_n,out,
    negative = contact point moving backwards) versus incident angle, digitised from the
    benchmark figure of Chung & Ooi, Granular Matter 13 (2011) 643-656,
    doi:10.1007/s10035-011-0277-0 (test 4), which reproduces the Kharaz et al. data.

No scatter bands are available from these sources (Kharaz et al. report means of repeated
impacts); the comparisons (``impactlab.verification.partial_slip``) are against the digitised
means only.

Columns: incidence angle theta from the normal [deg], then the measured quantity.
"""

from __future__ import annotations

import numpy as np

KGS_ET = np.array(
    [
        [1.84, 0.79344],
        [3.703, 0.74533],
        [9.496, 0.67257],
        [20.012, 0.59691],
        [30.127, 0.68756],
        [39.382, 0.77148],
        [49.694, 0.84761],
        [60.02, 0.90142],
    ]
)

KGS_OMEGA = np.array(
    [
        [6.143, 136.18],
        [10.991, 265.69],
        [21.251, 577.65],
        [31.157, 612.88],
        [39.143, 595.49],
        [50.348, 453.21],
        [60.328, 382.09],
    ]
)

KGS_REBOUND_COM = np.array(
    [
        [0.016, 0.074],
        [2.15, 1.733],
        [4.096, 2.962],
        [9.826, 6.518],
        [20.567, 12.208],
        [30.29, 21.67],
        [39.535, 32.613],
        [49.747, 45.125],
        [60.208, 57.474],
    ]
)

KGS_REBOUND_CONTACT = np.array(
    [
        [2.0997281572207847, 0.7703927492447065],
        [3.9434155319702846, 0.7703927492447065],
        [9.717622556290827, -1.0574018126888234],
        [20.309682809728216, -8.53474320241692],
        [30.160683905575503, -2.5528700906344426],
        [39.120476602752326, 9.909365558912384],
        [49.51201496648886, 30.015105740181262],
        [59.9037955064207, 49.95468277945619],
        [70.46025585915032, 66.90332326283988],
        [78.85965284042405, 78.86706948640483],
        [84.78158734387202, 85.6797583081571],
    ]
)
