"""The package's one matplotlib policy: every module that plots calls :func:`pyplot`.

The non-interactive "Agg" backend is selected only when the user chose no backend: the
``MPLBACKEND`` environment variable is unset, no backend was set through ``matplotlib.use`` or a
``matplotlibrc``, and ``matplotlib.pyplot`` has not been imported yet. A user's choice is never
overridden.
"""

from __future__ import annotations

import os
import sys
from types import ModuleType


def _backend_chosen(matplotlib: ModuleType) -> bool:
    """True when a backend was already chosen (environment, ``matplotlib.use``, rc file or an
    imported pyplot)."""
    if os.environ.get("MPLBACKEND"):
        return True
    if "matplotlib.pyplot" in sys.modules:
        return True
    get = getattr(matplotlib.rcParams, "_get_backend_or_none", None)
    if get is None:  # pragma: no cover - matplotlib < 3.6 has no auto-backend sentinel
        return True
    return get() is not None


def pyplot() -> ModuleType:
    """``matplotlib.pyplot``, with the "Agg" backend selected when none was chosen."""
    # matplotlib is imported here, not at module top: it is a heavy import that only plotting
    # calls need, and importing impactlab must not pick a backend.
    import matplotlib

    if not _backend_chosen(matplotlib):
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt
