"""What ``import impactlab`` sets up before any compiled function is defined: numba's cache
folder (``impactlab._compiled_cache``), the notice while the engine compiles
(``impactlab._compile_notice``) and the garbage collector's pause during that compilation
(``impactlab._compile_gc``)."""

from __future__ import annotations

from impactlab import _compile_gc, _compile_notice
from impactlab._compiled_cache import use_cache_dir

use_cache_dir()
_compile_notice.install()
_compile_gc.install()
