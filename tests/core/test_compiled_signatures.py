"""No compiled function is compiled twice for a constant argument its other callers pass as a
value (``impactlab.dynamics.kernels._jit``, "Constant arguments, compiled for once").

numba compiles a function once per signature, and a constant passed by compiled code is a type
of its own (``Literal[int](2)``, ``Literal[bool](False)``): ``f(x, FR_MINDLIN)`` beside
``f(x, fric)`` compiles ``f``, and everything it calls, twice. This test reads the engine's
compiled code (the drivers, the shared kernels and the batch modules), finds every function
compiled on its own (not inlined), and checks each argument position of its calls from compiled
code: where one call passes a value, no other may pass a constant (an upper-case name or a
literal). The rigid batch's literal ``False`` for the history is the one exception: it folds
the history code out of the batch's hot loop.
"""

from __future__ import annotations

import ast
import importlib
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
ENGINE = ROOT / "src" / "impactlab" / "dynamics"
FOLDERS = ("core", "slipcore", "flexcore", "kernels")
MODULES = ("slip_batch.py", "drop_batch.py")
COMPILERS = {"njit", "jit", "njit_no_refcount", "njit_internal", "njit_llvm_inline"}
#: (file, callee, argument position): constants kept on purpose.
ALLOWED = {("core/batch.py", "impact", 12)}


def _decorator_name(dec: ast.expr) -> str:
    d = dec.func if isinstance(dec, ast.Call) else dec
    return d.id if isinstance(d, ast.Name) else getattr(d, "attr", "")


def _inlined(dec: ast.expr) -> bool:
    return isinstance(dec, ast.Call) and any(
        k.arg == "inline" and isinstance(k.value, ast.Constant) and k.value.value == "always"
        for k in dec.keywords
    )


def _files() -> list[Path]:
    files = [p for f in FOLDERS for p in sorted((ENGINE / f).glob("*.py"))]
    return files + [ENGINE / m for m in MODULES if (ENGINE / m).exists()]


def _compiled(tree: ast.AST) -> dict[str, bool]:
    """Compiled functions of a module: name -> compiled on its own (not inlined)."""
    out = {}
    for n in ast.walk(tree):
        if isinstance(n, ast.FunctionDef):
            decs = [d for d in n.decorator_list if _decorator_name(d) in COMPILERS]
            if decs:
                out[n.name] = not any(_inlined(d) for d in decs)
    return out


def _literal(value: object) -> bool:
    """numba types an int or a bool constant as a literal (a float is always float64)."""
    return isinstance(value, bool | int)


def _constant(arg: ast.expr, namespace: dict[str, object]) -> bool:
    """An argument numba types as a literal: an int or bool constant, or a module-level name
    bound to one."""
    if isinstance(arg, ast.Constant):
        return _literal(arg.value)
    if isinstance(arg, ast.UnaryOp) and isinstance(arg.operand, ast.Constant):
        return _literal(arg.operand.value)
    return isinstance(arg, ast.Name) and arg.id.isupper() and _literal(namespace.get(arg.id))


def _namespace(path: Path) -> dict[str, object]:
    rel = path.relative_to(ENGINE.parent).with_suffix("")
    return vars(importlib.import_module("impactlab." + ".".join(rel.parts)))


def _calls() -> tuple[dict[str, bool], list[tuple[str, str, int, bool, int]]]:
    own: dict[str, bool] = {}
    calls = []
    trees = {p: ast.parse(p.read_text()) for p in _files()}
    for tree in trees.values():
        own.update(_compiled(tree))
    for path, tree in trees.items():
        rel = path.relative_to(ENGINE).as_posix()
        namespace = _namespace(path)
        for fn in ast.walk(tree):
            if not (
                isinstance(fn, ast.FunctionDef)
                and any(_decorator_name(d) in COMPILERS for d in fn.decorator_list)
            ):
                continue
            for node in ast.walk(fn):
                if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
                    for i, a in enumerate(node.args):
                        calls.append((rel, node.func.id, i, _constant(a, namespace), node.lineno))
    return own, calls


def test_no_constant_argument_compiles_a_function_twice() -> None:
    own, calls = _calls()
    by_position: dict[tuple[str, int], list[tuple[str, bool, int]]] = defaultdict(list)
    for rel, callee, i, const, line in calls:
        if own.get(callee) and (rel, callee, i) not in ALLOWED:
            by_position[(callee, i)].append((rel, const, line))
    bad = [
        f"{rel}:{line}: {callee}(... argument {i} ...) is a constant, elsewhere a value"
        for (callee, i), uses in by_position.items()
        if any(c for _, c, _ in uses) and not all(c for _, c, _ in uses)
        for rel, c, line in uses
        if c
    ]
    assert not bad, "\n".join(bad)


def test_the_check_sees_the_engine() -> None:
    own, calls = _calls()
    # the rigid core, its batch and the shared kernels are all in view
    assert own["impact"] and own["impact_slip"] and own["slip_case"]
    assert not own["dense"]  # inlined: its copies cost nothing extra
    assert any(c[1] == "impact" and c[0] == "core/batch.py" for c in calls)
    assert ("core/batch.py", "impact", 12) in {(r, f, i) for r, f, i, c, _ in calls if c}
