"""Where the first compile of one engine part goes: CPU seconds per compiled function.

    .venv/bin/python benchmarks/profile_compile.py flexible [--cache DIR] [--top 40] [--json OUT]

Fills an empty cache folder (``--cache``, a temporary one by default) with the parts the
measured one builds on, each in its own process (``rigid`` for ``partial_slip`` and
``flexible``), then runs the measured part in a fresh process with a listener on numba's
``numba:compile`` and ``numba:run_pass`` events (``numba.core.event``) and prints:

- per compiled function, its exclusive CPU seconds (the time of its compile less that of the
  functions compiled inside it) and how many signatures it was compiled for;
- per compiler pass, its exclusive CPU seconds summed over the functions (type inference,
  lowering, the LLVM optimisation in ``NativeLowering``, ...);
- every dispatcher of the package compiled for more than one type signature;
- the CPU seconds of Python's cyclic garbage collector and its number of collections
  (``gc.callbacks``; ``impactlab._compile_gc`` pauses it while numba compiles);
- with ``--inlined``, per function inlined by numba (``inline="always"``), how many times its
  body was instantiated and its IR statements in all (numba translates, types and lowers an
  inlined body again at every call site; ``numba.core.inline_closurecall.InlineWorker``);

and writes, with ``--json``, also the 60 largest (function, compiler pass) times.

Only the increment over the parts already in the cache is compiled, so the figures are those
of the measured part alone. CPU seconds of this process (``time.process_time``).
"""

from __future__ import annotations

import argparse
import gc
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path
from typing import Any

PY = "import math, impactlab as il\n"
RIGID = PY + ("il.simulate(il.Rod.paper(), mu=0.2, angle=math.radians(20), velocity=(0.0, -1.41))")
PARTS: dict[str, str] = {
    "rigid": RIGID,
    "partial_slip": PY
    + (
        "il.simulate(il.Rod.paper(), friction='partial_slip', mu=0.2, "
        "angle=math.radians(20), velocity=(0.0, -1.41))"
    ),
    "flexible": PY
    + (
        "il.simulate(il.FlexibleRod.paper(), mu=0.2, angle=math.radians(20), velocity=(0.0, -1.41))"
    ),
}
#: The parts each measured part builds on (compiled into the cache first).
BEFORE: dict[str, tuple[str, ...]] = {
    "rigid": (),
    "partial_slip": ("rigid",),
    "flexible": ("rigid",),
}


def _fill(part: str, cache: Path) -> None:
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), IMPACTLAB_QUIET_COMPILE="1")
    subprocess.run([sys.executable, "-c", PARTS[part]], env=env, check=True)


def _copy_base(base: Path, cache: Path) -> None:
    """Copy the newest ``engine-*`` folder of ``base`` to this engine's folder in ``cache``."""
    from impactlab._compiled_cache import ENGINE_PREFIX, engine_source_hash

    folders = sorted(base.rglob(ENGINE_PREFIX + "*"), key=lambda p: p.stat().st_mtime)
    if not folders:
        raise SystemExit(f"--base {base}: no {ENGINE_PREFIX}* folder in it")
    shutil.copytree(folders[-1], cache / f"{ENGINE_PREFIX}{engine_source_hash()}")


class _GCTimer:
    """A ``gc.callbacks`` entry: CPU seconds and number of the collector's passes."""

    def __init__(self) -> None:
        self.start = 0.0
        self.seconds = 0.0
        self.count = 0

    def __call__(self, phase: str, info: dict[str, int]) -> None:
        if phase == "start":
            self.start = time.process_time()
        else:
            self.seconds += time.process_time() - self.start
            self.count += 1


def _count_inlined() -> dict[str, list[int]]:
    """Count numba's inlined bodies: name -> [instantiations, IR statements of its own]."""
    from numba.core import inline_closurecall as icc

    counts: dict[str, list[int]] = defaultdict(lambda: [0, 0])
    nested: list[list[int]] = []  # the statements of the bodies inlined into the current one
    orig = icc.InlineWorker.run_untyped_passes

    def run_untyped_passes(self: Any, func: Any, enable_ssa: bool = False) -> Any:
        nested.append([0])
        callee_ir = orig(self, func, enable_ssa)
        inner = nested.pop()[0]
        size = sum(len(b.body) for b in callee_ir.blocks.values())
        row = counts[f"{func.__module__}.{func.__qualname__}"]
        row[0] += 1
        row[1] += size - inner
        if nested:
            nested[-1][0] += size
        return callee_ir

    icc.InlineWorker.run_untyped_passes = run_untyped_passes  # type: ignore[method-assign]
    return counts


