"""A progress display on the terminal gives way to the engine's compile notice: it is stopped
just before the notice's line is written (so the notice keeps one line, its counter updated in
place, instead of a new line above the bar for every update), and only inside ``gives_way``."""

from __future__ import annotations

import io

from impactlab import _compile_notice


class _Live:
    is_started = True


class _Display:
    """What ``gives_way`` reads of a rich Progress: ``live.is_started`` and ``stop()``."""

    def __init__(self) -> None:
        self.live = _Live()
        self.stops = 0

    def stop(self) -> None:
        self.stops += 1
        self.live.is_started = False


def _announce(stream: io.StringIO) -> None:
    notice = _compile_notice._Notice("impactlab.dynamics.core", stream, "/cache")
    while not notice.shown and notice.thread.is_alive():
        notice.thread.join(0.01)
    notice.finish()


def test_a_display_gives_way_to_a_notice(monkeypatch) -> None:
    monkeypatch.setattr(_compile_notice, "DELAY_S", 0.0)
    display, stream = _Display(), io.StringIO()
    with _compile_notice.gives_way(display):
        _announce(stream)
    assert display.stops == 1 and not display.live.is_started
    assert stream.getvalue().startswith("impactlab: compiling the impact engine")
    assert _compile_notice._DISPLAYS == []


def test_a_display_outside_the_block_is_left_alone(monkeypatch) -> None:
    monkeypatch.setattr(_compile_notice, "DELAY_S", 0.0)
    display = _Display()
    with _compile_notice.gives_way(_Display()):
        pass
    _announce(io.StringIO())
    assert display.stops == 0 and display.live.is_started
