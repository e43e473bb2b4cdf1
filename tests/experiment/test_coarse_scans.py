"""Scans too coarse for their dent: pixels whose 1-pixel smoothing reaches the dent's edge at
every level the extrapolation to the zero threshold could use, and heights in steps coarser
than their noise.

On 64 um pixels a groove 22 um deep and 1250 um wide measured L_s = 1320.4 +- 9.3 um for 1400
(-8.6 sigma), on 80 um pixels -11.5 sigma: the width's levels clear of the smoothing lay too
deep, and the length and the width were then both taken at the threshold, assuming their
smoothing biases cancel in L_s (they were -6 um and +75 um). Heights rounded to 1 um gave a
noise of 1e-15 m, delta_p = 22.000 +- 2.5e-10 um for 22.4 and L_s 12 sigma off; with 0.2 um
steps a cryptic error or a spurious second depression 5.6e-05 um deep."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import HeightMap, ScanError, measure_dent
from impactlab.experiment.profilometry import dent as dent_module
from impactlab.experiment.profilometry.levelling import height_step


def _scan(pixel: float, depth: float = 22e-6, slide: float = 1400e-6, seed: int = 1) -> HeightMap:
    z, dx, dy, _ = S.synthetic_scan(
        delta_p=depth, sliding_length=slide, seed=seed, pixel=pixel, margin=1.2e-3
    )
    return HeightMap(z, dx, dy)


def _coarse(warnings: tuple[str, ...]) -> list[str]:
    return [w for w in warnings if "within the reach of the outline's smoothing" in w]


@pytest.mark.parametrize("pixel_um", [24, 48, 56, 64, 80, 100])
def test_the_sliding_length_is_within_its_sigmas_or_the_pixels_are_named(pixel_um: int) -> None:
    d = measure_dent(_scan(pixel_um * 1e-6))
    ls = d.sliding_length
    assert abs(ls.value - 1400e-6) < 2.5 * ls.sigma, ls
    notes = _coarse(d.warnings)
    if pixel_um >= 64:  # the width's levels clear of the smoothing lie too deep
        assert notes and f"1 pixel of {pixel_um} x {pixel_um} um" in notes[0], d.warnings
        assert "too coarse for this dent" in notes[0] and "pixels of about" in notes[0]
    if pixel_um <= 48:
        assert not notes, d.warnings


def test_the_pixel_size_named_measures_the_dent() -> None:
    """The pixel size the warning names clears the smoothing (no warning, L_s close)."""
    note = _coarse(measure_dent(_scan(64e-6)).warnings)[0]
    named = float(note.split("pixels of about ")[1].split(" um")[0])
    assert 40 <= named < 64, note
    d = measure_dent(_scan(named * 1e-6))
    assert not _coarse(d.warnings), d.warnings
    assert abs(d.sliding_length.value - 1400e-6) < 2.0 * d.sliding_length.sigma


def test_levels_kept_at_the_threshold_by_a_gap_carry_the_smoothing_in_their_sigma() -> None:
    """A dent 105 um deep on 90 um pixels: the dropouts on its flank keep the levels at the
    threshold, where the length came out +130 um and the width +168 (L_s 161.7 +- 3.5 um for
    200, -11 sigma)."""
    d = measure_dent(_scan(90e-6, depth=105e-6, slide=200e-6))
    ls = d.sliding_length
    assert abs(ls.value - 200e-6) < 2.5 * ls.sigma, ls
    assert any("a gap without data" in w for w in _coarse(d.warnings)), d.warnings


def _stepped(step: float, depth: float = 22.4e-6, offset: float = 0.0) -> HeightMap:
    z, dx, dy, _ = S.synthetic_scan(
        delta_p=depth,
        sliding_length=1400e-6,
        seed=1,
        noise=5e-8 if step >= 0.5e-6 else 2e-8,
        tilt=(0.0, 0.0),
        dropouts=0.0,
        offset=offset,
    )
    return HeightMap(np.round(z / step) * step, dx, dy)


@pytest.mark.parametrize("step", [0.5e-6, 1e-6])
def test_heights_in_steps_floor_the_noise_at_their_rounding(step: float) -> None:
    d = measure_dent(_stepped(step))
    assert d.noise == pytest.approx(step / np.sqrt(12.0))
    assert d.delta_p.sigma >= step / np.sqrt(12.0)
    assert abs(d.delta_p.value - 22.4e-6) < 2.0 * d.delta_p.sigma, d.delta_p
    assert abs(d.sliding_length.value - 1400e-6) < 3.0 * d.sliding_length.sigma
    notes = [w for w in d.warnings if "the heights come in steps of" in w]
    assert notes and f"steps of {step * 1e6:.3g} um" in notes[0], d.warnings


@pytest.mark.parametrize("offset", [0.03e-6, 0.13e-6])
def test_fine_steps_measure_one_dent(offset: float) -> None:
    """0.2 um steps: with the scan 0.13 um up the outline missed the line across the deepest
    point (an error naming no cause); 0.03 um up a second 'dent' 5.6e-05 um deep qualified."""
    d = measure_dent(_stepped(0.2e-6, depth=22e-6, offset=offset))
    assert abs(d.delta_p.value - 22e-6) < 3.0 * d.delta_p.sigma
    assert abs(d.sliding_length.value - 1400e-6) < 3.0 * d.sliding_length.sigma
    assert not any("depressions qualify" in w for w in d.warnings), d.warnings


def test_an_outline_that_misses_the_line_names_the_height_step(monkeypatch) -> None:
    monkeypatch.setattr(dent_module, "_extent", lambda *a, **k: None)
    with pytest.raises(ScanError, match="steps of 1 um") as err:
        measure_dent(_stepped(1e-6))
    assert "floating point" in str(err.value)


def test_measured_heights_have_no_step() -> None:
    z, *_ = S.synthetic_scan(seed=2)
    assert height_step(z) == 0.0
    assert height_step(np.round(z / 1e-8) * 1e-8) == pytest.approx(1e-8)
