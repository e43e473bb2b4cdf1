"""Errors of a measurements file that say what to do and where: an uncertainty of a drop input
(``mu_sigma``: before, "unknown column 'mu_sigma' (did you mean 'e_sigma'?)"), duplicate labels
with the file and its lines, a TOML drop's range error with the file, and a value outside its
range in the unit the file gave it (before, ``delta_p [um]`` -60 read "-6e-05 m")."""

from __future__ import annotations

import re

import pytest

from impactlab.calibrate import Measurements, read_measurements

ROW = {"label": "a", "angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.4, "e_sigma": 0.02}


def test_mu_sigma_says_mu_is_exact_and_how_to_calibrate_an_uncertain_one():
    with pytest.raises(ValueError, match="mu_sigma") as info:
        Measurements.from_records([{**ROW, "mu_sigma": 0.01}])
    text = str(info.value)
    assert text.startswith("drop 1: column 'mu_sigma': mu is an input of the drop, taken as exact")
    assert "free parameter with a normal prior" in text and '-p "mu=normal(mean, sd)"' in text
    assert "unknown column" not in text and "e_sigma" not in text


@pytest.mark.parametrize("name", ["angle_sigma", "vy_sigma", "spin_sigma"])
def test_a_kinematic_inputs_sigma_says_it_is_exact(name):
    with pytest.raises(ValueError, match=rf"column '{name}': {name.removesuffix('_sigma')} is an "
                       r"input of the drop, taken as exact; only a measured quantity takes an "
                       r"uncertainty \(<quantity>_sigma\): remove the column$"):  # fmt: skip
        Measurements.from_records([{**ROW, name: 1}])


def test_a_material_inputs_sigma_points_to_a_free_parameter(tmp_path):
    with pytest.raises(ValueError, match=r"flat_yield_strength is an input of the drop, taken "
                       r"as exact.*-p \"flat_yield_strength=normal\(mean, sd\)\""):  # fmt: skip
        Measurements.from_records([{**ROW, "flat_yield_strength_sigma [MPa]": 5}])
    path = tmp_path / "m.toml"
    path.write_text('[units]\nmu_sigma = "1"\n[[drop]]\nlabel = "a"\nangle = "20 deg"\n'
                    "vy = -1.41\ne = 0.4\ne_sigma = 0.02\n")  # fmt: skip
    with pytest.raises(ValueError, match=r"m.toml: \[units\]: column 'mu_sigma': mu is an input"):
        read_measurements(path)


def test_duplicate_labels_name_the_file_and_its_lines(tmp_path):
    path = tmp_path / "m.csv"
    path.write_text("label,angle [deg],vy,mu,e,e_sigma\na,20,-1.41,0.2,0.4,0.02\n"
                    "b,20,-1.41,0.2,0.4,0.02\n\na,30,-1.41,0.2,0.4,0.02\n")  # fmt: skip
    with pytest.raises(ValueError, match="duplicate drop labels") as info:
        read_measurements(path)
    assert str(info.value) == (
        f"{path}: duplicate drop labels: 'a' on lines 2 and 5 (drops 1 and 3): give each drop "
        "its own label (a drop without one is named 'drop N', N its place in the file)"
    )
    toml = tmp_path / "m.toml"
    drop = '[[drop]]\nlabel = "a"\nangle = "20 deg"\nvy = -1.41\nmu = 0.2\ne = 0.4\n'
    drop += "e_sigma = 0.02\n"
    toml.write_text(drop * 2)
    with pytest.raises(ValueError, match=re.escape(f"{toml}: duplicate drop labels: 'a' (drops "
                                                   "1 and 2)")):  # fmt: skip
        read_measurements(toml)
    with pytest.raises(ValueError, match=r"^duplicate drop labels: 'a' \(drops 1 and 2\)"):
        Measurements.from_records([ROW, ROW])


def test_a_toml_drops_range_error_names_the_file(tmp_path):
    path = tmp_path / "m.toml"
    path.write_text('[[drop]]\nlabel = "a"\nangle = "20 deg"\nvy = -1.41\nmu = 0.2\n'
                    "e = 1.5\ne_sigma = 0.02\n")  # fmt: skip
    with pytest.raises(ValueError, match=re.escape(f"{path}: drop 1 (a): e = 1.5 lies outside")):
        read_measurements(path)


@pytest.mark.parametrize(
    ("columns", "shown"),
    [
        ({"delta_p [um]": -60, "delta_p_sigma": 3},
         r"delta_p = -60 um lies outside the possible range \[0, inf\] um by more than 3 sigma "
         r"\(delta_p_sigma = 3 um;"),
        ({"delta_p": "-0.06 mm", "delta_p_sigma": "3 um"},
         r"delta_p = -0.06 mm lies outside the possible range \[0, inf\] mm by more than 3 sigma "
         r"\(delta_p_sigma = 0.003 mm;"),
        ({"e [%]": 130, "e_sigma": 2},
         r"e = 130 % lies outside the possible range \[0, 101.3\d*\] % by more than 3 sigma "
         r"\(e_sigma = 2 %;"),
        ({"delta_p": -6e-5, "delta_p_sigma": 3e-6},  # bare SI numbers: SI
         r"delta_p = -6e-05 m lies outside the possible range \[0, inf\] m"),
    ],
)  # fmt: skip
def test_a_value_outside_its_range_is_shown_in_the_files_unit(columns, shown):
    row = {k: v for k, v in ROW.items() if not k.startswith("e")}
    with pytest.raises(ValueError, match=shown):
        Measurements.from_records([{**row, **columns}])


def test_a_csv_value_outside_its_range_names_the_line_and_the_files_unit(tmp_path):
    path = tmp_path / "m.csv"
    path.write_text("label,angle [deg],vy [m/s],delta_p [um],delta_p_sigma\n"
                    "a,20,-1.41,100,3\nb,45,-1.41,-60,3\n")  # fmt: skip
    with pytest.raises(ValueError, match=re.escape(f"{path}: line 3: drop 2 (b): delta_p = -60 "
                                                   "um lies outside")):  # fmt: skip
        read_measurements(path)
