#!/usr/bin/env python3
"""Digest of impactlab's numerical outputs, to prove a refactoring changes no result bit.

    python tools/fingerprint.py OUT.json          # write the digests
    python tools/fingerprint.py OUT.json --compare BEFORE.json

It digests (SHA-256 of the raw float64 bytes, so any changed bit shows):

- ``impactlab reproduce``: every CSV/JSON table it writes (figures and the HTML report are
  rendered text and images; their numbers come from those tables);
- three seeded sweep stores (a grid, a Monte Carlo sample, and the laws study), every variable;
- ``simulate`` on a seeded random sample over every law x friction model x body, with histories
  and dents;
- the analytic inversion of the paper's three cases;
- the partial-slip engine (``friction="partial_slip"``, rod and sphere, with histories) and the
  flexible rod's drop (every friction model, with histories) on seeded random samples.

Run it on the commit before and after the change; ``--compare`` lists every digest that differs
and, where both runs saved the numbers (``OUT.npz`` next to ``OUT.json``), the largest relative
change of each (the simulate sample, the sweeps, the dents and the inversion).
Uses the public CLI and a small set of public functions whose names are looked up at run time,
so it runs unchanged across a restructuring.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

#: The numbers behind the digests (key -> float array), saved next to OUT for ``--compare``.
VALUES: dict[str, np.ndarray] = {}


def _digest(a: object, key: str = "") -> str:
    arr = np.ascontiguousarray(np.asarray(a))
    if key and arr.dtype.kind in "fiu":
        VALUES[key] = arr.astype(np.float64)
    if arr.dtype.kind in "fc":
        arr = arr.astype(np.float64 if arr.dtype.kind == "f" else np.complex128)
    h = hashlib.sha256(str(arr.dtype).encode() + str(arr.shape).encode())
    if arr.dtype.kind == "O" or arr.dtype.kind in "US":
        h.update(repr(arr.tolist()).encode())
    else:
        h.update(arr.tobytes())
    return h.hexdigest()[:20]


def _cli(*args: str) -> None:
    exe = Path(sys.executable).with_name("impactlab")
    subprocess.run([str(exe), *args], check=True, stdout=subprocess.DEVNULL)


def reproduce_digests(tmp: Path) -> dict[str, str]:
    out = tmp / "reproduction"
    _cli("reproduce", "--out", str(out))
    d: dict[str, str] = {}
    for f in sorted(out.rglob("*")):
        if f.suffix in {".csv", ".json"} and not f.name.startswith(".impactlab"):
            text = f.read_text()
            d[f"reproduce/{f.relative_to(out)}"] = hashlib.sha256(text.encode()).hexdigest()[:20]
    return d


STUDIES = {
    "grid": """
[study]
name = "fp-grid"
chunk_size = 500
[fixed]
law = "ghaednia"
friction = "coulomb"
[grid]
angle = { start = "5 deg", stop = "85 deg", num = 20 }
vy = { start = -4.0, stop = -0.5, num = 10 }
mu = [0.0, 0.1, 0.3, 0.6]
""",
    "sample": """
