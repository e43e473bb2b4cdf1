"""What would make a study's results wrong or every case of a body fail is refused when the
study is built (a rod other than the paper's without its mass, a tip wider than half the rod);
a run none of whose cases succeeded says so on stderr and exits with status 2; the uncertainty
report refuses codes (``regime``, ``flags``); an export never writes over a user's file."""

from __future__ import annotations

import pytest
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import Normal, Sample, Study, export_file, open_sweep, run_sweep
from impactlab.sweep.uncertainty import uncertainty_report

KIN = {"vy": "-1.41 m/s", "angle": "20 deg"}
MASS = r"^mass: give it for a rod other than the paper's \({}\): the default is the paper's"


@pytest.mark.parametrize(
    ("fixed", "grid", "why"),
    [
        ({"body_material": "al-6061-t6"}, {}, "body_material = 'al-6061-t6'"),
        ({}, {"body_material": ["aisi-201", "brass-c360"]}, "body_material = 'brass-c360'"),
        ({"length": 0.1}, {}, "length = 0.1 m"),
        ({"body": "flexible_rod", "length": "200 mm"}, {}, "length = 0.2 m"),
    ],
)
def test_a_rod_other_than_the_papers_needs_its_mass(fixed, grid, why) -> None:
    with pytest.raises(ValueError, match=MASS.format(why)):
        Study(name="s", fixed={**KIN, **fixed}, grid={"mu": [0.1, 0.2], **grid})
    Study(name="s", fixed={**KIN, **fixed, "mass": 0.16}, grid={"mu": [0.1, 0.2], **grid})


def test_the_papers_rod_and_spheres_keep_their_defaults() -> None:
    Study(name="s", fixed={**KIN, "length": 0.3048}, grid={"mu": [0.1, 0.2]})
    Study(name="s", fixed={"vy": -1.0, "body": "sphere", "radius": 0.005,
                           "body_material": "al-6061-t6"}, grid={"mu": [0.1]})  # fmt: skip


@pytest.mark.parametrize(
    ("fixed", "grid", "words"),
    [
        ({"tip_radius": "8.8 m"}, {}, "tip_radius = 8.8 m exceeds half the rod's length"),
        ({"length": 0.001, "mass": 0.01}, {}, "exceeds half the rod's length (0.0005 m)"),
        ({"mass": 0.1}, {"length": [0.001, 0.002]}, "exceeds half the rod's length"),
        ({"body": "flexible_rod", "tip_radius": "0.3 m"}, {}, "must not exceed half the length"),
    ],
)
def test_a_body_no_case_can_make_is_refused_in_its_own_words(fixed, grid, words) -> None:
    with pytest.raises(ValueError, match=r"every case of body '.*' would fail") as err:
        Study(name="s", fixed={**KIN, **fixed}, grid={"mu": [0.1, 0.2, 0.3], **grid})
    assert words in str(err.value)


def test_a_body_some_cases_can_make_runs() -> None:
    Study(name="s", fixed={**KIN, "mu": 0.2, "mass": 0.1}, grid={"length": [0.001, 0.3]})


def test_a_run_without_one_successful_case_exits_2(tmp_path, monkeypatch, capsys) -> None:
    study = tmp_path / "all-fail.toml"
    study.write_text(
        '[fixed]\nvy = "-1.41 m/s"\nangle = "20 deg"\nlaw = "brake"\n'
        'flat_material = "brass-c360"\n[grid]\nmu = [0.1, 0.2, 0.3]\n'
    )
    store = tmp_path / "all-fail.zarr"
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "run", str(study), "--out", str(store),
                           "--quiet")  # fmt: skip
    assert code == 2, err
    assert err.startswith("error: no case of study 'all-fail' succeeded (3 with status 103"), err
    assert open_sweep(store)["status"].size == 3  # the store keeps them


def _sample_store(tmp_path):
    study = Study(
        name="mc",
        fixed={"vy": -1.41, "law": "hertz"},
        sample=Sample(
            size=40, seed=1, inputs={"angle": Normal(0.35, 0.01), "mu": Normal(0.2, 0.01)}
        ),
        outputs=["e", "delta_p", "regime"],
    )
    return run_sweep(study, tmp_path / "mc.zarr", evaluator=FakeEvaluator(), quiet=True).path


