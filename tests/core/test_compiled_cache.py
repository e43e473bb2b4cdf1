"""Where the compiled engine is cached, the notice while it compiles, and ``impactlab warm``."""

from __future__ import annotations

import io
import json
import os
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import pytest

from impactlab import _compile_notice
from impactlab._compiled_cache import (
    ENGINE_SOURCES,
    compiled_cache_dir,
    default_cache_root,
    engine_source_hash,
    prune_engine_folders,
    source_hash,
)

ENGINE = f"engine-{engine_source_hash()}"


def _env_without(monkeypatch: pytest.MonkeyPatch, *names: str) -> None:
    for name in names:
        monkeypatch.delenv(name, raising=False)


def test_numba_cache_dir_wins(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "n"))
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path / "i"))
    assert compiled_cache_dir() == tmp_path / "n" / ENGINE
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "n" / ENGINE))  # as children inherit it
    assert compiled_cache_dir() == tmp_path / "n" / ENGINE


def test_impactlab_cache_dir_next(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    _env_without(monkeypatch, "NUMBA_CACHE_DIR")
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path / "i"))
    assert compiled_cache_dir() == tmp_path / "i" / "numba" / ENGINE
    assert default_cache_root() == tmp_path / "i"


def test_xdg_then_home(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    _env_without(monkeypatch, "NUMBA_CACHE_DIR", "IMPACTLAB_CACHE_DIR")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert compiled_cache_dir() == tmp_path / "xdg" / "impactlab" / "numba" / ENGINE
    monkeypatch.delenv("XDG_CACHE_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert compiled_cache_dir() == tmp_path / "home" / ".cache" / "impactlab" / "numba" / ENGINE


def test_every_entry_point_shares_one_folder(tmp_path: Path) -> None:
    """A fresh interpreter without NUMBA_CACHE_DIR: import impactlab points numba (its live
    configuration, the environment its children inherit, and the engine's cache) at the
    default folder."""
    env = {
        k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "IMPACTLAB_CACHE_DIR")
    }
    env["XDG_CACHE_HOME"] = str(tmp_path)
    code = (
        "import os, numba, impactlab\n"
        "from impactlab.dynamics.core.driver import impact\n"
        "print(numba.config.CACHE_DIR)\n"
        "print(os.environ['NUMBA_CACHE_DIR'])\n"
        "print(impact._cache.cache_path)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True
    ).stdout.split("\n")
    want = str(tmp_path / "impactlab" / "numba" / ENGINE)
    assert out[0] == want
    assert out[1] == want
    assert out[2].startswith(want)


def test_a_changed_engine_source_gets_a_new_folder(tmp_path: Path) -> None:
    """numba checks a cached function only against its own file: a constant changed in another
    file must change the folder, so nothing stale is linked."""
    (tmp_path / "core").mkdir()
    (tmp_path / "core" / "layout.py").write_text("C_MU = 8\n")
    (tmp_path / "core" / "rhs.py").write_text("def f(): ...\n")
    (tmp_path / "cli.py").write_text("x = 1\n")
    sources = ("core",)
    before = source_hash(tmp_path, sources)
    (tmp_path / "cli.py").write_text("x = 2\n")  # not engine source
    assert source_hash(tmp_path, sources) == before
    (tmp_path / "core" / "layout.py").write_text("C_MU = 6\n")
    assert source_hash(tmp_path, sources) != before


def test_every_compiled_function_and_what_it_reads_is_engine_source() -> None:
    """ENGINE_SOURCES covers every module with a compiled function and every impactlab module
    such a module imports (followed to the end)."""
    import ast
    import re

    package = Path(__file__).resolve().parents[2] / "src" / "impactlab"

    def covered(f: Path) -> bool:
        rel = f.relative_to(package).as_posix()
        return any(rel == s or rel.startswith(s + "/") for s in ENGINE_SOURCES)

    def module_file(name: str) -> Path | None:
        p = package.parent / Path(*name.split("."))
        for candidate in (p.with_suffix(".py"), p / "__init__.py"):
            if candidate.exists():
                return candidate
        return None

    def imported(f: Path) -> set[Path]:
        found: set[Path] = set()
        for node in ast.walk(ast.parse(f.read_text())):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("impactlab"):
                for alias in node.names:
                    m = module_file(f"{node.module}.{alias.name}") or module_file(str(node.module))
                    if m is not None:
                        found.add(m)
        return found

    compiled = re.compile(r"@njit|njit_no_refcount|= njit\(")
    todo = [f for f in package.rglob("*.py") if compiled.search(f.read_text())]
    assert len(todo) > 40
    seen: set[Path] = set()
    while todo:
        f = todo.pop()
        if f not in seen:
            seen.add(f)
            todo.extend(imported(f))
    missing = sorted(f.relative_to(package).as_posix() for f in seen if not covered(f))
    assert not missing, f"compiled code reads modules outside ENGINE_SOURCES: {missing}"


def test_old_engine_folders_are_pruned(tmp_path: Path) -> None:
    base = tmp_path / "numba"
    old = []
    for i in range(5):
        p = base / f"engine-{i:016x}"
        p.mkdir(parents=True)
        os.utime(p, (1000.0 + i, 1000.0 + i))
        old.append(p)
    legacy = base / "contact_0123"
    legacy.mkdir()
    current = base / "engine-ffffffffffffffff"
    removed = prune_engine_folders(current, keep=3, legacy=True)
    assert sorted(removed) == sorted([*old[:3], legacy])
    assert sorted(p.name for p in base.iterdir()) == [old[3].name, old[4].name]
    assert prune_engine_folders(current, keep=3) == []  # nothing more to remove


def _event(module: str) -> SimpleNamespace:
    return SimpleNamespace(
        data={"dispatcher": SimpleNamespace(py_func=SimpleNamespace(__module__=module))}
    )


class _Stream(io.StringIO):
    def isatty(self) -> bool:
        return False


def _stderr(monkeypatch: pytest.MonkeyPatch) -> _Stream:
    """A non-terminal stderr for this test (set in the test's body: pytest's own capture
    replaces sys.stderr between a fixture's setup and the test's call)."""
    s = _Stream()
    monkeypatch.setattr(sys, "stderr", s)
    monkeypatch.delenv("IMPACTLAB_QUIET_COMPILE", raising=False)
    return s


def _wait_for(predicate, limit_s: float = 60.0) -> bool:  # type: ignore[no-untyped-def]
    end = time.monotonic() + limit_s
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.01)
    return False