[study]
name = "fp-sample"
chunk_size = 256
[fixed]
law = "brake"
friction = "mindlin"
angle = "30 deg"
flat_E = "200 GPa"
flat_nu = 0.3
flat_brinell_hardness = 105
flat_meyer_index = 2.2
[sample]
size = 1000
seed = 7
vy = { dist = "uniform", low = -3.0, high = -0.5 }
mu = { dist = "uniform", low = 0.0, high = 0.5 }
flat_yield_strength = { dist = "uniform", low = "250 MPa", high = "360 MPa" }
""",
}


def sweep_digests(tmp: Path) -> dict[str, str]:
    import xarray as xr

    repo = Path(__file__).resolve().parents[1]
    studies = dict(STUDIES)
    studies["laws"] = (repo / "examples" / "study-laws.toml").read_text()
    d: dict[str, str] = {}
    for key, text in studies.items():
        toml = tmp / f"{key}.toml"
        toml.write_text(text)
        store = tmp / f"{key}.zarr"
        _cli("sweep", "run", str(toml), "--out", str(store))
        ds = xr.open_zarr(store)
        for name in sorted({*ds.data_vars, *ds.coords}):
            d[f"sweep/{key}/{name}"] = _digest(ds[name].values, f"sweep/{key}/{name}")
    return d


def simulate_digests() -> dict[str, str]:
    import impactlab as il

    rng = np.random.default_rng(20261123)
    d: dict[str, str] = {}
    laws = (
        list(il.law_names())
        if hasattr(il, "law_names")
        else ["hertz", "ghaednia", "jackson-green", "kogut-komvopoulos", "brake", "thornton"]
    )
    frictions = ["impulse_ratio", "coulomb", "mindlin"]
    bodies = {"rod": il.Rod.paper(), "sphere": il.Sphere(radius=0.01)}
    for law in laws:
        for fr in frictions:
            for bname, body in bodies.items():
                for k in range(4):
                    ang = float(rng.uniform(math.radians(5), math.radians(85)))
                    vy = float(rng.uniform(-4.0, -0.3))
                    vx = float(rng.uniform(-0.5, 0.5))
                    mu = float(rng.uniform(0.0, 0.6))
                    kw = {"angle": ang} if bname == "rod" else {}
                    try:
                        r = il.simulate(
                            body, law=law, friction=fr, mu=mu, velocity=(vx, vy), history=True, **kw
                        )
                    except Exception as exc:  # the message is part of the digest
                        d[f"simulate/{law}/{fr}/{bname}/{k}"] = "error:" + str(exc)[:80]
                        continue
                    vals = [getattr(r, f) for f in ("e", "delta_max", "delta_p", "duration")]
                    # the raw columns (the DataFrame may hold categorical phase/stick columns)
                    h = getattr(r.history, "data", None)
                    h = r.history.to_dataframe().to_numpy(dtype=float) if h is None else h
                    key = f"simulate/{law}/{fr}/{bname}/{k}"
                    d[key] = _digest(np.array(vals, dtype=float), key)
                    d[key + "/history"] = _digest(np.asarray(h, dtype=float))
                    if k == 0 and bname == "rod":
                        dent = r.dent()
                        arrs = [
                            np.asarray(v, dtype=float)
                            for v in vars(dent).values()
                            if isinstance(v, np.ndarray)
                        ]
                        dent_all = np.concatenate([a.ravel() for a in arrs])
                        d[key + "/dent"] = _digest(dent_all, key + "/dent")
    return d


def _numbers(r: object) -> np.ndarray:
    """The public float fields of a result (an ImpactResult or a DropResult), in name order (a
    drop's renamed totals in the order of their names before 0.3, so digests compare across
    the renaming: ``impactlab.schema.RENAMED_DROP_FIELDS``)."""
    from impactlab.schema import RENAMED_DROP_FIELDS

    before = {new: old for old, new in RENAMED_DROP_FIELDS.items()}
    names = sorted(
        (
            k
            for k, v in vars(r).items()
            if isinstance(v, float | int) and k != "status" and not k.startswith("_")
        ),
        key=lambda k: before.get(k, k),
    )
    return np.array([float(getattr(r, k)) for k in names], dtype=float)


def _history(r: object) -> np.ndarray | None:
    h = getattr(r, "history", None)
    if h is None:
        return None
    data = getattr(h, "data", None)
    if data is None and hasattr(h, "to_dataframe"):
        data = h.to_dataframe().to_numpy(dtype=float)
    return None if data is None else np.asarray(data, dtype=float)


def engines_digests() -> dict[str, str]:
    """The partial-slip impact and the flexible rod's drop on seeded random samples."""
    import impactlab as il

    rng = np.random.default_rng(20261128)
    d: dict[str, str] = {}
    cases: list[tuple[str, object, str, dict[str, object]]] = []
    for law in ("ghaednia", "hertz", "thornton"):
        for bname, body in {"rod": il.Rod.paper(), "sphere": il.Sphere(radius=0.01)}.items():
            for k in range(3):
                kw: dict[str, object] = {"law": law, "history": True}
                if bname == "rod":
                    kw["angle"] = float(rng.uniform(math.radians(5), math.radians(85)))
                kw["velocity"] = (float(rng.uniform(-1.0, 1.0)), float(rng.uniform(-3.0, -0.3)))
                kw["mu"] = float(rng.uniform(0.05, 0.6))
                cases.append((f"partial_slip/{law}/{bname}/{k}", body, "partial_slip", kw))
    flex = il.FlexibleRod.paper()
    for fr in ("impulse_ratio", "coulomb", "mindlin", "partial_slip"):
        for k in range(2):
            kw = {
                "angle": float(rng.uniform(math.radians(10), math.radians(70))),
                "velocity": (0.0, float(rng.uniform(-2.0, -0.5))),
                "mu": float(rng.uniform(0.05, 0.4)),
            }
            cases.append((f"flexible/{fr}/{k}", flex, fr, kw))
    for key, body, fr, kw in cases:
        try:
            r = il.simulate(body, friction=fr, **kw)
        except Exception as exc:  # the message is part of the digest
            d[key] = "error:" + str(exc)[:80]
            continue
        d[key] = _digest(_numbers(r), key)
        h = _history(r)
        if h is not None:
            d[key + "/history"] = _digest(h, key + "/history")
    return d


