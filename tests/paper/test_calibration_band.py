"""The calibration section's posterior predictive band: the exact quantiles of the mixture of
normals (each draw's prediction with the measurement's sigma), where the draws' predictions are
known; the shipped summary's sampled band, said as such, where they are not; and what the
posterior damping ratio means beside steel's."""

from __future__ import annotations

from statistics import NormalDist
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.stats import norm

from impactlab.paper.calibration_checks import (
    BAND,
    CLIPPED,
    EXACT,
    MONTE_CARLO,
    _ends,
    band_note,
    band_text,
    checks_table,
    interval_text,
    mixture_band,
    ppc_rows,
    reformat_interval,
)
from impactlab.paper.calibration_report import (
    PAPER_SIGMAS,
    calibration_section,
    shipped_calibration,
)
from impactlab.paper.report import Table, to_markdown

Z95 = NormalDist().inv_cdf(0.95)  # 1.6449


def test_one_prediction_is_a_normal_band():
    lo, hi = mixture_band([22.04, 22.04, 22.04], 140.0)
    assert lo == pytest.approx(22.04 - Z95 * 140.0, rel=1e-12)
    assert hi == pytest.approx(22.04 + Z95 * 140.0, rel=1e-12)


@settings(deadline=None, max_examples=40)
@given(
    means=st.lists(st.floats(-5.0, 5.0), min_size=1, max_size=12),
    sigma=st.floats(0.05, 3.0),
)
def test_the_band_holds_90_percent_of_the_mixture(means, sigma):
    lo, hi = mixture_band(means, sigma)
    mixture_cdf = np.mean([norm.cdf([lo, hi], m, sigma) for m in means], axis=0)
    assert mixture_cdf == pytest.approx([0.05, 0.95], abs=1e-9)
    assert min(means) - Z95 * sigma <= lo + 1e-9 and hi <= max(means) + Z95 * sigma + 1e-9


@pytest.mark.parametrize(("means", "sigma"), [([], 1.0), ([1.0], 0.0), ([np.nan], 1.0)])
def test_a_band_needs_predictions_and_a_sigma(means, sigma):
    with pytest.raises(ValueError, match="a band needs finite predictions and sigma > 0"):
        mixture_band(means, sigma)


def _row(config: str, quantity: str, measured: float, best: float, band: str) -> dict:
    return {
        "configuration": config,
        "drop": "20 deg",
        "quantity": quantity,
        "measured": measured,
        "best fit": best,
        "predicted median": best,
        BAND: band,
        "z (best fit)": 0.0,
    }


def test_draws_and_sigma_of_a_row_are_used():
    row = _row("flexible rod", "e", 0.5, 0.45, "[0.1, 0.2]") | {
        "sigma": 0.02,
        "draws": [0.44, 0.46],
    }
    out = checks_table([row], set(), PAPER_SIGMAS).iloc[0]
    lo, hi = mixture_band([0.44, 0.46], 0.02)
    assert out[BAND] == f"[{lo:.3g}, {hi:.3g}]" and out["band"] == EXACT
    assert out["sigma"] == 0.02


def test_without_draws_the_sampled_band_is_kept_and_said():
    row = _row("flexible rod", "scar_length [um]", 1400.0, 253.5, "[64.6, 344]")
    out = checks_table([row], {"rigid rod"}, PAPER_SIGMAS).iloc[0]
    assert out[BAND] == "[64.6, 344]" and out["band"] == MONTE_CARLO
    assert out["sigma"] == pytest.approx(140.0)  # 10 % of the measured value


def test_rows_of_a_calibration_carry_the_sigma():
    post = SimpleNamespace(
        ppc=[
            {
                "drop": "20 deg",
                "quantity": "delta_p",
                "unit": "m",
                "observed": 22e-6,
                "sigma": 2.2e-6,
                "best": 62e-6,
                "median": 62e-6,
                "pred_q05": 58e-6,
                "pred_q95": 66e-6,
                "z_best": 18.2,
            }
        ]
    )
    (row,) = ppc_rows({"rigid rod": post})
    assert row["quantity"] == "delta_p [um]"
    assert row["sigma"] == pytest.approx(2.2) and row["measured"] == pytest.approx(22.0)
    assert row[BAND] == "[58, 66]"


@pytest.fixture(scope="module")
def section():
    blocks = calibration_section(shipped_calibration(), 12)
    checks = next(b.df for b in blocks if isinstance(b, Table) and "predictive" in b.caption)
    return blocks, checks


def test_the_rigid_rods_band_is_exact(section):
    """The rigid rod has no free parameter: its band is best fit +- 1.645 sigma (the sampled
    one of the 30 draws was [-166, 113] um for the 20 deg scar, [0.385, 0.469] for e), a
    length's clipped at 0 (the 20 and 45 deg scars: [-208, 252] and [-170, 372] um)."""
    _, checks = section
    rigid = checks[checks["configuration"] == "rigid rod"].set_index(["drop", "quantity"])
    assert rigid["band"].str.startswith(EXACT).all()
    assert rigid.loc[("20 deg", "scar_length [um]"), BAND] == "[0, 252]"
    assert rigid.loc[("45 deg", "scar_length [um]"), BAND] == "[0, 372]"
    assert rigid.loc[("20 deg", "e"), BAND] == "[0.373, 0.472]"
    for _, r in rigid.iterrows():
        lo, hi = (float(x) for x in r[BAND].strip("[]").split(", "))
        low = r["best fit"] - Z95 * r["sigma"]
        assert (r["band"] == f"{EXACT}, {CLIPPED}") is (low < 0)
        assert lo == pytest.approx(max(low, 0.0), rel=2e-3, abs=0.5)
        assert hi == pytest.approx(r["best fit"] + Z95 * r["sigma"], rel=2e-3, abs=0.5)


