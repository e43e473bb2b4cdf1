"""The contexts that hide or record ArviZ's warnings hold one lock: two of them in two threads
(models calibrated on a threaded Dask worker) run one after the other, so neither restores the
process-wide warning filters while the other still computes."""

from __future__ import annotations

import threading
import warnings

from impactlab.calibrate._arviz import quiet, recording


def test_a_second_context_waits_for_the_first():
    order: list[str] = []
    inside = threading.Event()
    release = threading.Event()

    def first() -> None:
        with recording():
            inside.set()
            assert release.wait(60)
            order.append("first")

    def second() -> None:
        with quiet():
            order.append("second")

    a = threading.Thread(target=first)
    a.start()
    assert inside.wait(60)
    b = threading.Thread(target=second)
    b.start()
    b.join(0.2)  # a chance to run: it must wait for the first context, however long
    assert order == []
    release.set()
    a.join(60)
    b.join(60)
    assert order == ["first", "second"]


def test_recording_keeps_what_is_raised_inside_and_nothing_leaks():
    with warnings.catch_warnings(record=True) as outside:
        warnings.simplefilter("always")
        with recording() as caught:
            warnings.warn("advisory", UserWarning, stacklevel=1)
        with quiet():
            warnings.warn("hidden", UserWarning, stacklevel=1)
    assert [str(w.message) for w in caught] == ["advisory"]
    assert outside == []


def test_sampling_leaves_the_process_wide_warning_filters_alone(template):
    """The chain hides the floating-point warnings of refused proposals with numpy's per-thread
    error state: a process-wide ``catch_warnings`` around it would restore the filters under a
    context of another thread (a second chain on a threaded Dask worker)."""
    import numpy as np

    from impactlab.calibrate import CandidateModel, calibrate, parse_parameter
    from impactlab.calibrate.synthetic import synthetic_measurements

    mu = parse_parameter("mu", "uniform(0, 0.6)")
    data = synthetic_measurements(template, CandidateModel(), [mu], [0.15],
                                  np.random.default_rng(3))  # fmt: skip
    filters = warnings.filters
    seen: list[bool] = []
    calibrate(data, [mu], ["ghaednia/coulomb"], walkers=8, steps=10, n_ppc=0,
              progress=lambda *_: seen.append(warnings.filters is filters))  # fmt: skip
    assert seen and all(seen)