def invert_digests() -> dict[str, str]:
    import impactlab as il

    d: dict[str, str] = {}
    for case in ("paper-20", "paper-45", "paper-70"):
        exe = Path(sys.executable).with_name("impactlab")
        out = subprocess.run(
            [str(exe), "invert", "--case", case, "--json"],
            check=True,
            capture_output=True,
            text=True,
        ).stdout
        d[f"invert/{case}"] = hashlib.sha256(out.encode()).hexdigest()[:20]
    res = il.invert(
        angle=math.radians(20), v_i=-1.41, e=0.50, mu=0.20, delta_p=22e-6, sliding_length=1400e-6
    )
    d["invert/api"] = _digest(np.array([res.duration, res.mean_force], dtype=float), "invert/api")
    return d


def _values_path(out: str) -> Path:
    return Path(out).with_suffix(".npz")


def _relative_changes(before_json: str, keys: list[str]) -> dict[str, float]:
    """Largest |after - before| / max(|before|, 1e-300) over the finite values of each of
    ``keys`` whose values both runs saved with the same shape (NaN in the same places)."""
    path = _values_path(before_json)
    if not path.is_file():
        return {}
    old = np.load(path)
    out = {}
    for k in keys:
        if k not in old or k not in VALUES or old[k].shape != VALUES[k].shape:
            continue
        a, b = VALUES[k], old[k]
        ok = np.isfinite(a) & np.isfinite(b)
        if not ok.any():
            continue
        out[k] = float(np.max(np.abs(a[ok] - b[ok]) / np.maximum(np.abs(b[ok]), 1e-300)))
    return out


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--compare")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        d = {}
        d.update(simulate_digests())
        d.update(engines_digests())
        d.update(invert_digests())
        d.update(sweep_digests(tmp))
        d.update(reproduce_digests(tmp))
    Path(args.out).write_text(json.dumps(d, indent=1, sort_keys=True) + "\n")
    np.savez_compressed(_values_path(args.out), **VALUES)
    print(f"{len(d)} digests -> {args.out} (values: {_values_path(args.out)})")
    if args.compare:
        before = json.loads(Path(args.compare).read_text())
        diff = sorted(k for k in before.keys() | d.keys() if before.get(k) != d.get(k))
        rel = _relative_changes(args.compare, diff)
        for k in diff:
            r = f" (largest relative change {rel[k]:.2e})" if k in rel else ""
            print(f"DIFFERS {k}: {before.get(k)} -> {d.get(k)}{r}")
        print(f"{len(before)} before, {len(d)} after, {len(diff)} differ")
        if rel:
            k = max(rel, key=rel.__getitem__)
            print(f"largest relative change of a number: {rel[k]:.2e} ({k})")
        return 1 if diff else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
