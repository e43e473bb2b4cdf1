"""The garbage collector is paused exactly while numba compiles impactlab's engine
(``impactlab._compile_gc``): off from the outermost impactlab compilation to its end, then on and
collected; untouched by other packages' compilations and when the caller had switched it off."""

from __future__ import annotations

import gc
import subprocess
import sys
from collections.abc import Iterator
from types import SimpleNamespace

import pytest

from impactlab import _compile_gc


def _event(module: str) -> SimpleNamespace:
    def fn() -> None:
        pass

    fn.__module__ = module
    return SimpleNamespace(data={"dispatcher": SimpleNamespace(py_func=fn)})


@pytest.fixture
def gc_on() -> Iterator[None]:
    was = gc.isenabled()
    gc.enable()
    yield
    if not was:
        gc.disable()


ENGINE = _event("impactlab.dynamics.flexcore.driver")
KERNEL = _event("impactlab.contact.kernels")
OTHER = _event("someones_package.kernels")


def test_paused_from_the_outermost_compilation_to_its_end(gc_on: None) -> None:
    pause = _compile_gc.GCPause()
    pause.on_start(ENGINE)
    assert not gc.isenabled()
    pause.on_start(KERNEL)  # a nested callee
    pause.on_end(KERNEL)
    assert not gc.isenabled()
    pause.on_end(ENGINE)
    assert gc.isenabled()
    assert pause.depth == 0 and not pause.paused


def test_other_packages_compilations_leave_it_alone(gc_on: None) -> None:
    pause = _compile_gc.GCPause()
    pause.on_start(OTHER)
    pause.on_start(ENGINE)  # nested in another package's compilation: not the outermost
    assert gc.isenabled()
    pause.on_end(ENGINE)
    pause.on_end(OTHER)
    assert gc.isenabled()
    pause.on_start(_event(""))  # an event without a dispatcher
    assert gc.isenabled()
    pause.on_end(_event(""))


def test_collector_switched_off_by_the_caller_stays_off(gc_on: None) -> None:
    gc.disable()
    pause = _compile_gc.GCPause()
    pause.on_start(ENGINE)
    pause.on_end(ENGINE)
    assert not gc.isenabled()


def test_installed_once_on_import() -> None:
    assert len(_compile_gc._INSTALLED) == 1
    _compile_gc.install()
    assert len(_compile_gc._INSTALLED) == 1


def test_a_real_compilation_pauses_and_restores_it() -> None:
    """In a fresh process: a new compiled function of an impactlab module compiles with the
    collector off (seen by a listener registered after impactlab's), and the collector is on
    again afterwards."""
    code = (
        "import gc, impactlab\n"
        "from numba import njit\n"
        "def probe(x):\n"
        "    return x + 1.0\n"
        "probe.__module__ = 'impactlab.probe'\n"
        "import numba.core.event as ev\n"
        "class L(ev.Listener):\n"
        "    def on_start(self, e): states.append(gc.isenabled())\n"
        "    def on_end(self, e): pass\n"
        "states = []\n"
        "ev.register('numba:compile', L())\n"
        "njit(probe)(1.0)\n"
        "print(gc.isenabled(), states)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=600, check=True
    )
    enabled, states = out.stdout.split(" ", 1)
    assert enabled == "True"
    assert states.strip() == "[False]"  # off while the function compiled


def test_deferred_garbage_is_frozen_then_handed_back(gc_on: None) -> None:
    """``garbage_deferred`` (``impactlab simulate``): the block's start and the end of a
    compilation freeze instead of collecting, and the block's end hands the objects back to the
    collector."""
    assert gc.get_freeze_count() == 0
    pause = _compile_gc.GCPause()
    with _compile_gc.garbage_deferred(pause):
        assert gc.get_freeze_count() > 0  # what was alive at the start
        pause.on_start(ENGINE)
        garbage = [[]]
        garbage[0].append(garbage)  # a reference cycle left by the compilation
        del garbage
        pause.on_end(ENGINE)
        assert gc.isenabled() and gc.collect(0) == 0  # frozen, not in the youngest generation
        pause.on_start(ENGINE)  # a second compilation in the block: frozen as well
        pause.on_end(ENGINE)
    assert gc.get_freeze_count() == 0
    assert not pause.defer and not pause.froze


def test_deferral_leaves_objects_the_caller_froze_alone(gc_on: None) -> None:
    gc.freeze()
    try:
        frozen = gc.get_freeze_count()
        pause = _compile_gc.GCPause()
        with _compile_gc.garbage_deferred(pause):
            pause.on_start(ENGINE)
            pause.on_end(ENGINE)  # collected, as without the block
        assert gc.get_freeze_count() == frozen and not pause.froze
    finally:
        gc.unfreeze()
