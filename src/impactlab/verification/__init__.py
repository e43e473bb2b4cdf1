"""Verification of impactlab against closed forms, independent solutions and the paper.

Every number on the documentation page ``docs/verification/index.md`` is computed here, and the
test suite (``tests/docs/test_verification.py``) runs the same functions with smaller settings
and asserts the same tolerances, so the published tables come from tested code. Regenerate the
page and its figures with::

    python -m impactlab.verification docs/verification

Each ``verify_*`` function runs one family of cases and returns a :class:`VerificationTable`
(raw numbers in ``records``, a pass/fail against ``tolerance``, and ``to_markdown()``):

* :func:`verify_hertz`: elastic sphere, normal impact, Hertz law: duration, peak force and peak
  penetration against the closed forms (Johnson, *Contact Mechanics* (1985) Sec. 11.4,
  doi:10.1017/CBO9781139171731); e = 1.
* :func:`verify_thornton`: Thornton's elastic-perfectly plastic law, e(V/V_y) against Thornton's
  closed form over V/V_y in [1, 1000] (doi:10.1115/1.2787319).
* :func:`verify_rigid_limits`: the rod with frozen lever arms on an elastic contact against the
  rigid-body impulse solution ``impactlab.bodies.rigid_impulse`` (Stronge, *Impact Mechanics*
  (2000) Ch. 5, doi:10.1017/CBO9780511626432), in slip and in stick.
* :func:`verify_critical_friction`: the engine's slip/stick boundary against
  ``impactlab.analytic.critical_friction`` (mu_c = a b / (k^2 + b^2)).
* :func:`verify_reference`: the compiled engine against the independent ``solve_ivp``
  implementation ``impactlab.dynamics.reference`` at rtol = 1e-11, for every law and the
  friction models ``impulse_ratio``, ``coulomb`` and ``mindlin`` (``partial_slip`` has no
  ``solve_ivp`` reference: the page checks it against its converged Mindlin-Deresiewicz
  solution, Maw-Barber-Fawcett's problem and Kharaz's measurements).
* :func:`verify_paper_durations`: the corrected analytic inversion (``impactlab.analytic.invert``)
  against the paper's 4.30 ms and 1.40 ms (doi:10.1007/s00419-015-1108-2, Tables 2-3).
* :func:`verify_invariants`: every law and friction model on random impacts: the total energy
  never rises, 0 <= e <= 1, 0 <= e* <= 1, 0 <= delta_p <= delta_max.

:func:`main` runs them all and writes the page and the PNG figures into a folder;
:func:`page_markdown` returns the page's text without writing it. Modules:
``table`` (:class:`VerificationTable`, :data:`TOLERANCES`), one module per family (``hertz``,
``thornton``, ``rigid``, ``reference``, ``durations``, ``invariants``), ``plots`` and ``page``.
"""

from __future__ import annotations

from impactlab.verification.durations import verify_paper_durations
from impactlab.verification.hertz import (
    HERTZ_CASES,
    hertz_closed_form,
    hertz_convergence,
    verify_hertz,
)
from impactlab.verification.invariants import verify_invariants
from impactlab.verification.page import anchor, main, page_markdown, render_page, run_all
from impactlab.verification.plots import (
    plot_critical_friction,
    plot_hertz_convergence,
    plot_thornton,
)
from impactlab.verification.reference import reference_cases, verify_reference
from impactlab.verification.rigid import (
    engine_boundary,
    verify_critical_friction,
    verify_rigid_limits,
)
from impactlab.verification.table import TOLERANCES, Column, VerificationTable
from impactlab.verification.thornton import verify_thornton

__all__ = [
    "HERTZ_CASES",
    "TOLERANCES",
    "Column",
    "VerificationTable",
    "anchor",
    "engine_boundary",
    "hertz_closed_form",
    "hertz_convergence",
    "main",
    "page_markdown",
    "plot_critical_friction",
    "plot_hertz_convergence",
    "plot_thornton",
    "reference_cases",
    "render_page",
    "run_all",
    "verify_critical_friction",
    "verify_hertz",
    "verify_invariants",
    "verify_paper_durations",
    "verify_reference",
    "verify_rigid_limits",
    "verify_thornton",
]
