"""impactlab.fe without running ccx: input checks, the missing-ccx message, parsing, cache."""

from __future__ import annotations

import json
import math
import sys

import numpy as np
import pytest

import impactlab.fe as fe
from impactlab.fe import cache
from impactlab.fe.ccx import INSTALL_HINT, find_ccx, parse_dat, parse_sta
from impactlab.fe.deck import write_deck
from impactlab.fe.mesh import build_mesh
from impactlab.fe.problem import make_problem
from impactlab.fe.result import contact_radius_from_gap, zero_crossing
from impactlab.materials import AISI_201, AISI_1010

R = 8.8e-3


def test_import_needs_neither_ccx_nor_gmsh(monkeypatch):
    """The package imports without gmsh (it is imported inside build_mesh)."""
    monkeypatch.setitem(sys.modules, "gmsh", None)
    from impactlab.fe.mesh import MeshSpec, build_mesh

    with pytest.raises(ImportError, match="pip install 'impactlab\\[fe\\]'"):
        build_mesh(MeshSpec(R, 1e-6, 0.1, 1e-2, 1e-3, R))


def test_missing_ccx_message(monkeypatch, tmp_path):
    monkeypatch.setenv("PATH", str(tmp_path))
    monkeypatch.delenv("IMPACTLAB_CCX", raising=False)
    with pytest.raises(RuntimeError) as info:
        find_ccx()
    msg = str(info.value)
    assert "apt-get install calculix-ccx" in msg
    assert "\n" not in msg
    with pytest.raises(RuntimeError, match="apt-get install calculix-ccx"):
        fe.indent(AISI_1010, AISI_201, radius=R, delta_max=1e-6, cache_dir=tmp_path)
    monkeypatch.setenv("IMPACTLAB_CCX", str(tmp_path / "ccx-elsewhere"))
    with pytest.raises(RuntimeError, match=r"IMPACTLAB_CCX is set to '.*ccx-elsewhere'"):
        find_ccx()


def test_beyond_the_checked_interference_warns_before_ccx_runs(monkeypatch, tmp_path):
    """An indentation past 1000 delta_c (where the shipped cases end and the mesh was checked)
    or below 0.3 delta_c (where they start) warns before any ccx run; between them it does not."""
    import warnings

    from impactlab.fe.run import CHECKED_RATIO, SMALLEST_CHECKED_RATIO, BeyondCheckedWarning

    monkeypatch.setenv("PATH", str(tmp_path))  # no ccx: the call stops after the checks
    monkeypatch.delenv("IMPACTLAB_CCX", raising=False)
    dc = make_problem(AISI_1010, AISI_201, radius=R, delta_max=1e-6).delta_c
    beyond = pytest.warns(BeyondCheckedWarning, match=r"delta_max = 2000 delta_c is beyond 1000")
    no_ccx = pytest.raises(RuntimeError, match="apt-get install calculix-ccx")
    with beyond, no_ccx:
        fe.indent(AISI_1010, AISI_201, radius=R, delta_max=2000 * dc, cache_dir=tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("error", BeyondCheckedWarning)
        for ratio in (CHECKED_RATIO, SMALLEST_CHECKED_RATIO):
            with pytest.raises(RuntimeError, match="apt-get install calculix-ccx"):
                fe.indent(AISI_1010, AISI_201, radius=R, delta_max=ratio * dc, cache_dir=tmp_path)
    below = pytest.warns(BeyondCheckedWarning, match=r"delta_max = 0.001 delta_c is below 0.3 ")
    with below, pytest.raises(RuntimeError, match="apt-get install calculix-ccx"):
        fe.indent(AISI_1010, AISI_201, radius=R, delta_max=1e-3 * dc, cache_dir=tmp_path)


def test_a_run_that_does_not_converge_exits_with_status_2(cli_main, monkeypatch, tmp_path):
    """What was computed is printed; the exit status says that not every run converged."""
    fake = tmp_path / "ccx"
    fake.write_text('#!/bin/sh\nif [ "$1" = "-v" ]; then echo "This is Version 2.23"; fi\nexit 3\n')
    fake.chmod(0o755)
    monkeypatch.setenv("IMPACTLAB_CCX", str(fake))
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path / "cache"))  # no cache entry kept
    code, out, err = cli_main("fe", "indent", "--max", "5 um", "--no-cache")
    assert code == 2 and "NOT CONVERGED" in out
    assert "error: 1 of 1 FE run(s) did not converge (delta_max = 5 um)" in err


