"""Meshing leaves Python's Ctrl-C handler as it was: gmsh's ``initialize`` sets SIGINT to the
system default and its ``finalize`` does not put the handler back, after which a Ctrl-C would end
the interpreter (a sweep, a calibration, a notebook) instead of raising KeyboardInterrupt."""

from __future__ import annotations

import signal
import subprocess
import sys
from types import SimpleNamespace
from typing import Any

import pytest

from impactlab.fe.mesh import MeshSpec, build_mesh

R = 8.8e-3
#: A small mesh (about 150 elements, a fraction of a second).
SMALL = MeshSpec(R, 2e-5, 0.3, 2e-3, 5e-4, 2e-3)


def _mark(signum: int, frame: Any) -> None:  # pragma: no cover - never called
    """A handler of one's own, installed before meshing."""


@pytest.fixture
def own_handler():
    """A handler of one's own for SIGINT during the test; Python's put back after it."""
    before = signal.signal(signal.SIGINT, _mark)
    yield _mark
    signal.signal(signal.SIGINT, before)


@pytest.mark.parametrize("handler", [signal.default_int_handler, _mark])
def test_build_mesh_keeps_the_sigint_handler(handler):
    pytest.importorskip("gmsh", reason="impactlab.fe needs the gmsh package (the fe extra)")
    before = signal.signal(signal.SIGINT, handler)
    try:
        mesh = build_mesh(SMALL)
        after = signal.getsignal(signal.SIGINT)
    finally:
        signal.signal(signal.SIGINT, before)
    assert mesh.n_elements > 0
    assert after is handler


#: Meshes, then sends itself SIGINT: Python's handler raises KeyboardInterrupt (under gmsh's
#: default the process would end by the signal).
_AFTER_MESH = """
import signal
from impactlab.fe.mesh import MeshSpec, build_mesh
signal.signal(signal.SIGINT, signal.default_int_handler)
build_mesh(MeshSpec(8.8e-3, 2e-5, 0.3, 2e-3, 5e-4, 2e-3))
try:
    signal.raise_signal(signal.SIGINT)
except KeyboardInterrupt:
    print("KeyboardInterrupt")
"""


def test_ctrl_c_after_a_mesh_raises_keyboard_interrupt():
    pytest.importorskip("gmsh", reason="impactlab.fe needs the gmsh package (the fe extra)")
    r = subprocess.run(
        [sys.executable, "-c", _AFTER_MESH], capture_output=True, text=True, timeout=600
    )
    assert (r.returncode, r.stdout.strip()) == (0, "KeyboardInterrupt"), r.stderr


def _fake_gmsh(fail: bool) -> Any:
    """A gmsh that sets SIGINT to the default on initialize whatever it is asked (as gmsh before
    the ``interruptible`` keyword did) and whose meshing fails when ``fail``."""
    calls: list[str] = []

    def initialize(readConfigFiles: bool = True) -> None:  # noqa: N803 - gmsh's keyword
        calls.append("initialize")
        signal.signal(signal.SIGINT, signal.SIG_DFL)

    def set_number(name: str, value: float) -> None:
        if fail:
            raise RuntimeError("meshing failed")

    def finalize() -> None:
        calls.append("finalize")

    return SimpleNamespace(
        initialize=initialize,
        finalize=finalize,
        option=SimpleNamespace(setNumber=set_number),
        calls=calls,
    )


def test_the_handler_comes_back_when_meshing_fails(monkeypatch, own_handler):
    fake = _fake_gmsh(fail=True)
    monkeypatch.setitem(sys.modules, "gmsh", fake)
    with pytest.raises(RuntimeError, match="meshing failed"):
        build_mesh(SMALL)
    assert fake.calls == ["initialize", "finalize"]
    assert signal.getsignal(signal.SIGINT) is own_handler
