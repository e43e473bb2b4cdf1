"""Reproduce the seed paper's tables and figures into a folder, and read the result.

What it shows:

* ``impactlab.paper.reproduce``: the experimental rows (T and F from the measured dents, the
  paper's Eqs. 12 and 29 corrected), the 18 simulations (3 angles x 3 laws x 2 friction
  models), Tables 2-4 side by side with the published numbers, Figs. 4 and 5, and the report
  (report.md, report.html);
* the programmatic result: ``ReproductionResult.experimental``, ``.tables``, ``.comparison``
  (pandas DataFrames in display units) and ``.files``.

Run (everything is written into ``reproduction/`` under the output folder: the first argument,
else $IMPACTLAB_EXAMPLE_OUT, else a new temporary folder; ``--no-simulate`` runs the analytic
part only)::

    python examples/reproduce_paper.py [OUT_DIR] [--no-simulate]

The same from the shell: ``impactlab reproduce --out OUT_DIR/reproduction``.
Tutorial: docs/tutorials/reproduce.md.
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

from impactlab.paper import reproduce


def output_dir(args: list[str]) -> Path:
    """args[0], else $IMPACTLAB_EXAMPLE_OUT, else a fresh temporary folder."""
    target = args[0] if args else os.environ.get("IMPACTLAB_EXAMPLE_OUT")
    out = Path(target) if target else Path(tempfile.mkdtemp(prefix="impactlab-reproduce-"))
    out.mkdir(parents=True, exist_ok=True)
    return out


def main() -> None:
    if {"-h", "--help"} & set(sys.argv[1:]):  # how to run it: the docstring
        print(__doc__)
        raise SystemExit(0)
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    simulate = "--no-simulate" not in sys.argv[1:]
    out = output_dir(args)

    res = reproduce(out / "reproduction", simulate=simulate)

    exp = res.experimental.set_index("angle [deg]")
    print("experimental rows (the paper's method, I_C = m L^2/12):")
    for angle in (20, 45, 70):
        r = exp.loc[angle]
        pub = r["T published [ms]"]
        versus = (
            f"published {pub:.2f} ms ({r['T rel. diff']:+.1%})" if pub == pub else "not published"
        )
        print(f"  {angle} deg: T = {r['T [ms]']:.3f} ms, {versus}; F = {r['F [N]']:.1f} N")

    t2 = res.tables["table2"]
    t2 = t2[t2["source"] == "Table 2"]  # the rows of the printed table (not the Sec. 5.2 text)
    cols = [c for c in t2.columns if c in ("model", "friction") or c.startswith("e ")]
    print("\nTable 2 (20 deg), e published vs impactlab:")
    print(t2[cols].to_string(index=False))

    n_rows = len(res.simulations) if res.simulations is not None else 0
    print(f"\nsimulations: {n_rows}" + ("" if simulate else " (skipped: --no-simulate)"))
    print(f"files: {', '.join(sorted(p.name for p in res.files.values()))}")
    print(f"report: {res.report_html} ({res.elapsed_s:.1f} s)")


if __name__ == "__main__":
    main()
