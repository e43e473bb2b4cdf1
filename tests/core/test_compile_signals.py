"""Ctrl-C and SIGTERM while numba compiles a function of impactlab are held until that
compilation ends, then delivered to the handlers in place before (an interrupt inside
llvmlite's cache callback was dropped, and numba failed with "no compiled object yet")."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from types import SimpleNamespace

import pytest

from impactlab._compile_signals import HOLD, SignalHold


def _event(module: str) -> SimpleNamespace:
    func = SimpleNamespace(__module__=module)
    return SimpleNamespace(data={"dispatcher": SimpleNamespace(py_func=func)})


def test_an_interrupt_during_a_compilation_arrives_at_its_end() -> None:
    hold, outer, inner = SignalHold(), _event("impactlab.dynamics.core.driver"), _event("numba")
    hold.on_start(outer)
    hold.on_start(inner)  # a callee's compilation: still held
    os.kill(os.getpid(), signal.SIGINT)
    hold.on_end(inner)
    assert hold.noted == [signal.SIGINT]
    with pytest.raises(KeyboardInterrupt):
        hold.on_end(outer)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert hold.noted == [] and hold.depth == 0


def test_another_package_s_compilation_is_not_held() -> None:
    hold = SignalHold()
    hold.on_start(_event("mypackage.kernels"))
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    hold.on_end(_event("mypackage.kernels"))


def test_the_hold_is_registered_with_numba() -> None:
    from numba.core import event

    names = {type(listener).__name__ for listener in event._registered["numba:compile"]}
    assert "_NumbaListener" in names and HOLD.depth == 0


def test_sigterm_of_a_sweep_during_a_compilation_keeps_its_handler() -> None:
    """A handler set by the program (a sweep's SIGTERM) is the one that gets the signal."""
    code = (
        "import os, signal\n"
        "from types import SimpleNamespace as N\n"
        "from impactlab._compile_signals import SignalHold\n"
        "got = []\n"
        "signal.signal(signal.SIGTERM, lambda s, f: got.append(s))\n"
        "h = SignalHold()\n"
        "e = N(data={'dispatcher': N(py_func=N(__module__='impactlab.x'))})\n"
        "h.on_start(e); os.kill(os.getpid(), signal.SIGTERM); assert got == []\n"
        "h.on_end(e); print(got)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == f"[{int(signal.SIGTERM)}]"
