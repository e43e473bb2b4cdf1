"""The publications impactlab's models, methods and checks rest on."""

from __future__ import annotations

from impactlab.references.reference import PAPER, Reference

__all__ = ["LITERATURE"]

#: Papers and books: the models, methods and checks.
LITERATURE: tuple[Reference, ...] = (
    Reference(
        PAPER,
        "H. Ghaednia, D. B. Marghitu, R. L. Jackson, Permanent deformation during the oblique "
        "impact with friction, Archive of Applied Mechanics 86 (2016) 121-134",
        "10.1007/s00419-015-1108-2",
        confirmed=True,
        note="DOI confirmed: the article's text read at its DOI address (a Springer mirror)",
    ),
    Reference(
        "hertz-1882",
        "H. Hertz, Ueber die Beruehrung fester elastischer Koerper, J. reine angew. Math. 92 "
        "(1882) 156-171",
        "10.1515/crll.1882.92.156",
        note="citation confirmed by two citing works' reference lists; DOI not checked",
    ),
    Reference(
        "johnson-1985",
        "K. L. Johnson, Contact Mechanics, Cambridge University Press (1985)",
        "10.1017/CBO9781139171731",
        note="DOI not checked",
    ),
    Reference(
        "ghaednia-2016-contact",
        "H. Ghaednia, S. A. Pope, R. L. Jackson, D. B. Marghitu, A comprehensive study of the "
        "elasto-plastic contact of a sphere and a flat, Tribology International 93 (2016) 78-90",
        "10.1016/j.triboint.2015.09.005",
        note="citation confirmed (Willert 2020's reference list: Tribol. Int. 93(A) 78-90); "
        "DOI not confirmed",
    ),
    Reference(
        "jackson-green-2005",
        "R. L. Jackson, I. Green, A finite element study of elasto-plastic hemispherical contact "
        "against a rigid flat, J. Tribol. 127 (2005) 343-354",
        "10.1115/1.1866166",
        confirmed=True,
        note="DOI printed on the article's first page (a copy read)",
    ),
    Reference(
        "green-2005",
        "I. Green, Proc. IMechE C 219 (2005) (critical values, C(nu))",
        note="not checked; no DOI recorded",
    ),
    Reference(
        "kogut-etsion-2002",
        "L. Kogut, I. Etsion, Elastic-plastic contact analysis of a sphere and a rigid flat, J. "
        "Appl. Mech. 69 (2002) 657-662",
        "10.1115/1.1490373",
        confirmed=True,
        note="DOI printed on the article's first page (a copy read)",
    ),
    Reference(
        "kogut-komvopoulos-2004",
        "L. Kogut, K. Komvopoulos, Analysis of the spherical indentation cycle for elastic-"
        "perfectly plastic solids, J. Mater. Res. 19 (2004) 3641-3653",
        "10.1557/JMR.2004.0468",
        note="not found in the sources searched: citation and DOI not confirmed",
    ),
    Reference(
        "brake-2015",
        "M. R. W. Brake, An analytical elastic plastic contact model with strain hardening and "
        "frictional effects for normal and oblique impacts, Int. J. Solids Struct. 62 (2015) "
        "104-123",
        "10.1016/j.ijsolstr.2015.02.019",
        note="title and journal confirmed (OSTI record 1146110); DOI not confirmed",
    ),
    Reference(
        "brake-2012",
        "M. R. W. Brake, An analytical elastic-perfectly plastic contact model, Int. J. Solids "
        "Struct. 49 (2012) 3129-3141",
        note="citation confirmed (Willert 2020's reference list); DOI not found",
    ),
    Reference(
        "thornton-1997",
        "C. Thornton, Coefficient of restitution for collinear collisions of elastic-perfectly "
        "plastic spheres, J. Appl. Mech. 64 (1997) 383-386",
        "10.1115/1.2787319",
        note="citation confirmed (J. Appl. Mech. 64(2) 383-386, two citing works); DOI not "
        "confirmed",
    ),
    Reference(
        "swift-1952",
        "H. W. Swift, Plastic instability under plane stress, J. Mech. Phys. Solids 1 (1952) 1-18",
        "10.1016/0022-5096(52)90003-3",
        note="the flow curve sigma = K (eps0 + eps_p)^n; DOI not checked",
    ),
    Reference(
        "dieter-1961",
        "G. E. Dieter, Mechanical Metallurgy, McGraw-Hill, New York (1961), ISBN 07-016890-3; "
        "the tension test: Considere's necking criterion d sigma / d eps = sigma, and for a "
        "power law the uniform true strain equal to the exponent",
        note="a book without a DOI; ISBN read on the copyright page of a public scan "
        "(pdfdrive.to/book/mechanical-metallurgy); its section on instability in tension was "
        "not read here (section and page not confirmed); the criterion and Considere's "
        "construction also on the University of Cambridge DoITPoMS teaching pages "
        "(doitpoms.ac.uk/tlplib/mechanical_testing_metals)",
    ),
    Reference(
        "stronge-2000",
        "W. J. Stronge, Impact Mechanics, Cambridge University Press (2000)",
        "10.1017/CBO9780511626432",
    ),
    Reference(
        "mindlin-deresiewicz-1953",
        "R. D. Mindlin, H. Deresiewicz, Elastic spheres in contact under varying oblique forces, "
        "J. Appl. Mech. 20 (1953) 327-344",
        "10.1115/1.4010702",
        note="citation and DOI as given in several independent public DEM codes (e.g. "
        "https://doi.org/10.1115/1.4010702 with title, volume and pages); DOI address not read",
    ),
    Reference(
        "mindlin-1949",
        "R. D. Mindlin, Compliance of elastic bodies in contact, J. Appl. Mech. 16 (1949) 259-268",
        "10.1115/1.4009973",
        note="citation and DOI as given in several independent public DEM codes and a literature "
        "record (volume 16(3), pages 259-268); DOI address not read",
    ),
    Reference(
        "popov-hess-2014",
        "V. L. Popov, M. Hess, Method of dimensionality reduction in contact mechanics and "
        "friction: a users handbook. I. Axially-symmetric contacts, Facta Universitatis Ser. "
        "Mech. Eng. 12 (2014) 1-14",
        note="title, journal, volume and pages read in the article's text (open access); no DOI "
        "printed there",
    ),
    Reference(
        "di-renzo-di-maio-2004",
        "A. Di Renzo, F. P. Di Maio, Chem. Eng. Sci. 59 (2004) 525 (comparison of contact-force "
        "models for DEM)",
        "10.1016/j.ces.2003.09.037",
    ),
    Reference(
        "thornton-cummins-cleary-2011",
        "C. Thornton, S. J. Cummins, P. W. Cleary, An investigation of the comparative behaviour "
        "of alternative contact force models during elastic collisions, Powder Technol. 210 "
        "(2011) 189-197",
        note="title, journal, volume (number 3) and pages confirmed (the University of "
        "Birmingham's research portal record; the reference lists of the LIGGGHTS "
        "documentation, gran tangential incremental_history, and of Biegert, Vowinckel & "
        "Meiburg, arXiv:1608.03566); DOI not found in the sources searched",
    ),
    Reference(
        "thornton-cummins-cleary-2013",
        "C. Thornton, S. J. Cummins, P. W. Cleary, An investigation of the comparative behaviour "
        "of alternative contact force models during inelastic collisions, Powder Technol. 233 "
        "(2013) 30-46",
        note="the tangential stiffness 8 G* a with the actual (plastic) contact radius; title, "
        "journal, volume and pages confirmed (the reference lists of the LIGGGHTS "
        "documentation, gran tangential incremental_history, and of Biegert, Vowinckel & "
        "Meiburg, arXiv:1608.03566); DOI not found in the sources searched",
    ),
    Reference(
        "maw-barber-fawcett-1976",
        "N. Maw, J. R. Barber, J. N. Fawcett, The oblique impact of elastic spheres, Wear 38 "
        "(1976) 101-114",
        "10.1016/0043-1648(76)90201-5",
    ),
    Reference(
        "fritsch-carlson-1980",
        "F. N. Fritsch, R. E. Carlson, Monotone piecewise cubic interpolation, SIAM J. Numer. "
        "Anal. 17 (1980) 238-246",
        "10.1137/0717021",
        note="DOI not checked",
    ),
    Reference(
        "de-boor-1978",
        "C. de Boor, A Practical Guide to Splines, Springer (1978; revised edition 2001)",
        "10.1007/978-1-4612-6333-3",
        note="DOI not checked",
    ),
    Reference(
        "craven-wahba-1979",
        "P. Craven, G. Wahba, Smoothing noisy data with spline functions: estimating the "
        "correct degree of smoothing by the method of generalized cross-validation, Numer. "
        "Math. 31 (1979) 377-403",
        "10.1007/BF01404567",
        note="DOI not checked",
    ),
    Reference(
        "dormand-prince-1980",
        "J. R. Dormand, P. J. Prince, A family of embedded Runge-Kutta formulae, J. Comput. "
        "Appl. Math. 6 (1980) 19-26",
        "10.1016/0771-050X(80)90013-3",
    ),
    Reference(
        "shampine-1986",
        "L. F. Shampine, Some practical Runge-Kutta formulas, Math. Comp. 46 (1986) 135-150",
        "10.1090/S0025-5718-1986-0815836-3",
    ),
    Reference(
        "anderson-bjorck-1973",
        "N. Anderson, A. Bjorck, A new high order method of regula falsi type for computing a "
        "root of an equation, BIT 13 (1973) 253-264",
        "10.1007/BF01951936",
        note=(
            "the partial-slip engine's event search (dynamics.kernels.roots.anderson_bjorck); "
            "DOI not checked"
        ),
    ),
    Reference(
        "kabsch-1976",
        "W. Kabsch, A solution for the best rotation to relate two sets of vectors, Acta Cryst. "
        "A32 (1976) 922-923",
        "10.1107/S0567739476001873",
    ),
    Reference(
        "saltelli-2008",
        "A. Saltelli et al., Global Sensitivity Analysis: The Primer, Wiley (2008)",
        "10.1002/9780470725184",
    ),
    Reference(
        "steele-lea-flood-2014",
        "G. L. Steele, D. Lea, C. H. Flood, Fast splittable pseudorandom number generators, "
        "OOPSLA 2014",
        "10.1145/2660193.2660195",
    ),
    Reference(
        "goodman-weare-2010",
        "J. Goodman, J. Weare, Ensemble samplers with affine invariance, Commun. Appl. Math. "
        "Comput. Sci. 5 (2010) 65-80",
        "10.2140/camcos.2010.5.65",
    ),
    Reference(
        "foreman-mackey-2013",
        "D. Foreman-Mackey, D. W. Hogg, D. Lang, J. Goodman, emcee: The MCMC Hammer, Publ. "
        "Astron. Soc. Pac. 125 (2013) 306-312",
        "10.1086/670067",
    ),
    Reference(
        "vehtari-2017",
        "A. Vehtari, A. Gelman, J. Gabry, Practical Bayesian model evaluation using "
        "leave-one-out cross-validation and WAIC, Stat. Comput. 27 (2017) 1413-1432",
        "10.1007/s11222-016-9696-4",
    ),
    Reference(
        "kumar-2019-arviz",
        "R. Kumar, C. Carroll, A. Hartikainen, O. Martin, ArviZ a unified library for "
        "exploratory analysis of Bayesian models in Python, J. Open Source Softw. 4 (2019) 1143",
        "10.21105/joss.01143",
    ),
    Reference(
        "vehtari-2021-rhat",
        "A. Vehtari, A. Gelman, D. Simpson, B. Carpenter, P.-C. Buerkner, Rank-normalization, "
        "folding, and localization: an improved R-hat for assessing convergence of MCMC, "
        "Bayesian Anal. 16 (2021) 667-718",
        "10.1214/20-BA1221",
    ),
    Reference(
        "yao-2018-stacking",
        "Y. Yao, A. Vehtari, D. Simpson, A. Gelman, Using stacking to average Bayesian "
        "predictive distributions, Bayesian Anal. 13 (2018) 917-1007",
        "10.1214/17-BA1091",
    ),
    Reference(
        "sivula-2020-loo-uncertainty",
        "T. Sivula, M. Magnusson, A. A. Matamoros, A. Vehtari, Uncertainty in Bayesian "
        "leave-one-out cross-validation based model comparison, arXiv:2008.10296 (2020)",
        "10.48550/arXiv.2008.10296",
    ),
)