def test_a_long_compile_is_announced_once(monkeypatch: pytest.MonkeyPatch) -> None:
    stream = _stderr(monkeypatch)
    monkeypatch.setattr(_compile_notice, "DELAY_S", 0.0)
    listener = _compile_notice._Listener()
    listener.on_start(_event("impactlab.dynamics.core.driver"))
    listener.on_start(_event("impactlab.dynamics.kernels.rhs"))  # nested: counted, not announced
    assert _wait_for(lambda: stream.getvalue().endswith("\n"))
    listener.on_end(None)
    listener.on_end(None)
    lines = stream.getvalue().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("impactlab: compiling the impact engine (first run")
    assert f"about {_compile_notice.describe('impactlab.dynamics.core.driver')[1]} s" in lines[0]
    assert "cached in" in lines[0]


def test_a_part_compiled_in_pieces_is_announced_once(monkeypatch: pytest.MonkeyPatch) -> None:
    stream = _stderr(monkeypatch)
    monkeypatch.setattr(_compile_notice, "DELAY_S", 0.0)
    listener = _compile_notice._Listener()
    for module in ("impactlab.dynamics.flexcore.rhs", "impactlab.dynamics.flexcore.driver"):
        listener.on_start(_event(module))  # two outermost compiles of one part
        assert _wait_for(
            lambda: listener.notice is not None and not listener.notice.thread.is_alive()
        )
        listener.on_end(None)
    listener.on_start(_event("impactlab.dynamics.core.driver"))  # another part: its own line
    assert _wait_for(lambda: stream.getvalue().count("\n") == 2)
    listener.on_end(None)
    lines = stream.getvalue().splitlines()
    assert [line.split(" (")[0] for line in lines] == [
        "impactlab: compiling the flexible-rod drop engine",
        "impactlab: compiling the impact engine",
    ]


def test_compiles_in_one_block_share_one_line(monkeypatch: pytest.MonkeyPatch) -> None:
    stream = _stderr(monkeypatch)
    monkeypatch.setattr(_compile_notice, "DELAY_S", 0.0)
    listener = _compile_notice._Listener()
    with _compile_notice.one_line(listener):
        for module in ("impactlab.dynamics.flexcore.rhs", "impactlab.dynamics.flexcore.driver"):
            listener.on_start(_event(module))
            assert _wait_for(lambda: stream.getvalue().endswith("\n"))
            listener.on_end(None)
            assert listener.notice is not None  # the block is open: the notice stays
        first = listener.notice
    assert listener.notice is None and not first.thread.is_alive()  # ended with the block
    assert first.count == 1  # the second compile counted on the first one's line
    assert stream.getvalue().count("impactlab: compiling") == 1
    with _compile_notice.one_line(listener):  # nothing compiled: nothing printed
        pass
    assert stream.getvalue().count("\n") == 1
    assert listener.groups == 0 and listener.depth == 0


def test_short_or_foreign_compiles_stay_silent(monkeypatch: pytest.MonkeyPatch) -> None:
    stream = _stderr(monkeypatch)
    monkeypatch.setattr(_compile_notice, "DELAY_S", 3600.0)
    listener = _compile_notice._Listener()
    listener.on_start(_event("impactlab.contact.kernels"))  # ends long before the delay
    listener.on_end(None)
    monkeypatch.setattr(_compile_notice, "DELAY_S", 0.0)
    listener.on_start(_event("mypackage.kernels"))  # not impactlab's
    listener.on_end(None)
    monkeypatch.setenv("IMPACTLAB_QUIET_COMPILE", "1")
    listener.on_start(_event("impactlab.dynamics.core.driver"))
    listener.on_end(None)
    assert stream.getvalue() == ""
    assert listener.depth == 0


