"""The numba cache fingerprint covers every source the compiled core depends on (found by glob,
so a new file is covered), and a changed fingerprint flushes the compiled functions' caches."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

from impactlab.contact import kernels
from impactlab.dynamics.core import _cache, driver, integrator


def _tree(root: Path) -> None:
    for rel in (
        "dynamics/core/driver.py",
        "contact/kernels.py",
        "bodies/layout.py",
        "schema.py",
        "sweep/study.py",
    ):
        f = root / rel
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text(f"# {rel}\n")


def test_source_files_cover_every_module_of_the_real_package() -> None:
    files = set(_cache.source_files())
    pkg = _cache.PACKAGE
    for d in ("dynamics/core", "contact", "bodies"):
        expected = set((pkg / d).rglob("*.py"))
        assert expected and expected <= files, d
    assert pkg / "schema.py" in files
    assert pkg / "_floatbits.py" in files  # inlined into the table and the controller
    assert Path(driver.__file__).resolve() in files
    assert Path(kernels.__file__).resolve() in files
    assert not any("sweep" in f.parts or "cli" in f.parts for f in files)


def test_a_new_or_changed_file_changes_the_fingerprint(tmp_path: Path) -> None:
    _tree(tmp_path)
    fp0 = _cache.fingerprint(tmp_path)
    assert _cache.fingerprint(tmp_path) == fp0
    (tmp_path / "contact" / "new_law.py").write_text("X = 1\n")
    fp1 = _cache.fingerprint(tmp_path)
    assert fp1 != fp0
    nested = tmp_path / "dynamics" / "core" / "sub" / "kernel.py"
    nested.parent.mkdir()
    nested.write_text("Y = 2\n")
    fp2 = _cache.fingerprint(tmp_path)
    assert fp2 != fp1
    (tmp_path / "bodies" / "layout.py").write_text("NB = 7\n")
    fp3 = _cache.fingerprint(tmp_path)
    assert fp3 != fp2
    (tmp_path / "schema.py").write_text("# new field\n")
    fp4 = _cache.fingerprint(tmp_path)
    assert fp4 != fp3
    (tmp_path / "sweep" / "study.py").write_text("# not compiled\n")
    assert _cache.fingerprint(tmp_path) == fp4


class _FakeCache:
    def __init__(self, path: Path) -> None:
        self.cache_path = str(path)
        self.flushes = 0

    def flush(self) -> None:
        self.flushes += 1


def test_refresh_flushes_only_when_the_fingerprint_changes(tmp_path: Path) -> None:
    caches = [_FakeCache(tmp_path), _FakeCache(tmp_path / "other")]
    disps = [SimpleNamespace(_cache=c) for c in caches]
    assert _cache.refresh(disps, "test", fp="a")
    assert [c.flushes for c in caches] == [1, 1]
    assert not _cache.refresh(disps, "test", fp="a")
    assert [c.flushes for c in caches] == [1, 1]
    assert _cache.refresh(disps, "test", fp="b")
    assert [c.flushes for c in caches] == [2, 2]
    assert (tmp_path / "impactlab-test.stamp").read_text() == "b"


def test_dispatchers_include_the_core_and_the_contact_kernels() -> None:
    disps = _cache.dispatchers()
    for f in (driver.impact, integrator.dp_step, kernels.loading_force):
        assert any(d is f for d in disps)
    assert len({id(d) for d in disps}) == len(disps)
    # the stamp lives next to the core's cache: a core function comes first
    assert disps[0].py_func.__module__.startswith("impactlab.dynamics.core.")
