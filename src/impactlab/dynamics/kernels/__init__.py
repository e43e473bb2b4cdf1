"""The compiled kernels shared by the three engines: the rigid impact (``dynamics.core``), the
partial-slip impact (``dynamics.slipcore``) and the flexible-rod drop (``dynamics.flexcore``).

Everything here runs in numba ``nopython`` mode (``error_model="numpy"``), as pure functions of
their arguments and of module constants. The drivers import the kernels, never one another
(the import contracts ``kernels``, ``core``, ``slipcore`` and ``flexcore`` in
``pyproject.toml``); the kernels import only numpy, numba, math, L0 (``impactlab.schema``,
``impactlab.flags``, ``impactlab._floatbits``), ``impactlab.contact.kernels``,
``impactlab.contact.history_kernels`` and ``impactlab.bodies.layout``.

Modules, lowest first:

- ``_jit``: the compile option of the hot leaf functions (no reference counting).
- ``buffers``: copies between work arrays as loops (no slice assignment of arrays, whose
  error message numba would compile in every process), the growing history buffer.
- ``layout``: indices of the rigid-body state, constants, mode, event, output and history
  vectors; friction ids; limits (the partial-slip and flexible layouts extend it).
- ``status``: the status codes and messages of every engine, friction regime codes.
- ``tuples``: the state and mode as tuples.
- ``dormand_prince``: the Dormand-Prince 5(4) tableau, the stage point and error sum of a state
  array, Shampine's dense output, the work-array views of a step loop.
- ``step_control``: the step-size factors of the error control.
- ``roots``: event location on the dense output: the Illinois update, the round-off probe.
- ``normal``: contact-point kinematics, the normal force and contact radius on the current
  branch of the contact history.
- ``friction``: friction kernels with named scalar arguments (stick force, Coulomb decision,
  stick/slip switch, Mindlin trial rate).
- ``cells``: the Mindlin-Deresiewicz partial-slip cells (limits, stick rates, switches, births).
- ``rhs``: the rigid body's right-hand side, event functions and total energy.
- ``quality``: the result flags at separation (energy gain, gravity dominance).
- ``setup``: input checks, constants, initial mode, error scales.
- ``transitions``: mode transitions of the normal contact and the friction at events, and the
  restart after a switch.
"""
