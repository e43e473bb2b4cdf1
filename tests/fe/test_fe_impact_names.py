"""The FE impact speaks the glossary's names and signs (docs/glossary.md): ``e``, ``duration``,
``delta_max``, ``delta_p`` (with its two parts), the history ``penetration`` and ``vy`` (up
positive, negative towards the flat). The names before 0.3 read the same values with a
DeprecationWarning, and cache files and impact tables written in them still read. No ccx:
``assemble`` reads a small stand-in ``job.dat``, and ``impact`` finds its result in the cache.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path
from types import SimpleNamespace
from typing import Any, cast

import numpy as np
import pytest

from impactlab import schema
from impactlab.fe import cache, impact_run
from impactlab.fe.ccx import RunOutput
from impactlab.fe.impact_problem import make_impact_problem
from impactlab.fe.impact_quasistatic import one_dof_impact
from impactlab.fe.impact_reference import impact_path, load_impact_table
from impactlab.fe.impact_result import (
    IMPACT_ARRAYS,
    RENAMED_IMPACT_FIELDS,
    ImpactResult,
    node_masses,
)
from impactlab.materials import AISI_201, AISI_1010
from impactlab.verification.fe_impact import compare_impacts

R = 8.8e-3
SPEED = 0.1  # m/s
GAP = 1.0e-7  # m
DT = 1.0e-6  # s
#: The sphere's centre-of-mass velocity [mm/s] (ccx's units; up positive) at each increment.
V_CM = [-100.0, -90.0, -50.0, 0.0, 40.0, 70.0, 80.0, 80.0, 80.0, 80.0, 80.0, 80.0]
#: Its displacement [mm] and the contact force [N] there.
U_CM = [-1e-4, -2e-4, -3e-4, -3.5e-4, -3e-4, -2.5e-4, -2e-4, -1e-4, 0.0, 1e-4, 2e-4, 3e-4]
FORCE = [0.0, 10.0, 40.0, 80.0, 40.0, 10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
APEX_RISE = 2e-4  # mm: the apex above the sphere's other nodes (its permanent flattening)
DENT = 1e-3  # mm: the flat's axis node below its surface at the end

#: A stand-in mesh: one sphere element (nodes 1-4, the apex node 1 at the origin) and the
#: flat's two surface nodes (5 on the axis, 6).
MESH = cast(
    Any,
    SimpleNamespace(
        nodes=np.array([[0, 0], [1e-3, 1e-4], [1e-3, 1e-3], [0, 1e-3], [0, 0], [1e-3, 0]]),
        elements=np.array([[0, 1, 2, 3]]),
        sphere_elements=np.array([0]),
        sphere_nodes=np.arange(4),
        flat_surface_nodes=np.array([4, 5]),
        spec=SimpleNamespace(radius=R),
        n_elements=2,
    ),
)
PROBLEM = cast(
    Any,
    SimpleNamespace(
        gap=GAP,
        speed=SPEED,
        mass=0.02,
        end_time=len(V_CM) * DT,
        delta_c=4.36e-7,
        key_data=lambda: {"stand-in": True},
    ),
)


def _rows(what: str, nset: str, t: float, values: list[tuple[int, float]]) -> str:
    head = f" {what} (vx,vy,vz) for set {nset} and time  {t:.7E}\n\n"
    return head + "".join(f"{i:10d} {0.0:14.6E} {v:14.6E} {0.0:14.6E}\n" for i, v in values) + "\n"


def _dat() -> str:
    text = ""
    for k, (v, u, f) in enumerate(zip(V_CM, U_CM, FORCE, strict=True), 1):
        t = k * DT
        text += (
            f" statistics for slave set SF0, master set SSPH and time  {t:.7E}\n\n"
            "   total surface force (fx,fy,fz) and moment about the origin (mx,my,mz)\n\n"
            f"    0.000000E+00 {-f / 180.0:.6E}  0.000000E+00  0.0  0.0  0.0\n\n"
        )
        flat = -DENT if k > 6 else 0.0
        apex = u + (APEX_RISE if k > 6 else 0.0)
        text += _rows("displacements", "NSPH", t, [(1, apex), (2, u), (3, u), (4, u)])
        text += _rows("velocities", "NSPH", t, [(n, v) for n in range(1, 5)])
        text += _rows("displacements", "NFSURF", t, [(5, flat), (6, 0.0)])
    return text


def _sta() -> str:
    rows = ["SUMMARY OF JOB INFORMATION", "  STEP      INC     ATT  ITRS     TOT TIME"]
    rows += [f"     1  {k}  1  3  {k * DT:.6E}  {k * DT:.6E}  {DT:.6E}" for k in range(1, 13)]
    return "\n".join(rows) + "\n"


@pytest.fixture(scope="module")
def result() -> ImpactResult:
    return impact_run.assemble(PROBLEM, MESH, RunOutput(_dat(), _sta(), 0, "", 1.0))


def test_the_glossary_names_with_their_signs(result: ImpactResult) -> None:
    assert result.status() == "converged"
    # vy: up positive, -v_in before the contact, the rebound after it
    assert result.vy[0] == -SPEED and result.vy[1] == pytest.approx(-0.1)
    assert result.vy[-1] == pytest.approx(0.08) and result.rebound_speed == pytest.approx(0.08)
    assert result.e == pytest.approx(0.8) and result.e == result.rebound_speed / result.speed
    # penetration: the interference, the gap (negative) before first touch
    assert result.penetration[0] == -GAP
    assert result.penetration[4] == pytest.approx(3.5e-7 - GAP)
    assert result.delta_max == float(np.max(result.penetration))
    assert 0.0 < result.duration < 6 * DT and result.max_force == pytest.approx(80.0)
    # delta_p: the flat's dent at the axis plus the sphere's flattening at its apex
    weights = node_masses(MESH, MESH.sphere_elements, 1.0)
    share = weights[0] / weights[:4].sum()
    assert result.flat_dent_depth == pytest.approx(DENT * 1e-3, rel=1e-12)
    assert result.sphere_flattening == pytest.approx(APEX_RISE * 1e-3 * (1 - share), rel=1e-9)
    assert result.delta_p == result.flat_dent_depth + result.sphere_flattening
    assert set(IMPACT_ARRAYS) <= set(result.arrays())
    # the engine's names (impactlab.schema), and none of the names before 0.3
    assert {"e", "delta_max", "duration", "delta_p", "penetration", "vy"} <= set(schema.FIELDS)
    assert not set(RENAMED_IMPACT_FIELDS) & set(result.arrays())
    assert "velocity" not in result.arrays()


@pytest.mark.parametrize(("old", "new"), list(RENAMED_IMPACT_FIELDS.items()))
def test_an_old_name_warns_naming_the_new_and_agrees(
    result: ImpactResult, old: str, new: str
) -> None:
    with pytest.warns(DeprecationWarning, match=rf"'{old}' is renamed '{new}'"):
        value = getattr(result, old)
    assert np.array_equal(value, getattr(result, new))


def test_velocity_warns_of_the_sign_and_is_minus_vy(result: ImpactResult) -> None:
    with pytest.warns(DeprecationWarning, match=r"'velocity'.*renamed 'vy'.*velocity = -vy"):
        velocity = result.velocity
    assert np.array_equal(velocity, -result.vy) and velocity[0] == SPEED


def _write_old(path: Path, res: ImpactResult) -> None:
    """``res`` as ``impact_run.store`` wrote it before 0.3: its fields under the old names,
    ``velocity`` positive towards the flat, no split of the permanent depth."""
    new_to_old = {new: old for old, new in RENAMED_IMPACT_FIELDS.items()}
    record = {new_to_old.get(k, k): v for k, v in res.arrays().items() if k != "vy"}
    record["velocity"] = -res.vy
    del record["flat_dent_depth"], record["sphere_flattening"]
    arrays = ("time", "force", "interference", "velocity", "dent_r", "dent_z")
    header = {k: v for k, v in record.items() if k not in arrays}
    with open(path, "wb") as fh:
        np.savez(fh, header=np.array(json.dumps(header)), **{k: record[k] for k in arrays})


def _same(a: ImpactResult, b: ImpactResult, exact: bool = True) -> None:
    for k, v in a.arrays().items():
        w = getattr(b, k)
        if isinstance(v, np.ndarray):
            assert np.array_equal(v, w), k
        elif isinstance(v, float) and not exact:
            assert w == pytest.approx(v, rel=1e-12, abs=1e-20), k
        else:
            assert w == v, k


def test_a_cache_file_round_trips_in_the_new_names(result: ImpactResult, tmp_path: Path) -> None:
    impact_run.store(tmp_path, "k", result)
    with np.load(tmp_path / "impact-k.npz") as z:
        names = set(z.files) | set(json.loads(str(z["header"])))
    assert {"e", "delta_p", "penetration", "vy", "flat_dent_depth"} <= names
    assert not names & {*RENAMED_IMPACT_FIELDS, "velocity"}
    again = impact_run.load(tmp_path, "k")
    assert again is not None
    _same(result, again)


def test_a_cache_file_written_before_still_reads(
    result: ImpactResult, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An impact cached before 0.3 is found under the same key (the schema version did not
    change) and read in the new names: the same values, velocity turned into vy, and the
    flat's dent read from its final surface at the axis (the last increment's)."""
    problem = make_impact_problem(
        AISI_1010, AISI_201, radius=R, speed=SPEED, sphere="elastic", flat_hardening="elastic"
    )
    key = cache.cache_key(problem.key_data(), "stand-in")
    _write_old(tmp_path / f"impact-{key}.npz", result)
    monkeypatch.setattr(impact_run, "find_ccx", lambda: "ccx")
    monkeypatch.setattr(impact_run, "ccx_version", lambda exe: "stand-in")
    monkeypatch.setattr(impact_run, "build_mesh", lambda spec: pytest.fail("mesh built"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no DamagedCacheWarning: not a miss
        (old,) = impact_run.impact(
            AISI_1010,
            AISI_201,
            radius=R,
            speed=SPEED,
            sphere="elastic",
            flat_hardening="elastic",
            cache_dir=tmp_path,
        )
    _same(result, old, exact=False)


def test_the_quasi_static_impact_has_the_same_names() -> None:
    k, m, v = 2.0e8, 0.05, 1.0
    dm = v * math.sqrt(m / k)
    d = np.linspace(0.0, 2.0 * dm, 2001)[1:]
    un_d = np.linspace(dm, 0.6 * dm, 500)
    res = one_dof_impact(
        d, k * d, un_d, k * dm * (un_d - 0.6 * dm) / (0.4 * dm), mass=m, speed=v, curve_maximum=dm
    )
    assert res.delta_p == pytest.approx(0.6 * dm, rel=1e-4)
    for old, new in RENAMED_IMPACT_FIELDS.items():
        with pytest.warns(DeprecationWarning, match=rf"QuasiStaticImpact field '{old}'"):
            assert np.array_equal(getattr(res, old), getattr(res, new))


def _as_version_1(record: dict[str, Any]) -> dict[str, Any]:
    """A version-2 record as ``write_impact_tables`` wrote it before 0.3."""
    new_to_old = {new: old for old, new in RENAMED_IMPACT_FIELDS.items()}
    out = json.loads(json.dumps(record))
    out["version"] = 1
    for row in out["rows"]:
        for key in ("dynamic", "quasi_static"):
            if row[key] is not None:
                row[key] = {new_to_old.get(k, k): v for k, v in row[key].items()}
                row[key].pop("flat_dent_depth", None)
                row[key].pop("sphere_flattening", None)
    return out


def test_impact_tables_read_in_the_new_names(tmp_path: Path) -> None:
    """The shipped tables (version 1, the names before 0.3) and a version-2 table read alike;
    a table's old keys still read, with a DeprecationWarning; version 2 wins over 1."""
    name = "paper-ball-on-aisi1010"
    shipped = load_impact_table(name)
    assert shipped["version"] == 1
    dyn = shipped["rows"][0]["dynamic"]
    assert dyn["e"] == pytest.approx(0.8411922) and dyn["delta_p"] == pytest.approx(1.033894e-6)
    assert {"delta_max", "duration", "penetration"} <= set(dyn)
    assert not set(RENAMED_IMPACT_FIELDS) & set(dyn)
    with pytest.warns(DeprecationWarning, match="'restitution' is renamed 'e'"):
        assert dyn["restitution"] == dyn["e"]
    v2 = json.loads(json.dumps(shipped))
    v2["version"] = 2
    v2["rows"][0]["dynamic"]["e"] = 0.5
    impact_path(name, tmp_path, 1).write_text(json.dumps(_as_version_1(shipped)))
    assert load_impact_table(name, tmp_path)["rows"] == shipped["rows"]
    impact_path(name, tmp_path, 2).write_text(json.dumps(v2))
    assert load_impact_table(name, tmp_path)["rows"][0]["dynamic"]["e"] == 0.5
    (tmp_path / f"{name}.v2.json").write_text(json.dumps({**v2, "version": 3}))
    with pytest.raises(ValueError, match=r"version 1 or 2"):
        load_impact_table(name, tmp_path)


def test_a_comparison_row_reads_its_old_keys() -> None:
    comp = compare_impacts("elastic-ball-on-aisi1010", laws=())
    row = comp.columns["dynamic FE"][0]
    assert set(row) == {"e", "delta_p", "delta_max", "max_force", "duration"}
    with pytest.warns(DeprecationWarning, match="'contact_duration' is renamed 'duration'"):
        assert row["contact_duration"] == row["duration"]
    with pytest.raises(KeyError):
        row["no-such-key"]
    with pytest.warns(DeprecationWarning, match="'restitution' is renamed 'e'"):
        assert row.get("restitution") == row["e"]  # .get and `in` read the old keys too
    with pytest.warns(DeprecationWarning, match="'max_interference' is renamed 'delta_max'"):
        assert "max_interference" in row
    assert row.get("no-such-key", 7) == 7 and "no-such-key" not in row
