"""An output place that cannot be written: one line naming the option and the path as typed,
before any work (``--out``, ``--plot``); and an error of the system on a file that still
reaches the command line (a folder turned read-only mid-run) is one line in the words of
``impactlab._oserror``, naming the file the user asked for (never the writer's temporary
``.NAME.PID.partial``), with exit status 1 whatever its errno."""

from __future__ import annotations

import errno
import os
import tempfile
from pathlib import Path
from typing import Any

import pytest

from impactlab import _files
from impactlab._files import folder_refusal, write_text_atomic
from impactlab._oserror import target_of

SPHERE = ("simulate", "sphere", "--radius", "5 mm", "--vy", "-1 m/s")


def _deny(monkeypatch: pytest.MonkeyPatch, folder: Path, code: int = errno.EACCES) -> None:
    """No file can be made in ``folder`` (as for a user without permission, or a read-only
    file system): tests run as root, which may write anywhere."""
    real = tempfile.mkdtemp

    def mkdtemp(*args: Any, **kw: Any) -> str:
        if Path(kw.get("dir") or ".").resolve() == folder.resolve():
            raise OSError(code, os.strerror(code), str(folder))
        return real(*args, **kw)

    monkeypatch.setattr(_files.tempfile, "mkdtemp", mkdtemp)


def test_the_temporary_name_maps_back_to_the_target() -> None:
    assert target_of(os.path.join("ro", ".x.csv.11881.partial")) == os.path.join("ro", "x.csv")
    assert target_of(".impact_force_time.png.7.partial") == "impact_force_time.png"
    assert target_of("ro/x.csv") == "ro/x.csv"


def test_a_failed_atomic_write_names_the_target(tmp_path: Path) -> None:
    target = tmp_path / "missing" / "x.csv"
    with pytest.raises(FileNotFoundError) as caught:
        write_text_atomic(target, "a")
    assert caught.value.filename == str(target)  # not ".x.csv.<pid>.partial"


@pytest.mark.parametrize("code", [errno.EACCES, errno.EPERM, errno.EROFS])
def test_folder_refusal_names_the_option_and_the_path_as_typed(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, code: int
) -> None:
    ro = tmp_path / "ro"
    ro.mkdir()
    _deny(monkeypatch, ro, code)
    why = "read-only file system" if code == errno.EROFS else "no permission for this user"
    assert folder_refusal(ro, "--out") == (
        f"--out {str(ro)!r}: the folder is not writable ({why}); choose another --out"
    )
    assert folder_refusal(ro / "sub", "--plot") == (
        f"--plot {str(ro / 'sub')!r}: its folder {str(ro)!r} is not writable ({why}); "
        "choose another --plot"
    )
    assert folder_refusal(tmp_path, "--out") is None


def test_a_folder_that_takes_no_files_is_not_called_missing(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """A folder of a virtual file system (/proc) exists but refuses new entries with ENOENT:
    the reason given is not "No such file or directory"."""
    virtual = tmp_path / "virtual"
    virtual.mkdir()
    _deny(monkeypatch, virtual, errno.ENOENT)
    assert folder_refusal(virtual, "--out") == (
        f"--out {str(virtual)!r}: the folder is not writable (it takes no new files, as in "
        "/proc or /sys); choose another --out"
    )


def test_simulate_plot_refuses_an_unwritable_out_before_running(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    import impactlab.cli.simulate as simulate_cli

    ro = tmp_path / "ro"
    ro.mkdir()
    _deny(monkeypatch, ro)
    monkeypatch.setattr(simulate_cli, "simulate", lambda *a, **k: pytest.fail("it ran"))
    code, out, err = cli_main(*SPHERE, "--plot", "--out", str(ro))
    assert code == 2 and out == ""
    assert err == (
        f"error: --out {str(ro)!r}: the folder is not writable (no permission for this user); "
        "choose another --out\n"
    )


def test_sweep_run_checks_plot_before_the_sweep(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    import impactlab.cli.sweep as sweep_cli

    ro = tmp_path / "ro"
    ro.mkdir()
    _deny(monkeypatch, ro)
    monkeypatch.setattr(sweep_cli, "run_study", lambda *a, **k: pytest.fail("the sweep ran"))
    study = Path(__file__).parents[2] / "examples" / "study-regime-map.toml"
    code, _, err = cli_main(
        "sweep", "run", str(study), "--out", str(tmp_path / "m.zarr"), "--plot", str(ro), "-q"
    )
    assert code == 2
    assert err.startswith(f"error: --plot {str(ro)!r}: the folder is not writable"), err


def test_sweep_plot_and_calibrate_and_reproduce_check_out(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    ro = tmp_path / "ro"
    ro.mkdir()
    _deny(monkeypatch, ro)
    line = f"error: --out {str(ro)!r}: the folder is not writable"
    runs = [
        ("sweep", "plot", str(tmp_path / "no.zarr"), "--out", str(ro)),
        ("reproduce", "--no-simulate", "--out", str(ro)),
        ("calibrate", str(tmp_path / "d.csv"), "-p", "mu=uniform(0, 0.6)", "--out", str(ro)),
    ]
    (tmp_path / "d.csv").write_text("drop,angle,vy,T\nd1,20 deg,-1 m/s,4 ms\n")
    for args in runs:
        code, _, err = cli_main(*args)
        assert code == 2 and err.startswith(line), (args, err)


@pytest.mark.parametrize(
    ("exc", "line"),
    [
        (
            PermissionError(errno.EACCES, "Permission denied", "ro/.x.csv.11881.partial"),
            "no permission for this user writing 'ro/x.csv': change its permissions (or write "
            "elsewhere) and run the command again",
        ),
        (
            PermissionError(errno.EPERM, "Operation not permitted", "imm/.a.png.5.partial"),
            "no permission for this user writing 'imm/a.png': change its permissions (or write "
            "elsewhere) and run the command again",
        ),
        (
            OSError(errno.EROFS, "Read-only file system", "rom/.b.png.10919.partial"),
            "read-only file system writing 'rom/b.png': make it writable (or write elsewhere) "
            "and run the command again",
        ),
        (
            NotADirectoryError(errno.ENOTDIR, "Not a directory", "afile/sub/state"),
            "Not a directory: 'afile/sub/state'",
        ),
    ],
)
def test_an_error_of_the_system_is_one_line_and_status_1(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, exc: OSError, line: str
) -> None:
    import impactlab.cli as cli

    def fail() -> None:
        raise exc

    monkeypatch.setattr(cli, "_run", fail)
    code, _, err = cli_main("laws")
    assert (code, err) == (1, f"error: {line}\n")
    assert "Errno" not in err and ".partial" not in err


@pytest.mark.parametrize(
    "exc",
    [
        FileNotFoundError("calibration file not found: x.toml"),
        PermissionError("--out 'ro' cannot be written to (no write permission)"),
        ValueError("--mu must be a number"),
    ],
)
def test_impactlab_s_own_refusals_stay_status_2(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, exc: Exception
) -> None:
    import impactlab.cli as cli

    def fail() -> None:
        raise exc

    monkeypatch.setattr(cli, "_run", fail)
    code, _, err = cli_main("laws")
    assert (code, err) == (2, f"error: {exc}\n")
