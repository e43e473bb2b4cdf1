"""Compiled functions without wrappers (``njit_internal``, ``njit_leaf``, ``njit_llvm_inline``,
or ``no_cpython_wrapper=True``) are never called from Python.

numba compiles such a function without its Python- and C-callable wrappers (less compile
time), and a call from Python then crashes the interpreter instead of raising an error. Only
compiled code may call them: this test looks for every use of their names in Python code
(outside compiled function bodies and imports) in the package, the tests, the benchmarks and
the tools. It matches by name only, so a Python function of the same name elsewhere also fails
it: such a compiled function keeps its wrappers. Two uses call nothing and pass: reading the
dispatcher's ``py_func``, and pairing it with its signature, ``(f, STEP_SIGNATURE)``, for
``kernels.address_call.compiled_addresses`` or numba's ``_get_jit_address`` (the functions
called through their addresses, ``flexcore.indirect`` and ``slipcore.indirect``).
Only the files whose text holds a compiled function's decorator ("jit"), one of the names, or
a lookup by string (``BY_STRING``: getattr, globals(), ...) are parsed: an identifier is in its
file's text, and a string constant that is a name only once parsed (adjacent literals, escapes)
is looked up by one of those.
"""

from __future__ import annotations

import ast
import gc
import re
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
FOLDERS = ("src", "tests", "benchmarks", "tools")
COMPILERS = {"njit", "jit", "njit_no_refcount", "njit_internal", "njit_leaf", "njit_llvm_inline"}


def _decorator_name(dec: ast.expr) -> str:
    d = dec.func if isinstance(dec, ast.Call) else dec
    return d.id if isinstance(d, ast.Name) else getattr(d, "attr", "")


def _without_wrapper(dec: ast.expr) -> bool:
    if _decorator_name(dec) in ("njit_internal", "njit_leaf", "njit_llvm_inline"):
        return True
    return isinstance(dec, ast.Call) and any(
        k.arg == "no_cpython_wrapper" and isinstance(k.value, ast.Constant) and k.value.value
        for k in dec.keywords
    )


def _is_compiled(node: ast.AST) -> bool:
    return isinstance(node, ast.FunctionDef) and any(
        _decorator_name(d) in COMPILERS for d in node.decorator_list
    )


def _compiled_and_names(tree: ast.AST) -> tuple[list[ast.FunctionDef], list[tuple[str, ast.expr]]]:
    """One walk of ``tree``: its compiled functions, and every name it uses with its node (a
    ``Name``, an ``Attribute``'s attribute, a string constant). Imports hold none of these."""
    compiled: list[ast.FunctionDef] = []
    names: list[tuple[str, ast.expr]] = []
    for n in ast.walk(tree):
        if isinstance(n, ast.Name):
            names.append((n.id, n))
        elif isinstance(n, ast.Attribute):
            names.append((n.attr, n))
        elif isinstance(n, ast.Constant) and isinstance(n.value, str):
            names.append((n.value, n))
        elif isinstance(n, ast.FunctionDef) and _is_compiled(n):
            compiled.append(n)
    return compiled, names


def _no_call(tree: ast.AST) -> set[int]:
    """The nodes that name a compiled function without calling it from Python: ``f.py_func``,
    the first argument of ``_get_jit_address(f, signature)`` and the function of a pair
    ``(f, NAME_SIGNATURE)``."""
    named: list[ast.AST] = []
    for n in ast.walk(tree):
        if isinstance(n, ast.Attribute) and n.attr == "py_func":
            named.append(n.value)
        elif isinstance(n, ast.Call) and _decorator_name(n) == "_get_jit_address" and n.args:
            named.append(n.args[0])
        elif (
            isinstance(n, ast.Tuple)
            and len(n.elts) == 2
            and isinstance(n.elts[1], ast.Name)
            and n.elts[1].id.endswith("SIGNATURE")
        ):
            named.append(n.elts[0])
    return {id(m) for n in named for m in ast.walk(n)}


@contextmanager
def _without_gc() -> Iterator[None]:
    """The cyclic garbage collector paused: the million nodes of the parsed trees, none of them
    garbage, made it run over and over (two thirds of the parsing time)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


#: What looks a name up from a string: a file with one of these is parsed whole, so that a
#: string constant that is a name only once parsed (adjacent literals, escapes) is seen too.
BY_STRING = re.compile(r"getattr|globals\(|vars\(|__dict__|attrgetter|import_module|__all__")


def _sources() -> dict[Path, str]:
    files = [p for folder in FOLDERS for p in (ROOT / folder).rglob("*.py")]
    return {p: p.read_text() for p in files}


def test_functions_without_wrapper_are_called_only_from_compiled_code() -> None:
    with _without_gc():
        uses = _uses_from_python()
    assert not uses, "\n".join(uses)


def _uses_from_python() -> list[str]:
    """Every use of a compiled function without wrappers from Python code, as text."""
    sources = _sources()
    # every compiler in COMPILERS has "jit" in its name: the other files define none
    trees = {path: ast.parse(text) for path, text in sources.items() if "jit" in text}
    scanned = {path: _compiled_and_names(tree) for path, tree in trees.items()}
    internal: dict[str, str] = {}
    for path, (fns, _) in scanned.items():
        for fn in fns:
            if any(_without_wrapper(d) for d in fn.decorator_list):
                internal[fn.name] = path.relative_to(ROOT).as_posix()
    assert len(internal) > 40  # the engine's internal functions are found
    named = re.compile(r"\b(?:" + "|".join(map(re.escape, internal)) + r")\b")
    for path, text in sources.items():  # the files that may name one of them
        if path not in trees and (named.search(text) or BY_STRING.search(text)):
            trees[path] = ast.parse(text)
            scanned[path] = _compiled_and_names(trees[path])
    uses: list[str] = []
    for path, (fns, names) in scanned.items():
        found = [(name, node) for name, node in names if name in internal]
        if not found:  # the file names none of them
            continue
        inside = {id(n) for fn in fns for n in ast.walk(fn)} | _no_call(trees[path])
        for name, node in found:
            if id(node) not in inside:
                where = f"{path.relative_to(ROOT).as_posix()}:{node.lineno}"
                uses.append(f"{name} ({internal[name]}) used from Python at {where}")
    return uses
