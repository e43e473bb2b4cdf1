"""``calibrate``'s arguments are checked by name before a step is sampled: a wrong
``n_ppc`` failed with numpy's message after the whole chain had run."""

from __future__ import annotations

from pathlib import Path

import pytest

from impactlab.calibrate import calibrate

DROPS = Path(__file__).resolve().parents[2] / "examples" / "data" / "paper_drops.csv"
PRIORS = {"mu": "uniform(0, 1)"}


@pytest.mark.parametrize("n_ppc", [-1, 2.5, "200", True])
def test_a_bad_n_ppc_is_refused_first(n_ppc: object) -> None:
    with pytest.raises(ValueError, match=r"^n_ppc must be an integer"):
        calibrate(DROPS, PRIORS, n_ppc=n_ppc)  # type: ignore[arg-type]


def test_measurements_that_are_no_file_or_table_are_refused() -> None:
    with pytest.raises(ValueError, match=r"^measurements must be a Measurements .* got None$"):
        calibrate(None, PRIORS)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("parameters", "message"),
    [
        (None, r"^parameters must be a mapping of names to priors, .* got None$"),
        ("mu", r"^parameters must be a mapping of names to priors, .* got 'mu'$"),
        (["mu"], r"^parameters\[0\] is 'mu', not a Parameter: give Parameters, or a mapping"),
    ],
)
def test_parameters_of_another_type_are_refused_by_name(parameters: object, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        calibrate(DROPS, parameters)  # type: ignore[arg-type]
