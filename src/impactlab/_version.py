"""The installed version of impactlab (from the package metadata, with a fallback)."""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version

try:
    __version__: str = version("impactlab")
except PackageNotFoundError:  # pragma: no cover - running from a source tree without metadata
    __version__ = "0.2.0"

__all__ = ["__version__"]
