"""What every batch of results says about each case: computed or not, ok, flagged, and why.

One meaning for ``ok`` across the result family: a case is ok when it was computed (status 0)
and carries no flag but the advisory ones (``impactlab.flags.ADVISORY_FLAGS``), as
``ImpactResult.ok`` and ``DropResult.ok`` say for one result. ``computed`` is the status mask
alone. ``BatchResult`` (impacts) and ``DropBatchResult`` (flexible-rod drops) share it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from impactlab.dynamics.kernels.status import STATUS_MESSAGES
from impactlab.flags import ADVISORY_FLAGS


def flag_column(values: np.ndarray) -> np.ndarray:
    """A float ``flags`` column as the ``ResultFlag`` bitmask of each case (int64; 0 where the
    column is NaN, a failed case, whose status says why)."""
    f = np.asarray(values, dtype=np.float64)
    return np.where(np.isfinite(f), f, 0.0).astype(np.int64)


#: The outputs that hold integer codes or counts (held as floats in a batch's ``out``).
INTEGER_FIELDS = ("regime", "flags", "n_steps", "n_contacts", "next_end", "n_jumps", "n_dents")


def integer_series(values: np.ndarray, computed: np.ndarray) -> Any:
    """An integer-coded column (flags, regime, counts) as a pandas nullable ``Int64`` Series:
    integers where the case was computed, ``<NA>`` where it failed (its status says why), as
    pandas marks a missing integer; never floats."""
    import pandas as pd  # heavy, needed only here

    f = np.asarray(values, dtype=np.float64)
    keep = np.asarray(computed, dtype=bool) & np.isfinite(f)
    ints = np.where(keep, f, 0.0).astype(np.int64)
    return pd.Series(pd.arrays.IntegerArray(ints, ~keep))


class BatchStatus:
    """``computed``, ``ok``, ``flagged`` and ``messages`` from the ``status`` (int, 0: computed)
    and ``flags`` (``ResultFlag`` bits) of each case, which the class provides."""

    status: np.ndarray
    if TYPE_CHECKING:  # each batch class has its own (a property, or a dataclass field)

        @property
        def flags(self) -> np.ndarray: ...

    @property
    def computed(self) -> np.ndarray:
        """Boolean mask of the cases that ran to a result (status 0; ``messages`` says why
        not)."""
        return np.asarray(self.status) == 0

    @property
    def ok(self) -> np.ndarray:
        """Boolean mask of the cases whose result may be read as plain success: computed, and
        no flag but the advisory ones (``ImpactResult.ok``: an energy gain or a gravity-dominated
        contact is not ok; a law beyond its verified range is ok and flagged)."""
        return self.computed & ((self.flags & ~ADVISORY_FLAGS) == 0)

    @property
    def flagged(self) -> np.ndarray:
        """Boolean mask of the computed cases that carry a flag (``impactlab.flags``)."""
        return self.computed & (self.flags != 0)

    @property
    def messages(self) -> list[str]:
        """The status message of each case (``kernels.status.STATUS_MESSAGES``)."""
        return [STATUS_MESSAGES.get(int(s), f"status {int(s)}") for s in self.status]
