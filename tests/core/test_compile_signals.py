"""Ctrl-C and SIGTERM while numba compiles a function of impactlab reach their handlers at
once, and again at the end of the compilation where numba's toolchain dropped them (an
interrupt inside llvmlite's cache callback was printed and lost, and numba failed with "no
compiled object yet")."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
from types import SimpleNamespace

import pytest

from impactlab._compile_signals import WATCH, SignalWatch


def _event(module: str, exc: type[BaseException] | None = None) -> SimpleNamespace:
    func = SimpleNamespace(__module__=module)
    details = None if exc is None else (exc, exc(), None)
    return SimpleNamespace(data={"dispatcher": SimpleNamespace(py_func=func)}, _exc_details=details)


def _kill_and_wait(sig: int) -> None:
    os.kill(os.getpid(), sig)
    for _ in range(10**6):  # the handler runs at the next bytecode
        pass


def test_an_interrupt_during_a_compilation_arrives_at_once() -> None:
    watch, outer = SignalWatch(), _event("impactlab.dynamics.core.driver")
    watch.on_start(outer)
    with pytest.raises(KeyboardInterrupt):
        _kill_and_wait(signal.SIGINT)
    watch.on_end(_event("impactlab.dynamics.core.driver", KeyboardInterrupt))  # came through
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert watch.noted == [] and watch.depth == 0


def test_an_interrupt_dropped_on_its_way_is_raised_again_at_the_end() -> None:
    watch, outer, inner = SignalWatch(), _event("impactlab.x"), _event("numba.y")
    watch.on_start(outer)
    watch.on_start(inner)
    with contextlib.suppress(KeyboardInterrupt):  # what a ctypes callback does with it
        watch.deliver(signal.SIGINT, None)
    with pytest.raises(KeyboardInterrupt):
        watch.on_end(inner)  # the callee's compilation ended as if nothing had happened
    watch.on_end(_event("impactlab.x", KeyboardInterrupt))
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert watch.noted == [] and watch.depth == 0


def test_another_package_s_compilation_is_not_watched() -> None:
    watch = SignalWatch()
    watch.on_start(_event("mypackage.kernels"))
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    watch.on_end(_event("mypackage.kernels"))


def test_the_watch_is_registered_with_numba() -> None:
    from numba.core import event

    names = {type(listener).__name__ for listener in event._registered["numba:compile"]}
    assert "_NumbaListener" in names and WATCH.depth == 0


def test_a_program_s_sigterm_handler_gets_the_signal_at_once() -> None:
    """A handler set by the program (a sweep's SIGTERM) is the one that gets the signal."""
    code = (
        "import os, signal\n"
        "from types import SimpleNamespace as N\n"
        "from impactlab._compile_signals import SignalWatch\n"
        "got = []\n"
        "signal.signal(signal.SIGTERM, lambda s, f: got.append(s))\n"
        "w = SignalWatch()\n"
        "e = N(data={'dispatcher': N(py_func=N(__module__='impactlab.x'))}, _exc_details=None)\n"
        "w.on_start(e); os.kill(os.getpid(), signal.SIGTERM)\n"
        "for _ in range(10**6): pass\n"
        "assert got == [signal.SIGTERM], got\n"
        "w.noted.clear(); w.on_end(e); print(got)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == f"[{int(signal.SIGTERM)}]"


def test_the_report_of_a_dropped_interrupt_is_left_out(capsys: pytest.CaptureFixture[str]) -> None:
    """Python printed "Exception ignored on calling ctypes callback function" and a traceback
    for the interrupt it dropped, which the end of the compilation raises again."""
    watch, e, hook = SignalWatch(), _event("impactlab.x"), sys.unraisablehook
    watch.on_start(e)
    with contextlib.suppress(KeyboardInterrupt):
        watch.deliver(signal.SIGINT, None)
    report = SimpleNamespace(
        exc_type=KeyboardInterrupt,
        exc_value=KeyboardInterrupt(),
        exc_traceback=None,
        err_msg="Exception ignored",
        object=None,
    )
    sys.unraisablehook(report)
    assert capsys.readouterr().err == ""
    with pytest.raises(KeyboardInterrupt):
        watch.on_end(e)
    assert sys.unraisablehook is hook
