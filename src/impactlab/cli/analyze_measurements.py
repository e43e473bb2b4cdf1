"""``impactlab analyze --measurements FILE.csv``: the analysed drop appended to a measurements
file for ``impactlab calibrate`` (``calibrate.experiment_rows.append_experiment``), checked
before the analysis runs (a file that is not CSV, a label it has already or that it would not
read back as written)."""

from __future__ import annotations

import os
import warnings
from pathlib import Path
from typing import TYPE_CHECKING

from impactlab.cli._common import UserError

if TYPE_CHECKING:
    from impactlab.experiment import ExperimentResult

__all__ = ["append_drop", "check_measurements"]


def check_measurements(path: Path, label: str) -> None:
    """Before the analysis: UserError for a --measurements file that is not CSV, in a folder
    that does not exist, that cannot be read as measurements or that has the drop ``label``,
    and for a ``label`` the file would not read back as written
    (``measurement_append.check_label``: empty, a line break, a leading '#', end spaces)."""
    from impactlab.calibrate.measurement_append import check_label
    from impactlab.calibrate.measurements import read_measurements

    try:
        check_label(label, "--label (default: the marker file's name)")
    except ValueError as exc:
        raise UserError(f"--measurements: {exc}") from None

    if path.suffix.lower() != ".csv":
        raise UserError(
            f"--measurements {str(path)!r}: a drop is appended to a CSV file (.csv), got "
            f"{path.suffix or 'no extension'!r}"
        )
    if not path.parent.is_dir():
        raise UserError(
            f"--measurements {str(path)!r}: the folder {str(path.parent)!r} does not exist"
        )
    if path.is_dir():
        raise UserError(f"--measurements {str(path)!r} is a folder; give a CSV file")
    if path.exists() and not path.is_file():  # a device, a FIFO, a socket: never read whole
        raise UserError(f"--measurements {str(path)!r} is not a regular file; give a CSV file")
    if not os.access(path.parent, os.W_OK | os.X_OK):  # the file is replaced in its folder
        raise UserError(
            f"--measurements {str(path)!r}: the folder {str(path.parent)!r} cannot be written "
            "(no permission for this user): choose another file"
        )
    if not path.is_file():
        return
    try:
        labels = read_measurements(path).labels
    except ValueError as exc:
        if "no drops (rows) found" in str(exc):
            return
        raise UserError(f"--measurements: {exc}") from None
    if label in labels:
        raise UserError(
            f"--measurements {str(path)!r} has a drop labelled {label!r} already: give another "
            "--label"
        )


def append_drop(
    path: Path, res: ExperimentResult, label: str, include_doubtful: bool
) -> tuple[int, list[str]] | UserError | OSError:
    """(drops in the file, the warnings given) after appending the drop of ``res`` to ``path``,
    or the error saying why it was not (raised after the analysis is shown): a UserError for a
    drop the file cannot take (status 2), the system's OSError for a file that could not be
    written (status 1; the file named, not its temporary file)."""
    from impactlab.calibrate.experiment_rows import append_experiment

    if res.kinematics is None:
        return UserError(
            f"--measurements: nothing appended to {path}: the analysis has no kinematics (a "
            "drop needs its angle and incoming velocity)"
        )
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            meas = append_experiment(path, res, label, include_doubtful=include_doubtful)
        except ValueError as exc:
            text = str(exc).replace("include_doubtful=True (impactlab analyze --include-doubtful)",
                                    "--include-doubtful")  # fmt: skip
            return UserError(f"--measurements: nothing appended to {path}: {text}")
        except OSError as exc:  # a read-only or full disk, a folder without write permission
            if exc.errno is None:  # impactlab's own refusal (a lock it cannot take)
                return UserError(f"--measurements: nothing appended to {path}: {exc}")
            # the system's, while the command worked: status 1, the file named (not the
            # temporary one)
            return OSError(exc.errno, exc.strerror or type(exc).__name__, str(path))
    return meas.n_drops, [str(w.message) for w in caught]
