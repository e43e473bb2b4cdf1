"""A law file: a user's contact law from measured indentation data, for the command line
(``impactlab --law-file FILE ...``) and for study files (``[laws]``).

A law file is TOML (SI numbers, or strings with units)::

    name = "my-steel"                      # the law's name (--law my-steel)
    title = "Drop-rig indentation, 2026"   # optional
    source = "lab notebook 12, p. 40"      # optional
    body_material = "AISI-201"             # as for --body-material: a name, values or a file
    flat_material = "AISI-1010"
    radius = "8.8 mm"                      # the indenter's radius of the data (bare: m)
    loading = "loading.csv"                # columns delta [m], F [N]; one header line
    unloading = "unloading.csv"            # columns delta_max [m], delta_r [m]

CSV paths are relative to the law file. The data become ``IndentationCurves.from_csv`` and
the law is registered with ``register_law`` (the tabulated law under its own name).
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from impactlab._validation import check_positive, read_text_file
from impactlab.contact.indentation_data import IndentationCurves
from impactlab.contact.registered import RegisteredLaw
from impactlab.contact.registry import register_law
from impactlab.materials import ContactPair, get_material

#: The keys of a law file: required, then optional.
REQUIRED_KEYS = ("name", "body_material", "flat_material", "radius", "loading", "unloading")
OPTIONAL_KEYS = ("title", "source")


def read_law_file(path: str | Path) -> RegisteredLaw:
    """Register the law of the law file ``path`` (module docstring) and return it.
    ValueError naming the file and the key for a missing file, one that is not UTF-8 text, bad
    TOML, an unknown or missing key, or bad data."""
    where = str(path)
    p = Path(path)
    try:
        data: dict[str, Any] = tomllib.loads(read_text_file(p, "TOML", f"law file {where!r}"))
    except OSError as exc:
        raise ValueError(f"law file {where!r}: {exc.strerror or exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"law file {where!r}: not valid TOML ({exc})") from None
    unknown = sorted(set(data) - set(REQUIRED_KEYS) - set(OPTIONAL_KEYS))
    if unknown:
        raise ValueError(
            f"law file {where!r}: unknown key(s) {unknown}; known: "
            f"{', '.join(REQUIRED_KEYS + OPTIONAL_KEYS)}"
        )
    missing = [key for key in REQUIRED_KEYS if key not in data]
    if missing:
        raise ValueError(f"law file {where!r}: missing key(s) {missing}")
    for key in ("name", "loading", "unloading", *OPTIONAL_KEYS):
        if key in data and not isinstance(data[key], str):
            raise ValueError(f"law file {where!r}: {key} must be a string, got {data[key]!r}")
    try:
        pair = ContactPair(
            get_material(_beside(p, data["body_material"]), "body_material"),
            get_material(_beside(p, data["flat_material"]), "flat_material"),
        )
        radius = check_positive("radius", data["radius"], "m")
        curves = IndentationCurves.from_csv(
            pair,
            radius,
            p.parent / data["loading"],
            p.parent / data["unloading"],
            name=data["name"],
            source=data.get("source", f"law file {p.name}"),
        )
        return register_law(data["name"], curves, title=data.get("title", ""))
    except ValueError as exc:
        raise ValueError(f"law file {where!r}: {exc}") from None


__all__ = ["OPTIONAL_KEYS", "REQUIRED_KEYS", "read_law_file"]


def _beside(law_file: Path, material: Any) -> Any:
    """A material given as a TOML file by a relative path: the file beside the law file, as its
    CSV tables are (not one of the same name in the current folder); anything else as it is."""
    if isinstance(material, str) and material.strip().lower().endswith(".toml"):
        path = Path(material.strip())
        if not path.is_absolute():
            return law_file.parent / path
    return material
