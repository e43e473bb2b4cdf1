"""The handbooks and data sheets of the material library and the flat's strain hardening."""

from __future__ import annotations

from impactlab.references.reference import Reference

__all__ = ["MATERIAL_DATA"]

#: Material data: handbooks and data sheets (``impactlab.materials.library``).
MATERIAL_DATA: tuple[Reference, ...] = (
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
        "Ballistics, The Hague (1983) 541-547; their table of constants: 1006 steel, "
        "A = 350 MPa, B = 275 MPa, n = 0.36, C = 0.022, m = 1.00",
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
        "MakeItFrom.com, 'Annealed Soda-Lime Glass'; density and E of container glass (the "
        "table's container column; window glass: 74 GPa, 2.53 g/cm^3) from the table of "
        "soda-lime glass properties (Wikipedia, 'Soda-lime glass')",
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