@pytest.mark.parametrize(
    ("kwargs", "pattern"),
    [
        ({"delta_max": 9e-3}, r"delta_max \(0\.009 m\) must be smaller than the sphere radius"),
        ({"delta_max": 5e-3}, r"delta_max .* too large for radius .* allowed delta_max <"),
        ({"delta_max": -1e-6}, "delta_max"),
        ({"delta_max": 1e-6, "sphere": "glass"}, "sphere must be one of rigid, elastic"),
        ({"delta_max": 1e-6, "mesh_level": 9}, r"mesh_level must be one of \[1, 2, 3, 4\]"),
        ({"delta_max": 1e-6, "mu": -0.1}, "mu"),
        (
            {"delta_max": 1e-6, "flat_hardening": [[305e6, 0.0], [400e6, 0.1], [380e6, 0.2]]},
            "flat_hardening must be monotonic",
        ),
        (
            {"delta_max": 1e-6, "flat_hardening": [[305e6, 0.0], [400e6, 0.1], [420e6, 0.05]]},
            "flat_hardening must be monotonic",
        ),
        ({"delta_max": 1e-6, "sphere_hardening": [[305e6, 0.01]]}, "must start at plastic"),
        (
            {"delta_max": 1e-6, "flat_hardening": [[305.0, 0.0], [400.0, 0.1]]},
            r"flat_hardening must start at the material's yield strength S_y = 3.05e\+08 Pa .*"
            r"got a first stress of 305.0 Pa \(stresses are in Pa",
        ),
        (
            {"delta_max": 1e-6, "sphere_hardening": [[500e6, 0.0], [900e6, 0.1]]},
            r"sphere_hardening must start at the material's yield strength S_y = 7.6e\+08 Pa",
        ),
        ({"delta_max": 1e-6, "flat_hardening": [1, 2, 3]}, "flat_hardening must be rows"),
        ({"delta_max": 1e-6, "unload": "no"}, "unload must be True or False, got 'no'"),
        ({"delta_max": 1e-6, "unload": 0}, "unload must be True or False, got 0"),
    ],
)
def test_bad_input_one_line(kwargs, pattern):
    with pytest.raises(ValueError, match=pattern) as info:
        make_problem(AISI_1010, AISI_201, radius=R, **kwargs)
    assert "\n" not in str(info.value)


def test_delta_max_with_units_and_delta_c():
    p = make_problem(AISI_1010, AISI_201, radius="8.8 mm", delta_max="20 um")
    assert p.delta_max == pytest.approx(20e-6)
    assert p.radius == pytest.approx(R)
    from impactlab.contact import get_law
    from impactlab.materials import ContactPair

    law = get_law("ghaednia").build(ContactPair(AISI_201, AISI_1010), radius=R)
    assert p.delta_c == pytest.approx(law.critical_interference, rel=1e-12)


def test_hardening_table_accepted():
    table = fe.check_hardening("t", [[305e6, 0.0], [400e6, 0.1], [450e6, 0.3]])
    assert table == ((305e6, 0.0), (400e6, 0.1), (450e6, 0.3))


