"""The garbage collector is paused exactly while numba compiles the flexible drop
(``flexcore.compile_gc``): off from the outermost flexcore compilation to its end, then on and
collected; untouched by other compilations and when the caller had switched it off."""

from __future__ import annotations

import gc
from collections.abc import Iterator
from types import SimpleNamespace

import pytest

from impactlab.dynamics.flexcore import compile_gc


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


FLEX = _event("impactlab.dynamics.flexcore.driver")
KERNEL = _event("impactlab.contact.kernels")
RIGID = _event("impactlab.dynamics.core.driver")


def test_paused_from_outermost_flexcore_compile_to_its_end(gc_on: None) -> None:
    pause = compile_gc.GCPause()
    pause.on_start(FLEX)
    assert not gc.isenabled()
    pause.on_start(KERNEL)  # nested: a callee of another package
    pause.on_end(KERNEL)
    assert not gc.isenabled()
    pause.on_end(FLEX)
    assert gc.isenabled()
    assert pause.depth == 0


def test_other_compilations_leave_it_alone(gc_on: None) -> None:
    pause = compile_gc.GCPause()
    pause.on_start(RIGID)
    pause.on_start(FLEX)  # nested in a rigid compilation: not the outermost
    assert gc.isenabled()
    pause.on_end(FLEX)
    pause.on_end(RIGID)
    assert gc.isenabled()


def test_collector_switched_off_by_the_caller_stays_off(gc_on: None) -> None:
    gc.disable()
    pause = compile_gc.GCPause()
    pause.on_start(FLEX)
    pause.on_end(FLEX)
    assert not gc.isenabled()


def test_installed_once_with_numba() -> None:
    import impactlab.dynamics.flexcore  # noqa: F401  (installs it)

    assert len(compile_gc._INSTALLED) == 1
    compile_gc.install()
    assert len(compile_gc._INSTALLED) == 1
