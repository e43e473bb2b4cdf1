"""The posterior predictive check of the calibration section: each measured value beside each
configuration's prediction, with the 90 % band a new measurement would fall in.

The band is the 5 % and 95 % quantiles of the predictive distribution: the mixture, over the
posterior draws, of a normal around each draw's prediction with the measurement's standard
uncertainty sigma. It is computed exactly (no noise sampled) from the draws' predictions: a row
that carries them (``draws``), or a configuration without a free parameter (the rigid rod), whose
every draw predicts its best fit, so that its band is best fit +- 1.645 sigma. A row without
them (the shipped summary keeps only quantiles) keeps the band the calibration sampled, one
noise value per draw (Monte Carlo), and says so. A length (the dent depth, the scar) cannot be
negative, but the Gaussian measurement model gives it some probability below zero: the band
shown is that of the length a scan would read, max(0, x), so a negative end is clipped at 0
and the row says so (the summary keeps the quantiles as computed).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from statistics import NormalDist
from typing import Any

import numpy as np
import pandas as pd
from scipy.optimize import brentq

from impactlab.paper.report import fmt_number

__all__ = [
    "BAND",
    "CLIPPED",
    "EXACT",
    "LENGTHS",
    "MONTE_CARLO",
    "band_note",
    "band_text",
    "checks_table",
    "interval_text",
    "mixture_band",
    "ppc_rows",
    "reformat_interval",
]

#: The band's column, and how each row's band was obtained (column ``band``).
BAND = "90 % band (with noise)"
EXACT = "exact"
MONTE_CARLO = "sampled (Monte Carlo)"
#: How a band clipped at 0 is marked in column ``band``, after how it was obtained.
CLIPPED = "clipped at 0"
#: The quantities that cannot be negative (lengths): their band is that of max(0, x).
LENGTHS = ("delta_p", "scar_length")

#: The central interval [probability].
_LEVELS = (0.05, 0.95)


def mixture_band(means: Sequence[float], sigma: float) -> tuple[float, float]:
    """The 5 % and 95 % quantiles of the equal-weight mixture of normals N(``means[i]``,
    ``sigma``), exactly (root of the mixture's distribution function)."""
    mu = np.asarray(means, dtype=float)
    if mu.size == 0 or not np.isfinite(mu).all() or not sigma > 0:
        raise ValueError(f"a band needs finite predictions and sigma > 0, got sigma = {sigma!r}")
    unit = NormalDist()
    if np.ptp(mu) == 0.0:
        lo, hi = (float(mu[0] + sigma * unit.inv_cdf(p)) for p in _LEVELS)
        return lo, hi

    def cdf(x: float, p: float) -> float:
        return float(np.mean([unit.cdf((x - m) / sigma) for m in mu])) - p

    a, b = float(mu.min()) - 10 * sigma, float(mu.max()) + 10 * sigma
    lo, hi = (float(brentq(cdf, a, b, args=(p,), xtol=1e-12 * sigma)) for p in _LEVELS)
    return lo, hi


#: Significant digits of a band's ends (the quantiles of a sampled distribution).
BAND_DIGITS = 3

_FROM_SUPERSCRIPT = str.maketrans(
    "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079", "-0123456789"
)


def interval_text(lo: float, hi: float) -> str:
    """``[691, 1080]``: the two ends with :data:`BAND_DIGITS` significant digits, in the report's
    number format (``impactlab.paper.report.fmt_number``: positional from 0.001 to below 1e6,
    else a mantissa, U+00D7 and a superscript power of ten; never ``1.08e+03``)."""
    return f"[{fmt_number(lo, BAND_DIGITS)}, {fmt_number(hi, BAND_DIGITS)}]"


def band_text(lo: float, hi: float, quantity: str) -> tuple[str, bool]:
    """The band ``[lo, hi]`` of ``quantity`` (its name, with or without the unit) as shown
    (:func:`interval_text`), and whether it was clipped: a length's (:data:`LENGTHS`) is that
    of max(0, x), its negative ends raised to 0."""
    clip = str(quantity).split(" [")[0] in LENGTHS and lo < 0.0
    if clip:
        lo, hi = 0.0, max(hi, 0.0)
    return interval_text(lo, hi), clip


def _number(text: str) -> float:
    """A number as a band writes it: Python's (``1.08e+03``, ``nan``, as older summaries stored
    it) or the report's (``1.23``, U+00D7, ``10`` and a superscript power; ``-`` for NaN, a band
    whose every draw failed)."""
    text = text.strip()
    if text == "-":
        return math.nan
    if "\u00d710" in text:
        mantissa, power = text.split("\u00d710")
        return float(f"{mantissa}e{power.translate(_FROM_SUPERSCRIPT)}")
    return float(text)


def _ends(band: str) -> tuple[float, float]:
    """The two ends of a band written ``[lo, hi]``."""
    lo, hi = (_number(x) for x in band.strip("[]").split(","))
    return lo, hi


def reformat_interval(text: Any) -> Any:
    """A stored interval ``[lo, hi]`` written again by :func:`interval_text` (a summary may
    hold Python's ``1.08e+03``); anything else (``-``, None) unchanged."""
    if isinstance(text, str) and text.startswith("[") and text.endswith("]"):
        return interval_text(*_ends(text))
    return text


def ppc_rows(posteriors: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The check's rows of a finished calibration (``Calibration.posteriors``), display units
    (um for lengths), with each measurement's ``sigma``."""
    rows = []
    for name, post in posteriors.items():
        for r in post.ppc:
            scale = 1e6 if r["unit"] == "m" else 1.0
            rows.append(
                {
                    "configuration": name,
                    "drop": r["drop"],
                    "quantity": r["quantity"] + (" [um]" if scale != 1.0 else ""),
                    "measured": r["observed"] * scale,
                    "sigma": r["sigma"] * scale,
                    "best fit": r["best"] * scale,
                    "predicted median": r["median"] * scale,
                    BAND: interval_text(r["pred_q05"] * scale, r["pred_q95"] * scale),
                    "z (best fit)": r["z_best"],
                }
            )
    return rows


def checks_table(
    rows: Sequence[Mapping[str, Any]],
    fixed: set[str],
    sigmas: Mapping[str, float],
) -> pd.DataFrame:
    """The check's table: ``rows`` (``ppc_rows``, or those of a stored summary) with the band
    recomputed exactly where the draws' predictions are known, and its column ``band`` saying
    how it was obtained. ``fixed``: the configurations without a free parameter (their every
    draw predicts the best fit); ``sigmas``: per quantity (its name before the unit) the
    measurement's sigma where a row does not carry its own (absolute for ``e``, relative to the
    measured value otherwise)."""
    out = []
    for r in rows:
        sigma, draws = r.get("sigma"), r.get("draws")
        if sigma is None:
            q = str(r["quantity"]).split(" [")[0]
            sigma = sigmas[q] if q == "e" else sigmas[q] * abs(float(r["measured"]))
        if draws is None and r["configuration"] in fixed:
            draws = [r["best fit"]]
        how = EXACT if draws is not None else MONTE_CARLO
        lo, hi = mixture_band(draws, float(sigma)) if draws is not None else _ends(r[BAND])
        # a stored band is written again in the report's number format (older summaries
        # stored Python's 1.08e+03)
        band, clipped = band_text(lo, hi, r["quantity"])
        shown = {k: r[k] for k in ("configuration", "drop", "quantity", "measured")}
        out.append(
            shown
            | {"sigma": sigma, "best fit": r["best fit"], "predicted median": r["predicted median"]}
            | {BAND: band, "band": f"{how}, {CLIPPED}" if clipped else how}
            | {"z (best fit)": r["z (best fit)"]}
        )
    return pd.DataFrame(out)


def band_note(checks: pd.DataFrame, n_draws: int | None) -> str:
    """How the predictive band of each row was obtained."""
    draws = f"the {n_draws} posterior draws" if n_draws else "the posterior draws"
    how = checks["band"].astype(str)
    sampled = sorted(set(checks.loc[how.str.startswith(MONTE_CARLO), "configuration"]))
    exact = sorted(set(checks.loc[how.str.startswith(EXACT), "configuration"]))
    clipped = checks[how.str.endswith(CLIPPED)]
    text = (
        "90 % band (with noise): the 5 % and 95 % quantiles of the predictive distribution, "
        f"the mixture over {draws} of a normal around each draw's prediction with the "
        "measurement's sigma (column 'sigma'), where a new measurement would fall. "
    )
    if exact:
        text += (
            f"Exact for {' and '.join(exact)} (column 'band'): the quantiles of that mixture; a "
            "configuration without a free parameter predicts its best fit with every draw, so "
            "its band is best fit +- 1.645 sigma. "
        )
    if sampled:
        text += (
            f"For {', '.join(sampled)}, the summary keeps only the band the calibration "
            f"sampled, one noise value for each of {draws} (Monte Carlo), not the draws' "
            "predictions: those bands carry that sampling error. "
        )
    if not clipped.empty:
        which = ", ".join(f"{r.configuration} {r.drop} {r.quantity}" for r in clipped.itertuples())
        text += (
            "A length cannot be negative, but the Gaussian measurement model, the likelihood's "
            "choice, gives it some probability below zero: where a band's end fell below 0 "
            f"({which}), the band shown is that of the length a scan would read, max(0, x), "
            f"its end raised to 0 (column 'band': '{CLIPPED}'); the likelihood is unchanged."
        )
    return text.rstrip()
