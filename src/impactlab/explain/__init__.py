"""Which physics explains measured drops: each drop of a measurements file with the rigid body,
the flexible rod (re-contacts of a ringing rod) and the flexible rod on a rate-dependent flat,
nothing tuned, every measured quantity beside its prediction (docs/explain.md)."""

from impactlab.explain.api import explain
from impactlab.explain.configurations import Configuration, configurations
from impactlab.explain.result import Explanation
from impactlab.explain.saving import save_explanation

__all__ = ["Configuration", "Explanation", "configurations", "explain", "save_explanation"]
