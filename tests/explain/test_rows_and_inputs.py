"""Each row states its law's range, delta_c and (a rate row) its strain rate, the JSON its
sources; the summary counts contacts as ``n_contacts``; an ``--out`` that cannot be made is
refused before any run; error texts fit their situation; a library rate law keeps its label
however asked for; the rigid configuration is the drop's rigid body, a sphere's too."""

from __future__ import annotations

import math

import pytest

import impactlab.explain
from impactlab.calibrate.measurements import Measurements
from impactlab.contact.rate import RateLaw
from impactlab.explain import configurations, explain
from impactlab.explain.api import ELASTIC_NOT_RUN
from impactlab.explain.configurations import LIBRARY_RATES, RIGID
from impactlab.explain.result import NOTHING_TUNED

CS, JC = (c.name for c in LIBRARY_RATES)
DROP = {"label": "a", "angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.5, "e_sigma": 0.03}


def test_rows_state_their_range_delta_c_and_strain_rate(paper_explained) -> None:
    s = paper_explained.summary.set_index(["drop", "configuration"])
    assert "contacts" not in s.columns and list(s.xs("20 deg")["n_contacts"]) == [1, 4, 4, 4]
    cs = s.loc[("20 deg", CS)]
    assert cs["strain_rate"] == pytest.approx(485.9, abs=0.1)
    assert "E*/S_y = 136.2" in cs["law_range"] and cs["law_range"].startswith("verified")
    flexible = s.loc[("20 deg", "flexible rod")]
    assert math.isnan(flexible["strain_rate"]) and "E*/S_y = 360.3" in flexible["law_range"]
    for name in ("flexible rod", CS, JC, RIGID.name):  # the ghaednia law's reference: delta_c
        res = paper_explained.result("20 deg", name)
        ref = res.delta_max / res.max_delta_ratio
        assert s.loc[("20 deg", name), "delta_c"] == pytest.approx(ref, rel=1e-9)
    assert cs["delta_c"] / flexible["delta_c"] == pytest.approx(7.0, abs=0.1)  # S_y raised
    doc = paper_explained.to_dict()
    row = next(r for r in doc["summary"] if r["configuration"] == CS)
    assert row["strain_rate"]["unit"] == "1/s" and row["delta_c"]["unit"] == "m"
    assert row["n_contacts"] == 4 and "contacts" not in row and row["law_range"]
    refs = doc["references"]
    assert len(refs) == len(set(refs)) and any("doi:10.1007/s00419-015-1108-2" in r for r in refs)
    assert any("Cowper" in r for r in refs)


def test_out_under_a_file_is_refused_before_any_run(cli_main, paper_file, tmp_path,
                                                    monkeypatch) -> None:  # fmt: skip
    def never(*args: object, **kwargs: object) -> None:
        raise AssertionError("ran")

    monkeypatch.setattr(impactlab.explain, "explain", never)
    (tmp_path / "afile").write_text("")
    for out in (tmp_path / "afile" / "sub", tmp_path / "afile" / "sub" / "deeper"):
        code, stdout, err = cli_main("explain", str(paper_file), "-q", "--out", str(out))
        assert code == 2 and stdout == "" and err.count("\n") == 1, err
        assert err.startswith(f"error: --out {str(out)!r}: ") and "is a file" in err


def test_rate_laws_of_the_wrong_kind_are_refused_by_name() -> None:
    for bad, kind in ((5, "int"), (3.5, "float"), (b"none", "bytes"), ({"a": 1}, "dict")):
        words = r"^rate_laws must be None \(the library's rate laws\), a rate law or a list of "
        with pytest.raises(ValueError, match=rf"{words}rate laws .*; got .* \({kind}\)$"):
            explain(Measurements.from_records([DROP]), rate_laws=bad)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^--rate must be None"):
        configurations(5, "--rate")  # type: ignore[arg-type]


def test_a_toml_drop_without_mu_is_named_with_its_file_and_place(tmp_path) -> None:
    toml = tmp_path / "m.toml"
    drop = 'angle = "20 deg"\nvy = "-1.41 m/s"\ne = 0.5\ne_sigma = 0.03\n'
    toml.write_text(f'[[drop]]\nlabel = "a"\nmu = 0.2\n{drop}[[drop]]\nlabel = "b"\n{drop}')
    with pytest.raises(ValueError, match="gives no mu") as err:
        explain(toml)
    assert str(err.value) == (
        f"{toml}: drop 2 (b) gives no mu: explain runs every drop with its measured mu as the "
        "Coulomb coefficient (nothing tuned); give each [[drop]] its mu key"
    )
    csv = tmp_path / "m.csv"
    csv.write_text("label,angle [deg],vy [m/s],mu,e,e_sigma\na,20,-1.41,,0.5,0.03\n"
                   "b,20,-1.41,0.2,0.5,0.03\nc,20,-1.41,,0.5,0.03\n")  # fmt: skip
    with pytest.raises(ValueError, match=rf"^{csv}: drops 1 \(a\), 3 \(c\) give no mu: .*; "
                       "fill in each drop's mu cell$"):  # fmt: skip
        explain(csv)


def test_error_texts_fit_the_situation() -> None:
    partial = [DROP, {**DROP, "label": "b", "mu": math.nan}]
    with pytest.raises(ValueError, match=r"^drop 2 \(b\) gives no mu: .*give each drop its mu$"):
        explain(Measurements.from_records(partial))
    assert len(configurations([None])) == len(configurations(["none"])) == 2
    with pytest.raises(ValueError, match="give 'none' alone for no rate row"):
        configurations([None, "cowper-symonds"])
    x = explain(Measurements.from_records([DROP]), law="hertz")
    status = x.summary.set_index("configuration")["status"]
    for name in (CS, JC):
        assert status[name] == ELASTIC_NOT_RUN.format(law="hertz")
    assert "--rate none" in ELASTIC_NOT_RUN and "rate=None" not in ELASTIC_NOT_RUN


def test_a_library_law_keeps_its_label_and_is_run_once() -> None:
    assert [c.name for c in configurations(["cowper-symonds", "johnson-cook"])[2:]] == [CS, JC]
    with pytest.raises(ValueError, match=r"--rate: cowper-symonds and cowper-symonds\(D=40.4 1/s, "
                       r"q=5\) are the same law .* given twice"):  # fmt: skip
        configurations(["cowper-symonds", "cowper-symonds(D=40.4 1/s, q=5)"], "--rate")
    # given by its own constants, in any form, it is the library's law: label, material check
    for given in ("cowper-symonds(D=40.4 1/s, q=5)", "cowper-symonds (D = 0.0404 1/ms, q = 5)",
                  RateLaw.custom("cowper-symonds", D="40.4 1/s", q=5)):  # fmt: skip
        same = configurations([given])[2]
        assert same == LIBRARY_RATES[0] and same.name == CS
        assert same.rate is not None and same.rate.fitted_for is not None
    assert configurations(["johnson-cook(C=0.022, rate0=1 1/s)"])[2] == LIBRARY_RATES[1]
    # other constants are one's own law: its constants in the name, no material check
    own = configurations(["cowper-symonds(D=40 1/s, q=5)"])[2]
    assert own.rate is not None and own.rate.fitted_for is None and "estimate" not in own.name


def test_the_rigid_configuration_is_the_drops_rigid_body() -> None:
    assert RIGID.name == "rigid body" and "rigid sphere" in RIGID.description
    sphere = {"label": "s", "body": "sphere", "radius": "5 mm", "vy": -1.0, "mu": 0.2,
              "e": 0.9, "e_sigma": 0.03}  # fmt: skip
    x = explain(Measurements.from_records([sphere]))
    assert x.verdict("s").configuration in (RIGID.name, None)
    assert "rigid rod" not in x.verdict("s").reason


def test_the_rate_rows_say_the_rod_is_raised_so_that_the_flat_yields_first() -> None:
    for text in (LIBRARY_RATES[0].description, NOTHING_TUNED):
        assert "1.5 times the raised flat's" in text
        assert "a flat that yields first still does" in text
        assert "a rod that yields first is left as it is" in text
