"""``python -m impactlab.verification [OUT_DIR] [--fast]``: write the verification page and its
figures into OUT_DIR (default docs/verification); exit 1 if a check fails."""

from __future__ import annotations

import sys

from impactlab.verification.page import main

args = [a for a in sys.argv[1:] if not a.startswith("--")]
tabs = main(args[0] if args else "docs/verification", fast="--fast" in sys.argv)
sys.exit(0 if all(t.passed for t in tabs) else 1)
