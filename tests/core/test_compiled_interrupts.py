"""Ctrl-C while a compiled function is dispatched: numba wraps the KeyboardInterrupt into a
SystemError ("returned a result with an exception set"), which reached the user as a traceback
with exit status 1 (`impactlab explain` interrupted during a flexible drop)."""

from __future__ import annotations

import pytest

from impactlab._interrupts import interrupt_inside, plain_interrupts


def _wrapped() -> None:
    try:
        raise KeyboardInterrupt
    except KeyboardInterrupt as ki:
        raise SystemError("CPUDispatcher(drop) returned a result with an exception set") from ki


def test_a_wrapped_interrupt_is_an_interrupt_again() -> None:
    with pytest.raises(KeyboardInterrupt), plain_interrupts():
        _wrapped()
    with pytest.raises(SystemError, match="other"), plain_interrupts():  # others pass on
        raise SystemError("other")
    assert interrupt_inside(ValueError("no")) is None


def test_a_wrapped_termination_keeps_its_class_and_status() -> None:
    """SIGTERM during a compiled call became a plain Ctrl-C (exit 130 instead of 143)."""
    from impactlab._compile_notice import one_line
    from impactlab.sweep.termination import SweepTerminated

    def wrapped_termination() -> None:
        try:
            raise SweepTerminated("terminated")
        except SweepTerminated as ki:
            raise SystemError("returned a result with an exception set") from ki

    with pytest.raises(SweepTerminated, match="terminated"), one_line():
        wrapped_termination()


def test_the_command_line_says_interrupted_with_status_130(monkeypatch) -> None:
    from typer.testing import CliRunner

    from impactlab.cli import app
    from impactlab.cli import laws as laws_cli

    def interrupted_inside(*args, **kwargs):  # type: ignore[no-untyped-def]
        _wrapped()

    monkeypatch.setattr(laws_cli, "_laws", interrupted_inside)
    result = CliRunner().invoke(app, ["laws"])
    if result.exit_code != 130:  # the command did not reach the patched function
        pytest.fail(f"exit {result.exit_code}: {result.output}")
    assert "interrupted" in result.output