@pytest.mark.parametrize(
    ("module", "what"),
    [
        ("impactlab.dynamics.slipcore.driver", "partial-slip"),
        ("impactlab.dynamics.flexcore.driver", "flexible-rod"),
        ("impactlab.dynamics.core.batch", "batch"),
        ("impactlab.dynamics.slip_batch", "partial-slip batch"),
        ("impactlab.dynamics.core.driver", "impact engine"),
        ("impactlab.contact.kernels", "contact-law"),
    ],
)
def test_each_part_is_named(module: str, what: str) -> None:
    name, seconds = _compile_notice.describe(module)
    assert what in name
    assert seconds > 0


def test_warm_command_reports_the_cache() -> None:
    from typer.testing import CliRunner

    from impactlab.cli import app

    res = CliRunner().invoke(app, ["warm", "--part", "rigid impact", "--json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    assert data["cache_dir"] == str(compiled_cache_dir())
    assert [p["name"] for p in data["parts"]] == ["rigid impact"]
    assert data["parts"][0]["cpu_time"]["unit"] == "s"


def test_warm_refuses_an_unknown_part() -> None:
    from impactlab.dynamics.warm import warm

    with pytest.raises(ValueError, match="unknown engine part 'rigid'; choose from contact laws"):
        warm(("rigid",))


def test_the_process_groups_hold_every_part_once() -> None:
    from impactlab.dynamics.warm import PARTS, PROCESS_GROUPS

    names = [n for g in PROCESS_GROUPS for n in g]
    assert sorted(names) == sorted(PARTS)
    assert len(names) == len(set(names))


def test_warm_in_processes_returns_the_parts_in_the_order_asked() -> None:
    from impactlab.dynamics.warm import warm_in_processes

    done = warm_in_processes(("flexible rod", "contact laws"), jobs=2)
    assert [p.name for p in done] == ["flexible rod", "contact laws"]
    assert all(p.cpu_s >= 0 and p.wall_s >= 0 for p in done)


def test_warm_in_processes_names_the_group_that_failed(monkeypatch: pytest.MonkeyPatch) -> None:
    from impactlab.dynamics import warm as warm_module

    monkeypatch.setattr(warm_module.sys, "executable", "false")
    with pytest.raises(RuntimeError, match=r"failed in: contact laws \(exit code 1\); flexible"):
        warm_module.warm_in_processes(("contact laws", "flexible rod"), jobs=2)


def test_warm_in_processes_refuses_zero_jobs() -> None:
    from impactlab.dynamics.warm import warm_in_processes

    with pytest.raises(ValueError, match="jobs must be a whole number >= 1, got 0"):
        warm_in_processes(jobs=0)


def test_the_kernels_on_the_way_to_an_engine_wait_longer(monkeypatch: pytest.MonkeyPatch) -> None:
    """A cold run compiles the contact-law kernels (1-3 s) and then the engine: only the
    engine's line, unless the kernels alone run past KERNEL_DELAY_FACTOR x DELAY_S."""
    stream = _stderr(monkeypatch)
    monkeypatch.setattr(_compile_notice, "DELAY_S", 0.05)
    monkeypatch.setattr(_compile_notice, "KERNEL_DELAY_FACTOR", 3600.0 / 0.05)
    listener = _compile_notice._Listener()
    listener.on_start(_event("impactlab.contact.kernels"))
    listener.on_end(None)  # long before its delay: silent
    listener.on_start(_event("impactlab.dynamics.core.driver"))
    assert _wait_for(lambda: stream.getvalue().endswith("\n"))
    listener.on_end(None)
    lines = stream.getvalue().splitlines()
    assert len(lines) == 1 and lines[0].startswith("impactlab: compiling the impact engine")
    assert _compile_notice.KERNEL_PARTS <= {name for _, name, _ in _compile_notice.PARTS}


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.mark.parametrize("columns", [80, 1000])
def test_the_refreshed_line_fits_the_terminal(
    monkeypatch: pytest.MonkeyPatch, columns: int
) -> None:
    """The ~200-character line was refreshed with a carriage return on narrower terminals:
    one new row per refresh (136 rows for a 69 s compile at 120 columns)."""
    stream = _Terminal()
    monkeypatch.setattr(sys, "stderr", stream)
    monkeypatch.delenv("IMPACTLAB_QUIET_COMPILE", raising=False)
    monkeypatch.setattr(_compile_notice, "DELAY_S", 0.0)
    monkeypatch.setattr(_compile_notice, "_columns", lambda: columns)
    listener = _compile_notice._Listener()
    listener.on_start(_event("impactlab.dynamics.core.driver"))
    assert _wait_for(lambda: " functions" in stream.getvalue())
    listener.on_end(None)
    text = stream.getvalue()
    assert text.startswith("impactlab: compiling the impact engine") and "done in" in text
    for row in text.split("\n")[1:]:  # the refreshed rows (the first is written once)
        assert len(row.rsplit("\r", 1)[-1]) < columns
    if columns == 80:  # the whole line once, then a short line refreshed
        assert text.split("\n")[1].startswith("\r  compiling ... ")
    else:
        assert text.count("\n") == 1  # one line, refreshed in place
