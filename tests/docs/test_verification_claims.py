"""Statements about the verification and the benchmarks, in the docs and in the verification
page's texts, against what they describe: the Hertz cases, the partial-slip reference, each
law's reference interference, the engine benchmark's results file and the energy-rise study."""

from __future__ import annotations

import importlib.util
import json
import math
from pathlib import Path
from types import ModuleType

import pytest

from impactlab import verification as V
from impactlab.bodies import PAPER_ROD

ROOT = Path(__file__).resolve().parents[2]
STUDY = ROOT / "tools" / "energy_history_study.py"

pytestmark = pytest.mark.usefixtures("warm_engine")


def _flat(text: str) -> str:
    return " ".join(text.split())


def test_hertz_cases_span_the_stated_ranges() -> None:
    radii = [r for r, _v, _m in V.HERTZ_CASES]
    speeds = [v for _r, v, _m in V.HERTZ_CASES]
    assert (min(radii), max(radii)) == (0.002, 0.030) and (min(speeds), max(speeds)) == (0.05, 4.0)
    text = _flat(V.verify_hertz(V.HERTZ_CASES[:1]).text)
    assert f"speeds of 0.05-4 m/s (a factor of {max(speeds) / min(speeds):.0f})" in text
    assert f"radii of 2-30 mm (a factor of {max(radii) / min(radii):.0f})" in text
    assert "two decades" not in text


def test_partial_slip_is_said_to_be_verified_without_solve_ivp() -> None:
    from impactlab.dynamics.reference import simulate_reference

    with pytest.raises(ValueError, match="no solve_ivp reference"):
        simulate_reference(
            PAPER_ROD, friction="partial_slip", mu=0.2, velocity=(0.0, -1.0), angle=0.3
        )
    index = _flat((ROOT / "docs" / "index.md").read_text())
    assert "for every law and friction model" not in index
    assert "the `partial_slip` model against its converged Mindlin-Deresiewicz solution" in index
    assert "`solve_ivp` integrator at rtol = 1e-11" in index
    assert "no `solve_ivp` reference" in _flat(V.verify_reference([]).text)


def test_each_laws_reference_interference_is_within_the_stated_percent() -> None:
    from impactlab.contact import get_law
    from impactlab.fe.accuracy import load_cases, measured_laws

    brake: list[float] = []
    others: list[float] = []
    for case in load_cases():
        for law in measured_laws():
            if law == "kogut-komvopoulos":  # stated on its own: 0.85-1.00
                continue
            try:
                model = get_law(law).build(case.pair, case.radius)
            except ValueError:  # a law that does not apply to the pair
                continue
            ratio = model.critical_interference / case.delta_c
            (brake if law == "brake" else others).append(ratio)
    assert brake and all(0.997 <= round(r, 3) <= 0.998 for r in brake)
    assert max(abs(r - 1.0) for r in brake + others) <= 0.003
    page = _flat((ROOT / "docs" / "laws" / "accuracy.md").read_text())
    assert "differs from it by at most 0.3 % (Brake's $\\delta_y$: 0.997-0.998 $\\delta_c$)" in page


def test_engine_benchmark_page_quotes_its_results_file() -> None:
    res = json.loads((ROOT / "benchmarks" / "results" / "engine.json").read_text())
    page = (ROOT / "docs" / "engine" / "benchmarks.md").read_text()
    top = page[: page.index("<!-- written by hand below")]
    one, calls = res["compiled_one_core"], res["single_call"]
    assert f"{one['impacts_per_cpu_s']:,.0f} impacts per CPU-second" in top
    assert f"{res['speedup_vs_solve_ivp_per_core']:.0f} x" in top
    assert f"{calls['simulate_us_history_false']:.1f} us without history" in top
    quick = one["n"] == 4000
    assert ("--quick" in top) == quick
    if not res["targets_met"]["impacts_per_s_per_core"]:
        assert "**On that run the per-core target was missed**" in top
        row = next(ln for ln in page.splitlines() if ln.startswith("| >= 150,000 impacts"))
        assert f"{one['impacts_per_cpu_s'] / 1e3:.1f}k" in row and "missed" in row


def _study() -> ModuleType:
    spec = importlib.util.spec_from_file_location("energy_history_study", STUDY)
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_energy_history_study_runs(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "study.json"
    assert _study().main(["--drops", "2", "--seeds", "0", "--json", str(out)]) == 0
    res = json.loads(out.read_text())
    assert len(res["rows"]) == 7 * 4
    assert set(res["worst_at_rtol"]) == {"1e-07", "1e-08", "1e-09", "1e-10"}
    assert all(r["counted"] + r["excluded"] == 2 for r in res["rows"])
    assert "largest:" in capsys.readouterr().out
    text = _flat(V.verify_invariants(1, laws=["hertz"], frictions=["coulomb"]).text)
    assert "`tools/energy_history_study.py`" in text and "600 random drops" in text


def _sci(x: float) -> str:
    mant, exp = f"{x:.1e}".split("e")
    return f"{mant}e{int(exp)}"


@pytest.mark.slow
def test_invariants_text_quotes_the_energy_history_study() -> None:
    """The figures of the invariants text are those of ``tools/energy_history_study.py`` with
    its defaults (2 seeds x 300 drops per law and friction model)."""
    res = _study().study(300, [1, 2])
    text = _flat(V.verify_invariants(1, laws=["hertz"], frictions=["coulomb"]).text)
    w = res["worst"]
    assert f"the largest was {_sci(w['rise'])} E0" in text
    assert f"(`{w['law']}`, `{w['friction']}`, a {w['regime']};" in text
    ps = max(r["worst"]["rise"] for r in res["rows"] if r["friction"] == "partial_slip")
    assert f"{math.ceil(ps * 1e7)}e-7 at most with `partial_slip`" in text
    tighter = ", ".join(_sci(v) for v in list(res["worst_at_rtol"].values())[:3])
    last = _sci(res["worst_at_rtol"]["1e-10"])
    assert f"on that drop {tighter} and {last} E0 at rtol 1e-7, 1e-8, 1e-9 and 1e-10" in text