def _measure(part: str, inlined: bool = False) -> dict[str, object]:
    """Run ``part`` in this process with the listeners; the per-function and per-pass times."""
    from numba.core import event

    inline_counts = _count_inlined() if inlined else {}

    stack: list[list[object]] = []  # [function, pass or "", start, child time]
    per_fn: dict[str, float] = defaultdict(float)
    per_pass: dict[str, float] = defaultdict(float)
    per_fn_pass: dict[str, float] = defaultdict(float)
    calls: dict[str, int] = defaultdict(int)

    class _Listener(event.Listener):
        def __init__(self, kind: str) -> None:
            self.kind = kind

        def on_start(self, ev: event.Event) -> None:
            if self.kind == "numba:compile":
                fn = ev.data["dispatcher"].py_func
                key, step = f"{fn.__module__}.{fn.__qualname__}", ""
                calls[key] += 1
            else:
                key = str(stack[-1][0]) if stack else "?"
                step = str(ev.data.get("name", "?")).split(" [")[0]
            stack.append([key, step, time.process_time(), 0.0])

        def on_end(self, ev: event.Event) -> None:
            key, step, t0, child = stack.pop()
            total = time.process_time() - float(t0)  # type: ignore[arg-type]
            own = total - float(child)  # type: ignore[arg-type]
            if stack:
                stack[-1][3] = float(stack[-1][3]) + total  # type: ignore[arg-type]
            per_fn[str(key)] += own
            if step:
                per_pass[str(step)] += own
                per_fn_pass[f"{key} | {step}"] += own

    from numba.core import codegen

    llvm: dict[str, float] = defaultdict(float)

    def _timed(cls: type, name: str, label: str) -> None:
        orig = getattr(cls, name)

        def wrapper(self: object, *a: object, **k: object) -> object:
            t = time.process_time()
            try:
                return orig(self, *a, **k)
            finally:
                dt = time.process_time() - t
                llvm[label] += dt
                if stack:  # not the compile's own time: counted apart
                    stack[-1][3] = float(stack[-1][3]) + dt  # type: ignore[arg-type]
                    per_llvm[str(stack[-1][0])] += dt

        setattr(cls, name, wrapper)

    per_llvm: dict[str, float] = defaultdict(float)
    _timed(codegen.CPUCodeLibrary, "_optimize_functions", "LLVM: optimise each function")
    _timed(codegen.CPUCodeLibrary, "_optimize_final_module", "LLVM: optimise with the callees")
    _timed(codegen.JITCodeLibrary, "_finalize_specific", "LLVM: machine code")
    event.register("numba:compile", _Listener("numba:compile"))
    event.register("numba:run_pass", _Listener("numba:run_pass"))
    collector = _GCTimer()
    gc.callbacks.append(collector)
    t0 = time.process_time()
    exec(PARTS[part], {})
    total = time.process_time() - t0
    gc.callbacks.remove(collector)
    multi = {}
    for name, mod in list(sys.modules.items()):
        if not name.startswith("impactlab"):
            continue
        for obj in list(vars(mod).values()):
            sigs = getattr(obj, "signatures", None)
            if sigs is not None and hasattr(obj, "py_func") and len(sigs) > 1:
                multi[f"{obj.py_func.__module__}.{obj.py_func.__qualname__}"] = [
                    str(s) for s in sigs
                ]
    return {
        "part": part,
        "cpu_s": total,
        "compiled_cpu_s": sum(per_fn.values()) + sum(llvm.values()),
        "functions": dict(sorted(per_fn.items(), key=lambda kv: -kv[1])),
        "compiles": dict(calls),
        "passes": dict(sorted(per_pass.items(), key=lambda kv: -kv[1])),
        "function_passes": dict(sorted(per_fn_pass.items(), key=lambda kv: -kv[1])[:60]),
        "llvm": dict(llvm),
        "llvm_per_function": dict(per_llvm),
        "multi_signature": multi,
        "gc_s": collector.seconds,
        "gc_collections": collector.count,
        "inlined": dict(sorted(inline_counts.items(), key=lambda kv: -kv[1][1])),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("part", choices=sorted(PARTS))
    ap.add_argument("--cache", type=Path, help="an empty folder (default: a temporary one)")
    ap.add_argument(
        "--base",
        type=Path,
        help="a cache folder that holds the parts before (its newest engine-* folder is copied "
        "in, instead of compiling them; valid while their source files are unchanged)",
    )
    ap.add_argument("--top", type=int, default=40)
    ap.add_argument("--inlined", action="store_true", help="count numba's inlined bodies")
    ap.add_argument("--json", type=Path)
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        print(json.dumps(_measure(args.part, args.inlined)))
        return
    with tempfile.TemporaryDirectory() as tmp:
        cache = args.cache or Path(tmp) / "cache"
        if args.base:
            _copy_base(args.base, cache)
        else:
            for before in BEFORE[args.part]:
                _fill(before, cache)
        env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), IMPACTLAB_QUIET_COMPILE="1")
        out = subprocess.run(
            [sys.executable, __file__, args.part, "--child"] + ["--inlined"] * args.inlined,
            env=env,
            check=True,
            capture_output=True,
            text=True,
        ).stdout
    res = json.loads(out.splitlines()[-1])
    print(f"{args.part}: {res['cpu_s']:.1f} s CPU, {res['compiled_cpu_s']:.1f} s in numba:compile")
    print(f"{'numba s':>8} {'LLVM s':>7} {'n':>3}  function (exclusive CPU seconds)")
    llvm_fn = res["llvm_per_function"]
    rows = sorted(res["functions"], key=lambda k: -(res["functions"][k] + llvm_fn.get(k, 0.0)))
    for name in rows[: args.top]:
        s, ll = res["functions"][name], llvm_fn.get(name, 0.0)
        print(f"{s:8.2f} {ll:7.2f} {res['compiles'][name]:3d}  {name}")
    for name, s in res["llvm"].items():
        print(f"{s:11.2f}  {name}")
    print(f"{res['gc_s']:11.2f}  Python gc ({res['gc_collections']} collections, within the above)")
    print(f"{'exclusive s':>11}  pass")
    for name, s in list(res["passes"].items())[:15]:
        print(f"{s:11.2f}  {name}")
    if res["inlined"]:
        print(f"{'bodies':>6} {'stmts':>6}  inlined by numba (instantiations, own IR statements)")
        for name, (n, size) in list(res["inlined"].items())[: args.top]:
            print(f"{n:6d} {size:6d}  {name}")
    for name, sigs in res["multi_signature"].items():
        print(f"{len(sigs)} signatures: {name}")
        for s in sigs:
            print(f"    {s[:300]}")
    if args.json:
        args.json.write_text(json.dumps(res, indent=2) + "\n")


if __name__ == "__main__":
    main()
