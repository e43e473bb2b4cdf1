"""An explanation's files in an output folder: ``explain.csv`` (the comparison, one row per
drop, configuration and measured quantity, SI) and ``explain.json`` (``Explanation.to_dict``).

The rule of every output folder (docs/json-schema.md, "Files in an output folder"): a file that
an earlier explanation wrote is replaced; a file of the same name that it did not write (a
user's) is left as it is, and nothing is written (FileExistsError naming it). impactlab knows
its files by their content: ``explain.json`` by its keys, ``explain.csv`` by its header line.
An empty file (left by an interrupted write) is replaced. Each file is written whole or not at
all.
"""

from __future__ import annotations

import json
from pathlib import Path

from impactlab._files import folder_refusal, write_text_atomic
from impactlab.explain.result import Explanation
from impactlab.explain.tables import COMPARISON_COLUMNS

__all__ = ["CSV_NAME", "JSON_KEYS", "JSON_NAME", "save_explanation", "written_by_explain"]

CSV_NAME = "explain.csv"
JSON_NAME = "explain.json"
#: The keys that mark an ``explain.json`` as an explanation's.
JSON_KEYS = ("nothing_tuned", "configurations", "comparison", "summary")
_HEADER = ",".join(COMPARISON_COLUMNS)


def written_by_explain(path: Path) -> bool:
    """Whether the file ``path`` is one an explanation wrote (or an empty one): a JSON object
    holding :data:`JSON_KEYS`, a CSV file whose first line is the comparison's header."""
    try:
        if path.stat().st_size == 0:
            return True
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return False
    if path.suffix == ".json":
        try:
            data = json.loads(text)
        except ValueError:
            return False
        return isinstance(data, dict) and set(JSON_KEYS) <= data.keys()
    return text.splitlines()[0].strip() == _HEADER if text.strip() else True


def check_folder(folder: Path, option: str = "folder") -> None:
    """FileExistsError (NotADirectoryError for a file given as the folder or standing where a
    folder above it would be made; PermissionError for a folder that cannot be made or written
    to) before anything is written or run when a file of the explanation is in the way;
    ``option`` names the folder as the caller took it (``--out``)."""
    if folder.exists() and not folder.is_dir():
        raise NotADirectoryError(f"{option} {str(folder)!r} is a file; give a folder")
    above = next((p for p in (folder, *folder.absolute().parents) if p.exists()), None)
    if above is not None and not above.is_dir():
        raise NotADirectoryError(
            f"{option} {str(folder)!r}: {str(above)!r} is a file, so the folder cannot be made "
            "under it; give a folder"
        )
    refused = folder_refusal(folder, option)  # a probe, as every command's output folder
    if refused is not None:
        raise PermissionError(refused)
    paths = [folder / CSV_NAME, folder / JSON_NAME]
    for p in paths:
        if p.is_dir():
            raise FileExistsError(
                f"cannot write {str(p)!r}: a folder of that name is in the way (remove or "
                f"rename it, or choose another {option})"
            )
    foreign = [p for p in paths if p.is_file() and not written_by_explain(p)]
    if foreign:
        one = len(foreign) == 1
        named = " and ".join(repr(str(p)) for p in foreign)
        raise FileExistsError(
            f"{named} {'is' if one else 'are'} in the output folder but {'was' if one else 'were'}"
            f" not written by impactlab explain: {'it is' if one else 'they are'} left as "
            f"{'it is' if one else 'they are'} (move {'it' if one else 'them'}, or choose another "
            f"{option})"
        )


def save_explanation(
    explanation: Explanation, folder: str | Path, option: str = "folder"
) -> dict[str, Path]:
    """Write ``explain.csv`` and ``explain.json`` into ``folder`` (made with its parents) by
    the rule of every output folder (module docstring); returns name -> path."""
    out = Path(folder)
    check_folder(out, option)
    out.mkdir(parents=True, exist_ok=True)
    csv_path, json_path = out / CSV_NAME, out / JSON_NAME
    write_text_atomic(csv_path, explanation.comparison.to_csv(index=False, lineterminator="\n"))
    write_text_atomic(json_path, json.dumps(explanation.to_dict(), indent=2) + "\n")
    return {"csv": csv_path, "json": json_path}
