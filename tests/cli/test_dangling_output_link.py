"""A symbolic link to a missing folder given as an output folder (or standing where a folder
above it would be made) is refused before any work, in one line naming the option, the path
as typed and the link's target: the folder could not be made through it."""

from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import Any

import pytest

from impactlab._files import folder_refusal, missing_link
from impactlab.experiment.checks import check_output_folder, output_folder

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="symbolic links (POSIX)")

SPHERE = ("simulate", "sphere", "--radius", "5 mm", "--vy", "-1 m/s")


def _dangling(tmp_path: Path) -> tuple[Path, str]:
    link, target = tmp_path / "dangling", tmp_path / "gone"
    link.symlink_to(target)
    return link, f"symbolic link to a missing folder ({str(target)!r}): make that folder"


def test_folder_refusal_names_a_dangling_link(tmp_path: Path) -> None:
    link, words = _dangling(tmp_path)
    assert folder_refusal(link, "--out") == (
        f"--out {str(link)!r} is a {words}, or choose another --out"
    )
    assert folder_refusal(link / "sub", "--plot") == (
        f"--plot {str(link / 'sub')!r} is inside {str(link)!r}, a {words}, or choose another --plot"
    )


def test_a_link_to_an_existing_folder_is_taken(tmp_path: Path) -> None:
    (tmp_path / "real").mkdir()
    (tmp_path / "link").symlink_to(tmp_path / "real")
    assert missing_link(tmp_path / "link", "--out") is None
    assert missing_link(tmp_path / "link" / "new" / "sub", "--out") is None
    assert folder_refusal(tmp_path / "link" / "new", "--out") is None
    assert check_output_folder(tmp_path / "link" / "new") == tmp_path / "link" / "new"


def test_check_output_folder_refuses_a_dangling_link(tmp_path: Path) -> None:
    link, words = _dangling(tmp_path)
    line = f"out_dir {str(link)!r} is a {words}, or choose another out_dir"
    with pytest.raises(ValueError, match=f"^{re.escape(line)}$"):
        check_output_folder(link)
    inside = f"out_dir {str(link / 'sub')!r} is inside {str(link)!r}, a {words}"
    with pytest.raises(ValueError, match=f"^{re.escape(inside)}"):
        output_folder(link / "sub")
    assert not (tmp_path / "gone").exists()


def test_simulate_refuses_a_dangling_out_before_running(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    import impactlab.cli.simulate as simulate_cli

    link, words = _dangling(tmp_path)
    monkeypatch.setattr(simulate_cli, "simulate", lambda *a, **k: pytest.fail("it ran"))
    code, out, err = cli_main(*SPHERE, "--plot", "--out", str(link))
    assert (code, out) == (2, "")
    assert err == f"error: --out {str(link)!r} is a {words}, or choose another --out\n"


def test_calibrate_and_sweep_refuse_a_dangling_out(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    import impactlab.cli.sweep as sweep_cli

    link, words = _dangling(tmp_path)
    monkeypatch.setattr(sweep_cli, "run_study", lambda *a, **k: pytest.fail("the sweep ran"))
    (tmp_path / "d.csv").write_text("drop,angle,vy,T\nd1,20 deg,-1 m/s,4 ms\n")
    study = Path(__file__).parents[2] / "examples" / "study-regime-map.toml"
    runs = [
        ("calibrate", str(tmp_path / "d.csv"), "-p", "mu=uniform(0, 0.6)", "--out", str(link)),
        ("sweep", "plot", str(tmp_path / "no.zarr"), "--out", str(link)),
        ("sweep", "run", str(study), "--out", str(link), "-q"),
    ]
    for args in runs:
        code, _, err = cli_main(*args)
        assert (code, err) == (2, f"error: --out {str(link)!r} is a {words}, or choose another "
                                  "--out\n"), args  # fmt: skip
