"""The literature impactlab cites: one registry of references with their DOIs.

Models carry the references they implement (``ContactLaw.references``,
``FrictionModel.references``, the engine's integrator), and results record the references a
computation used. ``confirmed`` is True only where the DOI was checked against the publisher's
record or in a copy of the publication in this project; ``note`` says what was checked (see
docs/laws/index.md, "References and their status"). The other DOIs are carried over from the
sources' own citations and are not verified here. Every DOI must match ``DOI_PATTERN``; a
reference without a DOI (a handbook, a data sheet) has ``doi == ""`` and, where it is on the
web, the address it was read at in ``url`` (``""`` otherwise).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from types import MappingProxyType

#: A well-formed DOI: "10.", a registrant code of 4-9 digits (dot-separated parts allowed), "/",
#: a suffix without spaces (Crossref's recommended pattern, widened to upper case).
DOI_PATTERN = re.compile(r"^10\.\d{4,9}(\.\d+)*/\S+$")


@dataclass(frozen=True)
class Reference:
    """A cited source: registry ``key``, ``citation`` text, ``doi`` and ``url``
    (https://doi.org/<doi>, filled in from the DOI; for a source without a DOI, its web address
    or ""); ``confirmed``: the DOI was read in a copy
    of the publication or at its DOI address; ``note``: what was checked, and where."""

    key: str
    citation: str
    doi: str = ""
    url: str = field(default="")
    confirmed: bool = False
    note: str = ""

    def __post_init__(self) -> None:
        if self.doi and not DOI_PATTERN.match(self.doi):
            raise ValueError(f"reference {self.key!r}: malformed DOI {self.doi!r}")
        if self.confirmed and not self.doi:
            raise ValueError(f"reference {self.key!r}: confirmed without a DOI")
        if self.url and not self.url.startswith(("https://", "http://")):
            raise ValueError(f"reference {self.key!r}: url must be a web address, got {self.url!r}")
        if self.doi and not self.url:
            object.__setattr__(self, "url", f"https://doi.org/{self.doi}")

    def __str__(self) -> str:
        return f"{self.citation}, doi:{self.doi}" if self.doi else self.citation


PAPER = "ghaednia-2016-impact"
"""Key of the seed paper (Ghaednia, Marghitu & Jackson 2016, Arch. Appl. Mech.)."""

_ALL: tuple[Reference, ...] = (
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
        "C. Thornton, S. J. Cummins, P. W. Cleary, Powder Technol. 210 (2011) 189",
    ),
    Reference(
        "maw-barber-fawcett-1976",
        "N. Maw, J. R. Barber, J. N. Fawcett, The oblique impact of elastic spheres, Wear 38 "
        "(1976) 101-114",
        "10.1016/0043-1648(76)90063-6",
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
)

#: Material data: handbooks and data sheets (``impactlab.materials.library``).
_MATERIAL_DATA: tuple[Reference, ...] = (
    Reference(
        "sae-j1397",
        "SAE J1397, Estimated mechanical properties and machinability of steel bars, SAE "
        "International (rev. May 1992); AISI/SAE 1010 cold drawn: tensile strength "
        "53,000 psi, yield 44,000 psi, elongation 20 % in 2 in., reduction of area 40 %, "
        "Brinell 105 (hot rolled: 47,000, 26,000 psi, 28 %, 50 %, 95); estimated minimum "
        "values for 20-30 mm (3/4-1 1/4 in) bars",
        url="https://summitsteel.com/mechanical-properties/carbon-steel/",
        note="the standard's scope (bar sizes, 2 in gauge) read in a public copy of J1397 "
        "rev. May 1992 (kupdf.net, 'SAE-J1397-92'), whose tables were not in reach; the 1010 "
        "rows read in reproductions that agree: Summit Steel, 'Mechanical Property | Carbon "
        "Steel, Estimated Minimum Values' (prints Brinell 106 for cold-drawn 1010); Maryland "
        "Metrics, 'Mechanical Properties of Standard Cold Drawn Steels' (scribd 293076924); "
        "Budynas & Nisbett, Shigley's Mechanical Engineering Design, 9th ed., Table A-20, "
        "p. 1040, source '1986 SAE Handbook, p. 2.15' (370 (53) and 300 (44) MPa (kpsi), "
        "pdfcoffee.com/table-a-20-pdf-free.html); and AZoM's 'AISI 1010 carbon steel' page "
        "(azom.com/article.aspx?ArticleID=6539), cold drawn: 365 MPa (52,900 psi), 305 MPa "
        "(44,200 psi), 20 %, 40 %, Brinell 105, 7.87 g/cm3: the paper's S_y, H and density",
    ),
    Reference(
        "johnson-cook-1983",
        "G. R. Johnson, W. H. Cook, A constitutive model and data for metals subjected to "
        "large strains, high strain rates and high temperatures, Proc. 7th Int. Symp. on "
        "Ballistics, The Hague (1983) 541-547; Table 1: 1006 steel, A = 350 MPa, B = 275 MPa, "
        "n = 0.36, C = 0.022, m = 1.00",
        note="proceedings paper, no DOI; pages as commonly cited, not confirmed here; the "
        "1006-steel constants confirmed against a secondary source that reproduces their table "
        "(table number not confirmed); used for 1006's rate term and for the earlier stand-in "
        "hardening of AISI 1010 (AISI_1010_WITH_1006_HARDENING); no published hardening law "
        "for AISI 1010 itself was found (docs/materials.md, Strain hardening)",
    ),
    Reference(
        "matweb-al6061-t6",
        "MatWeb, data sheet 'Aluminum 6061-T6; 6061-T651' (values of the Aluminum Association "
        "and Alcoa)",
        url="https://hallaweb.jlab.org/tech/Detectors/public_html/manuals/data_sheets-manuals/"
        "M-N/M/materials/nickel/08-11-04/MatWeb%20-%20Online%20Material%20Data%20Sheet.htm",
        note="a saved copy of the MatWeb data sheet; the same values (E 68.9 GPa, nu 0.33, "
        "S_y 276 MPa, HB 95, 2.70 g/cc) are on the data sheets that cite MatWeb",
    ),
    Reference(
        "matweb-aisi-304",
        "MatWeb, data sheet 'AISI Type 304 Stainless Steel' (annealed)",
        url="https://www.scribd.com/document/416534641/304-Stainless-Steel-pdf",
        note="a copy of the MatWeb data sheet",
    ),
    Reference(
        "asm-matweb-ti6al4v",
        "ASM Aerospace Specification Metals / MatWeb, data sheet 'Titanium Ti-6Al-4V (Grade 5), "
        "Annealed' (MTP641)",
        url="http://asm.matweb.com/search/SpecificMaterial.asp?bassnum=MTP641",
    ),
    Reference(
        "aisi-52100-ball",
        "AISI 52100 chrome steel balls, material specification (through-hardened, HRC 60-67); "
        "density and elastic constants also on the 52100 data sheet of www.stindia.com",
        url="https://ja.scribd.com/document/252517093/ASTM-52100-Material-Del-Tornillo-de-Potencia",
        note="a ball maker's specification sheet; E 29.5e6 psi, S_y 295,000 psi, "
        "0.283 lb/in^3; Poisson's ratio 0.27-0.30 from "
        "https://www.stindia.com/article/difference-between/difference-between-52100-e52100-steel.html",
    ),
    Reference(
        "cda-c36000",
        "Copper Development Association data for C36000 free-cutting brass (ASTM B16), typical "
        "values for 1 in rod, half-hard temper (H02)",
        url="https://www.brass-copper-castings.com/casting-alloys-copper-bronze-brass/"
        "free-machining-brass-c36000.html",
        note="E 14,000 ksi, S_y 45 ksi, 0.307 lb/in^3; Poisson's ratio 0.31 from the MatWeb "
        "values at https://www.ezlok.com/technical-info/mechanical-properties/brass",
    ),
    Reference(
        "smithells-2004-copper",
        "W. F. Gale, T. C. Totemeier (eds.), Smithells Metals Reference Book, 8th ed., "
        "Elsevier (2004), Table 22.7: oxygen-free high-conductivity copper, strip, annealed (O)",
        url="http://www.globalspec.com/reference/26187/203279/"
        "22-2-mechanical-properties-of-copper-and-copper-alloys",
        note="0.2 % proof stress 48 MPa, HB 42, E 117 GPa; density 8.94 g/cm^3 (C10200, "
        "https://www.lfa-wire.com/copper-wire-oxygen-free-high-conductivity_c10200.htm); "
        "Poisson's ratio 0.34 (annealed C10800, makeitfrom.com)",
    ),
    Reference(
        "makeitfrom-wc",
        "MakeItFrom.com, 'Tungsten Carbide (WC)' (sources: Pierson, Handbook of Refractory "
        "Carbides and Nitrides, 1996; Martienssen & Warlimont, Springer Handbook of Condensed "
        "Matter and Materials Data, 2005)",
        url="https://www.makeitfrom.com/material-properties/Tungsten-Carbide-WC",
    ),
    Reference(
        "nist-srd30-alumina",
        "NIST Standard Reference Database 30/150, 'Sintered Alumina (Al2O3)', 99.5 % or higher, "
        "from R. G. Munro, Evaluated material properties for a sintered alpha-alumina, "
        "J. Am. Ceram. Soc. 80 (1997) 1919-1928",
        "10.18434/T42G62",
        note="E 416(30) GPa, density 3.984 g/cm^3, compressive strength 3.0(5) GPa at 20 degC; "
        "Poisson's ratio 0.22-0.24 (alumina grades, makeitfrom.com)",
    ),
    Reference(
        "makeitfrom-soda-lime",
        "MakeItFrom.com, 'Annealed Soda-Lime Glass'; density and E of window glass from the "
        "table of soda-lime glass properties (Wikipedia, 'Soda-lime glass')",
        url="https://www.makeitfrom.com/material-properties/Annealed-Soda-Lime-Glass",
        note="nu 0.23, compressive strength 330 MPa; E 72 GPa and 2.52 g/cm^3 (container "
        "glass) from http://www.liquisearch.com/soda-lime_glass/typical_compositions_and_properties",
    ),
    Reference(
        "usplastic-acrylic-sheet",
        "U.S. Plastic Corp., data sheet 'Physical Properties for Extruded Acrylic Sheet' (typical "
        "values, 0.250 in sheet; ASTM D792, D638, D695)",
        url="https://www.usplastic.com/knowledgebase/article.aspx?contentkey=533",
        note="specific gravity 1.19 (D792); modulus of elasticity (D638) printed "
        "'4000,000 psi (2,800 MPa)', a misprint of 400,000 psi: the printed 2,800 MPa taken; "
        "compressive strength (yield, D695) 17,000 psi (117 MPa); Rockwell M-93, no Brinell "
        "hardness, no Poisson's ratio. ASTM D695's standard test: 1.3 mm/min crosshead speed, "
        "23 +/- 2 degC (https://www.micomlab.com/micom-testing/astm-d695/)",
    ),
    Reference(
        "crc-sound-speed",
        "CRC Handbook of Chemistry and Physics, section 14, 'Speed of sound in various media', "
        "Table 1 (from D. E. Gray (ed.), American Institute of Physics Handbook, 3rd ed., 1972, "
        "and W. P. Mason, Physical Acoustics and the Properties of Solids, 1958): Lucite "
        "(PMMA), density 1.18 g/cm^3, v_l = 2680 m/s, v_s = 1100 m/s, v_ext = 1840 m/s",
        url="https://hbcp.chemnetbase.com/faces/documents/14_19/14_19_0001.xhtml",
        note="the table's heading, references and metal rows read at the address; the Lucite "
        "row read in the table's reproduction (same metal rows) at https://rudywinoto.com/"
        "flow-measurement/flow-meters/type-flow-meters/ultrasonic-flow-meter/"
        "sound-velocity-of-material/; dynamic (ultrasonic) nu = (v_l^2 - 2 v_s^2) / "
        "(2 (v_l^2 - v_s^2)) = 0.399, and rho v_ext^2 / (2 rho v_s^2) - 1 = 0.399 agrees",
    ),
)

REFERENCES: MappingProxyType[str, Reference] = MappingProxyType(
    {r.key: r for r in (*_ALL, *_MATERIAL_DATA)}
)
"""key -> Reference: every source the package cites (read-only)."""


def cite(*keys: str) -> tuple[Reference, ...]:
    """The references registered under ``keys``, in order; ValueError for an unknown key."""
    unknown = [key for key in keys if key not in REFERENCES]
    if unknown:
        raise ValueError(f"unknown reference key(s) {unknown}; known: {', '.join(REFERENCES)}")
    return tuple(REFERENCES[key] for key in keys)


def dois(references: tuple[Reference, ...]) -> tuple[str, ...]:
    """The DOIs of ``references`` (those that have one), in order, without repeats."""
    return tuple(dict.fromkeys(r.doi for r in references if r.doi))


__all__ = ["DOI_PATTERN", "PAPER", "REFERENCES", "Reference", "cite", "dois"]
