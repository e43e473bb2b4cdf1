"""Sweeps: grids and Monte Carlo samples of many impacts into a resumable Zarr store.

Quick start::

    import numpy as np
    from impactlab.sweep import Study, run_sweep

    study = Study(name="regime-map",
                  grid={"angle": np.radians(np.linspace(5, 85, 81)),
                        "mu": np.linspace(0.0, 0.6, 61)},
                  fixed={"vy": -1.41})
    ds = run_sweep(study, "regime-map.zarr").dataset

See docs/sweep.md for the study-file format, resume semantics and Dask usage.
"""

from impactlab.sweep.backends import StoreWriteError
from impactlab.sweep.chunks import compute_chunk
from impactlab.sweep.dimensions import Axis, Layout, Sample
from impactlab.sweep.distributions import Distribution, LogNormal, Normal, Uniform
from impactlab.sweep.engine import (
    ENGINE,
    EngineEvaluator,
    Evaluator,
    numba_cache_stats,
)
from impactlab.sweep.inputs import INPUTS, OUTPUT_ALIASES, OUTPUTS, InputSpec
from impactlab.sweep.integrity import DamagedStoreError, RepairableStoreError
from impactlab.sweep.limits import DEFAULT_MAX_CASES, SweepSizeWarning
from impactlab.sweep.models import Statics
from impactlab.sweep.netcdf import export_csv, export_file, export_netcdf
from impactlab.sweep.options import EngineOptions, UncertaintySpec
from impactlab.sweep.plots import SliceWarning, plot_output_map, plot_regime_map
from impactlab.sweep.plotsweep import PlotSkipped, plot_plan, plot_sweep
from impactlab.sweep.runner import (
    FailedCasesWarning,
    FlaggedCasesWarning,
    SweepInterrupted,
    SweepResult,
    SweepStats,
    run_sweep,
)
from impactlab.sweep.store import (
    CorruptStoreError,
    StudyMismatchError,
    SweepStore,
    open_sweep,
)
from impactlab.sweep.study import Study, load_study
from impactlab.sweep.summary import flag_counts, status_counts, store_info
from impactlab.sweep.uncertainty import (
    UncertaintyReport,
    format_report,
    uncertainty_report,
    uncertainty_reports,
)

__all__ = [
    "DEFAULT_MAX_CASES",
    "ENGINE",
    "INPUTS",
    "OUTPUTS",
    "OUTPUT_ALIASES",
    "Axis",
    "CorruptStoreError",
    "DamagedStoreError",
    "Distribution",
    "EngineEvaluator",
    "EngineOptions",
    "Evaluator",
    "FailedCasesWarning",
    "FlaggedCasesWarning",
    "InputSpec",
    "Layout",
    "LogNormal",
    "Normal",
    "PlotSkipped",
    "RepairableStoreError",
    "Sample",
    "SliceWarning",
    "Statics",
    "StoreWriteError",
    "Study",
    "StudyMismatchError",
    "SweepInterrupted",
    "SweepResult",
    "SweepSizeWarning",
    "SweepStats",
    "SweepStore",
    "UncertaintyReport",
    "UncertaintySpec",
    "Uniform",
    "compute_chunk",
    "export_csv",
    "export_file",
    "export_netcdf",
    "flag_counts",
    "format_report",
    "load_study",
    "numba_cache_stats",
    "open_sweep",
    "plot_output_map",
    "plot_plan",
    "plot_regime_map",
    "plot_sweep",
    "run_sweep",
    "status_counts",
    "store_info",
    "uncertainty_report",
    "uncertainty_reports",
]