def test_cache_dir_default_and_env(monkeypatch, tmp_path):
    monkeypatch.delenv("IMPACTLAB_FE_CACHE", raising=False)
    monkeypatch.delenv("IMPACTLAB_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert cache.default_cache_dir() == tmp_path / "xdg" / "impactlab" / "fe"
    monkeypatch.setenv("IMPACTLAB_FE_CACHE", str(tmp_path / "here"))
    assert cache.default_cache_dir() == tmp_path / "here"


def test_cache_key_covers_every_input():
    a = make_problem(AISI_1010, AISI_201, radius=R, delta_max=1e-6).key_data()
    b = make_problem(AISI_1010, AISI_201, radius=R, delta_max=1e-6, mu=0.1).key_data()
    assert cache.cache_key(a, "2.20") == cache.cache_key(dict(a), "2.20")
    assert cache.cache_key(a, "2.20") != cache.cache_key(b, "2.20")
    assert cache.cache_key(a, "2.20") != cache.cache_key(a, "2.21")
    c = make_problem(AISI_1010, AISI_201, radius=R, delta_max=1e-6, unload=False).key_data()
    assert cache.cache_key(a, "2.20") != cache.cache_key(c, "2.20")
    assert "unload" not in a  # a complete run's key is what it was before the option


def test_loading_only_deck_has_one_step():
    """``unload=False``: the deck ends after the loading step; the loading step's text is the
    complete run's."""
    pytest.importorskip("gmsh", reason="the deck needs a mesh (the fe extra)")
    full = make_problem(AISI_1010, AISI_201, radius=R, delta_max=1e-6)
    only = make_problem(AISI_1010, AISI_201, radius=R, delta_max=1e-6, unload=False)
    mesh = build_mesh(full.mesh_spec())
    a = write_deck(mesh, full.deck_spec(mesh.spec))
    b = write_deck(mesh, only.deck_spec(mesh.spec))
    assert a.count("*STEP") == 2 and b.count("*STEP") == 1
    assert "UNLOAD" not in b
    assert b.split("*STEP", 1)[1] == a.split("*STEP", 2)[1]


def test_parse_sta_counts_cutbacks():
    text = (
        "SUMMARY OF JOB INFORMATION\n"
        "  STEP      INC     ATT  ITRS     TOT TIME     STEP TIME      INC TIME\n"
        "     1          1     1     8  0.250000E-01  0.250000E-01  0.250000E-01\n"
        "     1          2     1U   60  0.250000E-01  0.250000E-01  0.250000E-01\n"
        "     1          2     2     5  0.375000E-01  0.375000E-01  0.125000E-01\n"
    )
    rows = parse_sta(text)
    assert [r.converged for r in rows] == [True, False, True]
    assert rows[2].attempt == 2
    assert rows[2].total_time == pytest.approx(0.0375)


def test_parse_dat_totals_and_nodes():
    text = (
        "\n total force (fx,fy,fz) for set NTOP and time  0.2500000E-01\n\n"
        "        2.847133E-08 -6.197790E-05 -7.978350E-25\n\n"
        " displacements (vx,vy,vz) for set NFSURF and time  0.2500000E-01\n\n"
        "         1  0.000000E+00 -4.976786E-06  0.000000E+00\n"
        "         5 -8.622471E-08 -5.374086E-06  0.000000E+00\n"
    )
    dat = parse_dat(text)
    t, vec = dat.totals[("force", "NTOP")][0]
    assert t == pytest.approx(0.025)
    assert vec[1] == pytest.approx(-6.19779e-5)
    _, ids, u = dat.nodal[("displacements", "NFSURF")][0]
    assert ids.tolist() == [1, 5]
    assert u[1, 1] == pytest.approx(-5.374086e-6)


def test_zero_crossing_and_contact_radius():
    d = np.array([10.0, 9.0, 8.0, 7.0])
    f = np.array([4.0, 2.0, -0.0, 0.0])
    assert zero_crossing(d, f) == pytest.approx(8.0)
    assert np.isnan(zero_crossing(d, np.array([4.0, 3.0, 2.0, 1.0])))
    r = np.array([0.0, 1.0, 2.0, 3.0])
    assert contact_radius_from_gap(r, np.array([-1.0, -1.0, 1.0, 2.0])) == pytest.approx(1.5)
    assert INSTALL_HINT.startswith("CalculiX (ccx) was not found")


def test_cli_errors_are_one_line(tmp_path, cli_main, monkeypatch):
    code, _, err = cli_main("fe", "indent", "--max", "9 mm")
    assert code == 2, err
    assert "--max '9 mm'" in err and "sphere radius" in err and "bare number" not in err
    assert len(err.strip().splitlines()) == 1
    table = tmp_path / "h.csv"
    table.write_text("stress,strain\n305e6,0\n300e6,0.1\n")
    code, _, err = cli_main("fe", "indent", "--max", "1 um", "--hardening", str(table))
    assert code == 2
    assert "--hardening must be monotonic" in err
    monkeypatch.setenv("PATH", str(tmp_path))
    monkeypatch.setenv("IMPACTLAB_CCX", "")
    code, _, err = cli_main("fe", "indent", "--max", "1 um")
    assert code == 2
    assert "apt-get install calculix-ccx" in err
    assert "Traceback" not in err


def test_cli_loading_only(cli_main, monkeypatch):
    """``--loading-only`` passes ``unload=False``; its summary has no delta_r (null)."""
    seen = {}

    def fake_indent(flat, body, **kwargs):
        seen.update(kwargs)
        d = np.array([0.0, 0.5e-6, 1e-6])
        none = np.empty(0)
        res = fe.IndentationResult(
            1e-6, d, 10.0 * d / 1e-6, d, none, none, math.nan, none, none, 0.4e-6, True,
            1e-6, "", 2, 0, 6, 1.0, 100, 0.0, {},
        )  # fmt: skip
        return [res]

    monkeypatch.setattr(fe, "indent", fake_indent)
    monkeypatch.setattr(fe, "find_ccx", lambda: "ccx")
    code, out, err = cli_main("fe", "indent", "--max", "1 um", "--loading-only", "--json")
    assert code == 0, err
    assert seen["unload"] is False
    run = json.loads(out)["runs"][0]
    assert run["residual_depth"]["value"] is None and run["unloading_force"] == []
    code, _, err = cli_main("fe", "indent", "--max", "1 um", "--json")
    assert code == 0, err
    assert seen["unload"] is True


def test_mesh_resolution_is_checked_against_the_requested_interference():
    """Every level-1 mesh puts about 17 or more elements across sqrt(R delta_max); a mesh with 8 or
    fewer is refused with a one-line error naming delta_max."""
    import dataclasses
    import math

    from impactlab.fe.problem import (
        MIN_CONTACT_ELEMENTS,
        check_resolution,
        contact_elements,
        make_problem,
    )
    from impactlab.materials import AISI_201, AISI_1010

    for dmax in (1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 4e-4):
        p = make_problem(AISI_1010, AISI_201, radius=8.8e-3, delta_max=dmax)
        assert contact_elements(p.mesh_spec(), dmax) >= 16.9  # ln(1 + sqrt(20)) / 0.1
    spec = p.mesh_spec()
    coarse = dataclasses.replace(spec, h0=math.sqrt(spec.radius * 4e-4))
    assert contact_elements(coarse, 4e-4) < MIN_CONTACT_ELEMENTS
    with pytest.raises(ValueError, match=r"too coarse for delta_max = 0.0004 m"):
        check_resolution(coarse, 4e-4)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("--flat-nu", "0.6"), "error: --flat-nu: nu must lie in (-1.0, 0.5), got 0.6"),
        (("--flat-sy", "276 GPa"), "error: --flat-sy: yield_strength (2.76e+11 Pa) must be"),
    ],
)
def test_a_material_option_is_named_in_its_error(cli_main, args, message):
    values = {"--flat-E": "200 GPa", "--flat-nu": "0.3", "--flat-sy": "276 MPa"} | dict([args])
    code, _, err = cli_main(
        "fe", "indent", "--max", "1 um", *(x for kv in values.items() for x in kv)
    )
    assert code == 2 and err.startswith(message) and err.count("\n") == 1


