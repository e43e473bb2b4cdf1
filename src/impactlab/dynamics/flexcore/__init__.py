"""The compiled flexible-rod integrator (a driver beside ``impactlab.dynamics.core``): the
drop of a flexible rod on a flat, from the first touch of its tip through every separation and
re-contact until the rod leaves the flat for good.

It imports only numpy, numba, math, ``impactlab.contact.kernels``, ``impactlab.schema`` and the
shared kernels of ``impactlab.dynamics.kernels`` (the Dormand-Prince tableau, the event search,
the friction, normal-contact and partial-slip cell kernels, layout constants and status codes);
never another driver. The model and the algorithm are documented in ``docs/flexible.md``; the
Python API is ``impactlab.dynamics.drop.simulate_drop``.

Modules: ``layout`` (vector layouts, outputs), ``kinematics`` (end kinematics, forces,
energies), ``rhs`` (right-hand side and event functions), ``stepper`` (Dormand-Prince steps,
dense output, event location), ``flight`` (closed-form free flight and the end-of-sequence
test), ``contacts`` (the event actions: touch, turning point, separation, stick/slip, dents),
``friction`` (the friction models), ``cells`` and ``cellswitch`` (the partial-slip cells per
end), ``history`` (recorded rows), ``setup`` (first touch, scales, work arrays), ``steps``,
``coast`` and ``events`` (the branches of the loop), ``results`` (the output vector), ``model``
(the inputs from Python), ``address_call`` and ``indirect`` (the right-hand side and the step
called through their addresses) and ``driver`` (``drop``: the event loop).

Every compiled function takes the model as one tuple
``mdl = (law, p, c, om, om2, dmp, zeta, Ue, We, Pe, Tg, ia, ib, rhs, step)``:
the contact law id and its parameter vector, the constants vector (``layout.FC_*``), the modal
circular frequencies, their squares, the damping coefficients 2 zeta omega, the damping ratios,
the modal end values U, W, Psi (NE, M), the geometric-stiffness tensor with its indices, and
the addresses of the compiled right-hand side and Dormand-Prince step of the friction model
(``indirect``; ``model.model_tuple`` builds it).
"""

from __future__ import annotations

from impactlab.dynamics.flexcore.driver import drop

__all__ = ["drop"]