def test_no_band_of_a_length_reaches_below_zero(section):
    """A scar length or a dent depth is >= 0: every band shown starts at 0 or above, the
    clipped ones are marked and the note says why (the Gaussian measurement model's choice)."""
    blocks, checks = section
    lengths = checks[checks["quantity"].str.endswith("[um]")]
    lows = [float(b.strip("[]").split(", ")[0]) for b in lengths[BAND]]
    assert min(lows) >= 0.0
    clipped = checks[checks["band"].str.endswith(CLIPPED)]
    assert list(clipped["configuration"]) == ["rigid rod", "rigid rod"]
    text = " ".join(to_markdown(blocks, "t").split())
    assert "the Gaussian measurement model, the likelihood's choice" in text
    assert "(rigid rod 20 deg scar_length [um], rigid rod 45 deg scar_length [um])" in text
    assert "the band shown is that of the length a scan would read, max(0, x)" in text


def test_a_clipped_band_is_said_only_where_there_is_one():
    assert band_text(-208.3, 252.4, "scar_length [um]") == ("[0, 252]", True)
    assert band_text(-0.02, 0.1, "e") == ("[-0.02, 0.1]", False)  # e is no length
    assert band_text(1.0, 2.0, "delta_p") == ("[1, 2]", False)
    sampled = _row("flexible rod", "delta_p [um]", 22.0, 5.0, "[-3.2, 9.1]")
    out = checks_table([sampled], set(), PAPER_SIGMAS)
    assert out.iloc[0][BAND] == "[0, 9.1]" and out.iloc[0]["band"] == f"{MONTE_CARLO}, {CLIPPED}"
    assert "flexible rod 20 deg delta_p [um]" in band_note(out, 30)
    kept = checks_table([_row("flexible rod", "e", 0.5, 0.45, "[0.4, 0.5]")], set(), PAPER_SIGMAS)
    assert "cannot be negative" not in band_note(kept, 30)


def test_the_flexible_bands_are_the_shipped_ones_and_said_so(section):
    blocks, checks = section
    shipped = {
        (r["configuration"], r["drop"], r["quantity"]): r[BAND]
        for r in shipped_calibration()["checks"]
    }
    flexible = checks[checks["configuration"] != "rigid rod"]
    assert (flexible["band"] == MONTE_CARLO).all()
    for _, r in flexible.iterrows():
        stored = shipped[(r["configuration"], r["drop"], r["quantity"])]
        lo, hi = (float(x) for x in stored.strip("[]").split(","))
        # the shipped ends, written in the report's number format (the summary stores .3g)
        assert r[BAND] == interval_text(lo, hi)
    text = to_markdown(blocks, "t")
    assert "e+0" not in text and "[691, 1080]" in text  # 1080 um, not 1.08e+03
    assert "the mixture over the 30 posterior draws of a normal" in text
    assert "best fit +- 1.645 sigma" in text
    assert "not the draws' predictions" in text


def test_the_damping_ratio_is_set_beside_steels(section):
    blocks, _ = section
    zetas = [r["zeta median"] for r in shipped_calibration()["ranking"] if r["zeta median"]]
    text = to_markdown(blocks, "t")
    lo, hi = min(zetas), max(zetas)
    said = f"The zeta medians, {lo:.2g} to {hi:.2g}, are {lo / 1e-3:.0f} to {hi / 1e-3:.0f} times"
    assert said in text
    assert "steel's material damping (1e-4 to 1e-3; docs/flexible.md)" in text
    assert "it is not a property of the rod" in text


@settings(deadline=None)
@given(
    st.floats(min_value=-1e9, max_value=1e9, allow_nan=False).filter(lambda x: abs(x) > 1e-9),
    st.floats(min_value=-1e9, max_value=1e9, allow_nan=False).filter(lambda x: abs(x) > 1e-9),
)
def test_an_interval_is_in_the_reports_number_format(lo, hi):
    """No Python exponent (``1.08e+03``) in a band or the zeta interval; the text reads back to
    its ends within the 3 digits shown."""
    text = interval_text(lo, hi)
    assert "e+" not in text and "e-" not in text
    back = _ends(text)
    assert back == pytest.approx((lo, hi), rel=5e-3)


def test_the_zeta_interval_and_a_stored_exponent_band():
    assert interval_text(691.0, 1083.0) == "[691, 1080]"
    assert interval_text(1.234e-4, 5.0e-3) == "[1.23\u00d710\u207b\u2074, 0.005]"
    assert _ends("[691, 1.08e+03]") == (691.0, 1080.0)  # as older summaries stored it
    assert reformat_interval("[1.2e-05, 0.3]") == "[1.2\u00d710\u207b\u2075, 0.3]"
    assert reformat_interval("-") == "-" and reformat_interval(None) is None


def test_a_nan_band_reads_back_as_nan() -> None:
    """A check whose every draw failed has a NaN band, written ``[-, -]``: it reads back as NaN
    (the report's table is built, its band shown as written), as Python's ``[nan, nan]`` of
    older summaries does."""
    text = interval_text(np.nan, np.nan)
    assert text == "[-, -]"
    assert all(np.isnan(x) for x in (*_ends(text), *_ends("[nan, nan]")))
    assert reformat_interval(text) == text
    row = _row("flexible rod", "e", 0.5, np.nan, text) | {"sigma": 0.02}
    out = checks_table([row], set(), PAPER_SIGMAS).iloc[0]
    assert out[BAND] == "[-, -]" and out["band"] == MONTE_CARLO
    row = _row("flexible rod", "scar_length [um]", 1400.0, np.nan, "[nan, nan]")
    assert checks_table([row], set(), PAPER_SIGMAS).iloc[0][BAND] == "[-, -]"
