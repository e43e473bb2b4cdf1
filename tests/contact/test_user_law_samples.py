"""A user's law given as Python callables (``register_law(loading=..., unloading=...)``): a
delta_max at or past the radius and samples a law cannot have are told in the callables' words
(``delta_max``, ``radius``, ``loading(delta)``, ``unloading(delta_max)``, the interference in
m), never in the tables' (a row, an index)."""

from __future__ import annotations

import math

import pytest

from impactlab.contact import law_names, register_law
from impactlab.contact._common import jg_critical
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = 8.8e-3
DC, _FC = jg_critical(PAIR.E_star, R, PAIR.yield_strength, PAIR.nu)
SW = 1e-6  # where the callables below leave Hertz [m]


def hertz(delta: float) -> float:
    """Hertz's force [N] at ``delta`` [m] for PAIR and R."""
    return 4.0 / 3.0 * PAIR.E_star * math.sqrt(R) * delta**1.5


def softening(delta: float) -> float:
    return hertz(delta) / math.sqrt(1.0 + delta / 100e-6)


def residual(delta_max: float) -> float:
    return 0.8 * delta_max * max(1.0 - SW / delta_max, 0.0) ** 2


def _refused(**kw: object) -> str:
    base: dict[str, object] = {"loading": softening, "unloading": residual, "pair": PAIR}
    base |= {"radius": R, "delta_max": 300e-6, "switch_interference": SW}
    with pytest.raises(ValueError, match=r"delta_max|loading|unloading") as err:
        register_law("samples-bad", **(base | kw))  # type: ignore[arg-type]
    assert "samples-bad" not in law_names()
    text = str(err.value)
    assert "\n" not in text and "index" not in text and "row" not in text
    return text


def test_a_bare_delta_max_past_the_radius_is_told_its_unit_before_sampling() -> None:
    calls: list[float] = []

    def loading(delta: float) -> float:
        calls.append(delta)
        return softening(delta)

    text = _refused(loading=loading, delta_max=300)
    assert text == (
        "delta_max = 300 m must be smaller than radius = 0.0088 m (a bare number is m: '300 um'?)"
    )
    assert calls == []  # refused before the callables ran


def test_a_delta_max_with_units_past_the_radius_is_named_as_given() -> None:
    text = _refused(delta_max="300 mm", radius="8.8 mm")
    assert text == "delta_max = '300 mm' (0.3 m) must be smaller than radius = 0.0088 m"


def test_a_force_of_zero_is_told_at_its_interference() -> None:
    text = _refused(loading=lambda d: 0.0 * d)
    assert text == (
        "law 'samples-bad': F = loading(delta) must be > 0 N from switch_interference to "
        "delta_max, got 0 N at delta = 1e-06 m"
    )
    text = _refused(loading=lambda d: 0.0 * d, switch_interference=None)
    assert f"from the pair's delta_c to delta_max, got 0 N at delta = {DC:.4g} m" in text


def test_a_falling_force_and_a_bad_residual_depth_are_told_in_the_callables_words() -> None:
    text = _refused(loading=lambda d: softening(d) * (0.5 if d > 1e-4 else 1.0))
    assert text.startswith(
        "law 'samples-bad': F = loading(delta) must not decrease with delta, got "
    )
    assert " N at delta = " in text and text.endswith(" m")
    text = _refused(unloading=lambda d: 0.5 * d)
    assert (
        "delta_r = unloading(delta_max) must be 0 at the elastic limit (switch_interference, "
        in text
    )
    text = _refused(unloading=lambda d: 1.2 * d if d > SW else 0.0)
    assert "delta_r = unloading(delta_max) must lie in [0, delta_max), got " in text
    assert " m at delta_max = " in text