@pytest.mark.parametrize("output", ["regime", "flags"])
def test_the_uncertainty_report_refuses_codes(tmp_path, monkeypatch, capsys, output) -> None:
    store = _sample_store(tmp_path)
    ds = open_sweep(store)
    with pytest.raises(ValueError, match=f"output '{output}' holds .*, not a quantity") as err:
        uncertainty_report(ds, outputs=[output])
    assert "choose among e, delta_p" in str(err.value) and "regime," not in str(err.value)
    args = ("sweep", "uncertainty", str(store), "--output", output)
    code, out, err_text = run_cli(monkeypatch, capsys, *args)
    assert code == 2 and out == "" and "not a quantity" in err_text


def test_an_export_never_writes_over_a_users_file(tmp_path, monkeypatch, capsys) -> None:
    store = _sample_store(tmp_path)
    for name in ("mine.csv", "mine.nc"):
        mine = tmp_path / name
        mine.write_text("my data\n")
        code, _, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(mine))
        assert code == 2 and "was not written by an impactlab sweep export" in err, err
        assert mine.read_text() == "my data\n"
        with pytest.raises(ValueError, match="it is left as it is"):
            export_file(open_sweep(store), mine)
        ours = tmp_path / f"ours{mine.suffix}"
        for _ in range(2):  # an export's own file is replaced
            code, _, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(ours))
            assert code == 0, err


def test_run_netcdf_refuses_a_users_file_before_the_study_runs(
    tmp_path, monkeypatch, capsys
) -> None:
    study = tmp_path / "s.toml"
    study.write_text('[fixed]\nvy = "-1.41 m/s"\nangle = "20 deg"\n[grid]\nmu = [0.1, 0.2]\n')
    mine = tmp_path / "mine.nc"
    mine.write_text("my data\n")
    store = tmp_path / "s.zarr"
    args = ("sweep", "run", str(study), "--out", str(store), "--netcdf", str(mine), "--quiet")
    code, _, err = run_cli(monkeypatch, capsys, *args)
    assert code == 2 and err.startswith("error: --netcdf"), err
    assert not store.exists() and mine.read_text() == "my data\n"


def test_a_flexible_study_with_a_loose_rtol_is_refused_when_built() -> None:
    """A drop's rtol is at most 1e-5; a study of flexible rods asking for more is refused when
    built, not run as cases that all fail with a status about their inputs."""
    from impactlab.sweep.options import EngineOptions

    with pytest.raises(ValueError, match=r"\[engine\] rtol 0\.0001 is too loose for a flexible"):
        Study(
            name="flex", grid={"angle": [0.8, 1.2]},
            fixed={"vy": -1.0, "mu": 0.1, "body": "flexible_rod"},
            engine=EngineOptions(rtol=1e-4), outputs=["e", "dent_depth"],
        )  # fmt: skip
    Study(
        name="flex", grid={"angle": [0.8, 1.2]},
        fixed={"vy": -1.0, "mu": 0.1, "body": "flexible_rod"},
        engine=EngineOptions(rtol=1e-5), outputs=["e"],
    )  # fmt: skip


@pytest.mark.parametrize("output", ["regime", "flags"])
def test_a_study_file_asking_the_report_for_codes_is_refused_when_read(tmp_path, output) -> None:
    from impactlab.sweep import UncertaintySpec, load_study

    with pytest.raises(ValueError, match=f"uncertainty outputs: '{output}' holds .*not a quantity"):
        UncertaintySpec(outputs=("e", output))
    path = tmp_path / "mc.toml"
    path.write_text(
        '[study]\nname = "mc"\n[fixed]\nvy = "-1.41 m/s"\nmu = 0.2\n[sample]\nsize = 10\n'
        'angle = { dist = "normal", mean = "20 deg", std = "1 deg" }\n'
        f'[uncertainty]\noutputs = ["e", "{output}"]\n'
    )
    with pytest.raises(ValueError, match=f"'{output}' holds"):
        load_study(path)


def test_the_papers_rod_in_inches_needs_no_mass() -> None:
    Study(name="s", fixed={**KIN, "length": "12 in"}, grid={"mu": [0.1, 0.2]})


def test_a_flat_by_values_with_a_hardness_below_its_yield_is_refused() -> None:
    flat = {"flat_E": "69 GPa", "flat_nu": 0.33, "flat_yield_strength": "276 MPa"}
    with pytest.raises(ValueError, match=r"\[fixed\] flat_\*: brinell_hardness HB = 9.5"):
        Study(name="s", fixed={**KIN, **flat, "flat_brinell_hardness": 9.5, "law": "brake"},
              grid={"mu": [0.1, 0.2]})  # fmt: skip
    Study(name="s", fixed={**KIN, **flat, "flat_brinell_hardness": 95, "law": "brake"},
          grid={"mu": [0.1, 0.2]})  # fmt: skip
