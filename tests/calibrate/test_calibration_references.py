"""The sources of the calibration's methods that its results list (results.json's and the
report's references): the ranking's stacking weights (Yao et al. 2018) and its rule for small
elpd differences (Sivula et al. 2020) were missing."""

from __future__ import annotations

from impactlab.calibrate.api import REFERENCES


def test_the_rankings_sources_are_among_the_references():
    dois = [r.doi for r in REFERENCES]
    for doi in ("10.1007/s11222-016-9696-4", "10.1214/17-BA1091", "10.48550/arXiv.2008.10296"):
        assert doi in dois
    assert any("Using stacking to average Bayesian" in str(r) for r in REFERENCES)
