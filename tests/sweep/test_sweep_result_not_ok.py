"""What ``run_sweep`` returns says how many cases of the store are not ok, and why (its repr,
its notebook table, ``stats``), and a run that leaves such cases warns once, as the command
line prints them; the status counts call status 0 "finished" (the engine ran the case to its
end: whether its result is ok, the flags say)."""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator, FlaggingEvaluator, run_cli

from impactlab.sweep import Study, run_sweep, status_counts, store_info
from impactlab.sweep.runner import FlaggedCasesWarning

NOT_OK = "9 case(s) not ok (energy gain: 4, gravity-dominated: 7)"


def _study(vy=(-1.41, -0.3)) -> Study:
    """mu = 0, 0.1, ..., 0.6 x vy (FlaggingEvaluator: energy gain where mu > 0.4, 4 cases;
    gravity-dominated where vy > -0.5, 7 cases; 9 not ok)."""
    return Study(
        name="notok",
        grid={"mu": np.round(np.linspace(0.0, 0.6, 7), 12), "vy": list(vy)},
        fixed={"angle": 0.5},
        outputs=["e"],
    )


def test_the_result_counts_the_cases_not_ok_and_warns_once(tmp_path: Path) -> None:
    store = tmp_path / "n.zarr"
    with pytest.warns(FlaggedCasesWarning) as caught:
        res = run_sweep(_study(), store, evaluator=FlaggingEvaluator(), quiet=True)
    assert len([w for w in caught if w.category is FlaggedCasesWarning]) == 1
    assert str(caught[0].message).startswith(f"sweep 'notok' in {str(store)!r}: {NOT_OK}: ")
    st = res.stats
    assert st.not_ok == 9 and st.flagged["energy gain"] == 4 and st.flagged["flagged"] == 9
    assert st.status == {"0: finished": 14}
    assert repr(res).endswith(f"backend='threads'; {NOT_OK})")
    assert repr(st).endswith(f"workers={st.workers}; {NOT_OK})")
    html = res._repr_html_()
    assert "not ok (flags)" in html and NOT_OK in html
    # a resume that computes nothing still says what the store holds
    with pytest.warns(FlaggedCasesWarning):
        again = run_sweep(_study(), store, evaluator=FlaggingEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0 and again.stats.not_ok == 9


def test_a_run_without_cases_not_ok_does_not_warn(tmp_path: Path) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", FlaggedCasesWarning)
        res = run_sweep(_study(vy=(-1.41,)), tmp_path / "ok.zarr", evaluator=FakeEvaluator(),
                        quiet=True)  # fmt: skip
    assert res.stats.not_ok == 0 and res.stats.flagged == {}
    assert "not ok" not in repr(res)


def test_cases_without_a_result_are_counted(tmp_path: Path) -> None:
    """FakeEvaluator: status 1 where vy < -5 (no result)."""
    res = run_sweep(_study(vy=(-1.41, -6.0)), tmp_path / "f.zarr", evaluator=FakeEvaluator(),
                    quiet=True)  # fmt: skip
    assert res.stats.status == {"0: finished": 7, "1: fake: vy outside the validity range": 7}
    assert repr(res).endswith("; 7 case(s) without a result (status > 0))")
    assert "without a result" in res._repr_html_()


def test_status_zero_reads_finished_in_the_summaries(tmp_path, monkeypatch, capsys) -> None:
    store = tmp_path / "n.zarr"
    with pytest.warns(FlaggedCasesWarning):
        res = run_sweep(_study(), store, evaluator=FlaggingEvaluator(), quiet=True)
    assert status_counts(res.dataset) == {"0: finished": 14}
    assert store_info(store)["status"] == {"0: finished": 14}
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store))
    assert code == 0, err
    assert "0: finished = 14" in out and "0: ok" not in out
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store), "--json")
    assert code == 0 and '"0: finished": 14' in out


def test_the_command_line_prints_them_once(tmp_path, monkeypatch, capsys) -> None:
    """``sweep run`` counts them in its summary; no warning line repeats them."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("impactlab.sweep.runner.ENGINE", FlaggingEvaluator())
    (tmp_path / "n.toml").write_text(
        '[study]\nname = "notok"\n[fixed]\nangle = "20 deg"\n[grid]\n'
        "mu = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6]\nvy = [-1.41, -0.3]\n"
    )
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "n.toml", "--out", "n.zarr")
    assert code == 0 and "not ok" in out and "warning" not in err, err
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "n.toml", "-o", "n.zarr", "--json")
    assert code == 0 and json.loads(out)["flagged"]["not_ok"] == 9 and "warning" not in err
