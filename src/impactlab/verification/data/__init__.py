"""Published measurements used by the verification pages (each module states its source)."""
