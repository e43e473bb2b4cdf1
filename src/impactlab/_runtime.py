"""What ``import impactlab`` sets up before any compiled function is defined: numba's cache
folder (``impactlab._compiled_cache``) and the notice while the engine compiles
(``impactlab._compile_notice``)."""

from __future__ import annotations

from impactlab._compile_notice import install
from impactlab._compiled_cache import use_cache_dir

use_cache_dir()
install()