def test_a_bare_maximum_is_said_to_be_metres(cli_main):
    code, _, err = cli_main("fe", "indent", "--max", "5")
    assert code == 2 and "a bare number is in m: give a unit, e.g. '5 um'" in err


@pytest.mark.parametrize(
    ("table", "message"),
    [
        ([[305e6, 0.0], [1e15, 0.1]], r"a true stress of 1e\+15 Pa is not below E"),
        ([[305e6, 0.0], [400e6, 1e6]], r"a true plastic strain of 1e\+06 \(allowed: up to 5\)"),
        ([[305e6, 0.0], [math.nan, 0.1]], r"must be finite, got row 2 \(nan, 0.1\)"),
    ],
)
def test_a_hardening_table_that_is_no_metals_is_refused(table, message):
    from impactlab.fe.problem import make_problem

    with pytest.raises(ValueError, match=message):
        make_problem(AISI_1010, AISI_201, radius=R, delta_max=1e-6, flat_hardening=table)


def test_one_run_asked_two_ways_has_one_cache_key():
    """'5 um' converts to 4.9999999999999996e-06: the inputs are kept to 15 significant digits,
    so it and 5e-6 are the same run (the cache does not compute it again)."""
    from impactlab.fe.problem import make_problem

    spelled = make_problem(AISI_1010, AISI_201, radius="8.8 mm", delta_max="5 um")
    plain = make_problem(AISI_1010, AISI_201, radius=0.0088, delta_max=5e-6)
    assert spelled.delta_max == 5e-6 and spelled.key_data() == plain.key_data()
