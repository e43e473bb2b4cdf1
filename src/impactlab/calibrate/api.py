"""``calibrate``: the posterior of each candidate model's free parameters given measured drops,
and the models ranked by PSIS-LOO."""

from __future__ import annotations

import contextlib
import os
import re
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from impactlab.calibrate.calibration_warning import CalibrationWarning
from impactlab.calibrate.cluster import map_on_dask
from impactlab.calibrate.correlated_likelihood import correlation_rows, likelihood_text
from impactlab.calibrate.diagnostics import misfits
from impactlab.calibrate.display import calibration_html, calibration_text
from impactlab.calibrate.drop_predictions import DropPredictions, predict_drops
from impactlab.calibrate.input_checks import (
    check_calibration_inputs,
    check_engine_cells,
    check_n_ppc,
    engine_options,
    parameter_usage,
    sampler_settings,
    unused_fixed,
)
from impactlab.calibrate.input_checks import parameters as free_parameters
from impactlab.calibrate.measurement_rows import unit_text
from impactlab.calibrate.measurements import Measurements, read_measurements
from impactlab.calibrate.model_specs import model_definition, parse_model
from impactlab.calibrate.models import CandidateModel
from impactlab.calibrate.posterior import LogPosterior
from impactlab.calibrate.priors import Parameter
from impactlab.calibrate.ranking import NOT_CONVERGED, rank_models
from impactlab.calibrate.result import ONE_DROP, ModelPosterior, summarise
from impactlab.calibrate.run_warnings import best_warnings as _best_warnings
from impactlab.calibrate.run_warnings import chain_warnings as _chain_warnings
from impactlab.calibrate.sampler import ProgressFn, run_chain
from impactlab.calibrate.statelock import state_lock
from impactlab.references import cite
from impactlab.sweep.engine import ENGINE, Evaluator
from impactlab.sweep.inputs import INPUTS

__all__ = ["REFERENCES", "Calibration", "CalibrationWarning", "calibrate", "parse_model"]

#: The methods' sources: the affine-invariant ensemble and emcee, PSIS-LOO, ArviZ and its R-hat,
#: the ranking's stacking weights and its rule for small elpd differences.
REFERENCES = cite(
    "goodman-weare-2010", "foreman-mackey-2013", "vehtari-2017", "kumar-2019-arviz",
    "vehtari-2021-rhat", "yao-2018-stacking", "sivula-2020-loo-uncertainty",
)  # fmt: skip


@dataclass(repr=False)
class Calibration:
    """What ``calibrate`` returns: ``posteriors`` (model name -> ModelPosterior), ``ranking``
    (rows best first, ``rank_models``: with ``converged``, ``distinguishable`` and ``note``),
    the ``measurements``, the sampler settings (with the engine options and each model's
    definition) and the ``warnings`` given."""

    posteriors: dict[str, ModelPosterior]
    ranking: list[dict[str, Any]]
    measurements: Measurements
    settings: dict[str, Any]
    warnings: list[str] = field(default_factory=list)

    @property
    def best(self) -> ModelPosterior:
        """The best-ranked model's posterior (``best_caveats``: why the choice may not hold)."""
        name = self.ranking[0]["model"] if self.ranking else next(iter(self.posteriors))
        return self.posteriors[name]

    @property
    def best_caveats(self) -> list[str]:
        """Why ``best`` may not be the model the data single out: its elpd does not differ from
        the runner-up's by 2 dse (``"not distinguishable (elpd_diff < 2 dse)"``) or by 4
        (``"not distinguishable (elpd_diff < 4)"``), either model has a drop with Pareto
        k > 0.7 (``"not distinguishable (Pareto k > 0.7: PSIS-LOO unreliable)"``), one drop
        cannot rank the models (``"not distinguishable (one drop: PSIS-LOO does not rank)"``),
        its chain has not converged (``"not converged"``), or its best fit lies more than 5
        standard uncertainties from a measured value (``"misfit (best fit > 5 sigma from a
        measured value)"``), or its posterior lies against a bound of a prior (``"at a prior
        bound (its interval is cut there)"``); empty when none."""
        if not self.ranking:
            return [] if self.best.converged else [NOT_CONVERGED]
        return [n for n in self.ranking[0]["note"].split("; ") if n]

    def predict(
        self,
        conditions: Measurements | Sequence[Mapping[str, Any]] | Mapping[str, Any] | str | Path,
        quantities: Sequence[str] | None = None,
        *,
        model: str | None = None,
        draws: int = 200,
        seed: int | None = 0,
        evaluator: Evaluator = ENGINE,
    ) -> DropPredictions:
        """What ``model`` (default: the best-ranked) predicts for drops that were not
        measured: ``conditions`` gives their inputs only (records such as ``{"label": "new",
        "angle": "30 deg", "vy": -2.0}``, one such record alone, a file, or
        ``Measurements.conditions``);
        ``quantities`` (default: those measured in the calibration) are any measurable ones
        (``e``, ``delta_p``, ``max_force``, ...), predicted at ``draws`` posterior draws
        (``seed``: an integer in [0, 2**32), or None for fresh draws; all the posterior holds,
        with a ``CalibrationWarning``, when it holds fewer: ``summary()``'s ``n_draws``);
        ``DropPredictions.summary()`` gives each one's median and 90 % interval and the share of
        draws beyond the contact law's verified range (``extrapolated``, with a
        ``CalibrationWarning``); a drop whose every draw failed is warned about and named with its
        reason (``DropPredictions.reason``). ``evaluator`` should be the one the calibration ran."""
        order = {r["model"]: r["rank"] for r in self.ranking}
        ranked = dict(sorted(self.posteriors.items(), key=lambda kv: order.get(kv[0], 0)))
        return predict_drops(
            ranked, self.settings, conditions, quantities or self.measurements.quantities,
            model=model, draws=draws, seed=seed, evaluator=evaluator,
            calibrated=self.measurements,
        )  # fmt: skip

    def __repr__(self) -> str:
        return calibration_text(self)

    def _repr_html_(self) -> str:
        return calibration_html(self)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready (the units of ``Measurements`` and ``Parameter.unit``)."""
        return {
            "measurements": {
                "source": self.measurements.source,
                "drops": list(self.measurements.labels),
                "quantities": list(self.measurements.quantities),
                "values": self.measurements.n_values,
                "correlation": correlation_rows(self.measurements),
            },
            "settings": self.settings,
            "ranking": self.ranking,
            "criterion": "PSIS-LOO elpd over drops (higher is better)",
            "models": {k: v.to_dict() for k, v in self.posteriors.items()},
            "warnings": self.warnings,
        }


@dataclass(frozen=True)
class _Run:
    """One model's chain and its summary, with the settings shared by every model (a
    picklable callable: the task of a Dask worker)."""

    meas: Measurements
    params: tuple[Parameter, ...]
    evaluator: Evaluator
    engine: dict[str, Any]
    walkers: int
    steps: int
    burn: int
    seed: int
    restart: bool
    n_ppc: int
    unused: Mapping[str, tuple[str, ...]]

    def __call__(
        self, model: CandidateModel, state: Path | None, progress: ProgressFn | None
    ) -> ModelPosterior:
        post = LogPosterior(model, self.meas, self.params, self.evaluator, self.engine)
        sampler = run_chain(
            post, walkers=self.walkers, steps=self.steps, seed=self.seed, state=state,
            restart=self.restart, progress=progress,
        )  # fmt: skip
        return summarise(
            post, sampler, steps=self.steps, burn=self.burn, seed=self.seed, n_ppc=self.n_ppc,
            unused=self.unused.get(model.name, ()),
        )  # fmt: skip


def _slug(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name)


def calibrate(
    measurements: Measurements | str | Path,
    parameters: Sequence[Parameter] | Mapping[str, Any],
    models: Sequence[CandidateModel | str] | CandidateModel | str = ("ghaednia/coulomb",),
    *,
    walkers: int | None = None,
    steps: int = 1000,
    burn: int | None = None,
    seed: int = 0,
    state_dir: str | Path | None = None,
    restart: bool = False,
    progress: ProgressFn | None = None,
    evaluator: Evaluator = ENGINE,
    engine: Mapping[str, Any] | None = None,
    n_ppc: int = 200,
    scheduler: Any = None,
) -> Calibration:
    """Calibrate the free ``parameters`` of each candidate model on the measured drops.

    measurements : a Measurements or the path of a measurements file (CSV or TOML);
    parameters : Parameters, or name -> prior text (``{"mu": "uniform(0, 1)"}``);
    models : CandidateModels or ``"law/friction[/flexible_rod]"`` texts;
    walkers : ensemble size (default max(16, 4 P), even); steps : steps per walker in all
    (a saved chain that holds more is used up to ``steps``); burn : steps discarded (default
    steps // 2); seed : the random seed, an integer in [0, 2^32) (same inputs and seed: the
    same chain); state_dir : a folder keeping each model's chain (emcee HDF5), so that an
    interrupted calibration resumes (``restart`` discards it; one calibration at a time uses
    a folder; a saved chain of other inputs, or unreadable, is refused:
    ``statelock.SavedChainError``); progress(model, done, total); evaluator, engine : the engine
    adapter and its options (gravity, rtol: a value, or results.json's quantity object;
    partial_slip_cells: friction partial_slip's cells; default: the compiled engine, gravity
    on); scheduler : a Dask
    ``distributed.Client`` or scheduler address: each model's chain runs as one task there
    (no progress display; ``state_dir`` must be a folder the workers share).

    ValueError for a parameter no model uses, a prior in which a model cannot produce the
    measurements, and bad input in general; a CalibrationWarning for a parameter some models do
    not use, for values of the file that a free parameter replaces, for misfits, chains that
    have not converged, posteriors against their prior's bound, a contact law used beyond its
    verified range in the predicted impacts (advisory: the cases still count), a model whose
    prior reaches where it does not run (more than ``diagnostics.FAILED_SHARE_MAX`` of the
    parameter values failed) and a best model the data do not single out
    (``Calibration.best_caveats``). Ctrl-C raises
    ``statelock.CalibrationInterrupted`` (a KeyboardInterrupt naming the step reached);
    ``statelock.StateInUseError`` (a ValueError) when another calibration uses ``state_dir``.
    """
    lock = state_lock(Path(state_dir)) if state_dir is not None else contextlib.nullcontext()
    with lock:
        return _calibrate(
            measurements, parameters, models, walkers=walkers, steps=steps, burn=burn,
            seed=seed, state_dir=state_dir, restart=restart, progress=progress,
            evaluator=evaluator, engine=engine, n_ppc=n_ppc, scheduler=scheduler,
        )  # fmt: skip


def _calibrate(
    measurements: Measurements | str | Path,
    parameters: Sequence[Parameter] | Mapping[str, Any],
    models: Sequence[CandidateModel | str] | CandidateModel | str,
    *,
    walkers: int | None,
    steps: int,
    burn: int | None,
    seed: int,
    state_dir: str | Path | None,
    restart: bool,
    progress: ProgressFn | None,
    evaluator: Evaluator,
    engine: Mapping[str, Any] | None,
    n_ppc: int,
    scheduler: Any,
) -> Calibration:
    if not isinstance(measurements, Measurements | str | os.PathLike):
        raise ValueError(
            "measurements must be a Measurements or the path of a measurements file (CSV or "
            f"TOML), got {measurements!r}"
        )
    n_ppc = check_n_ppc(n_ppc)
    meas = (
        measurements if isinstance(measurements, Measurements) else read_measurements(measurements)
    )
    params = free_parameters(parameters)
    cands = [
        parse_model(m) for m in ([models] if isinstance(models, str | CandidateModel) else models)
    ]
    if not cands:
        raise ValueError("calibrate needs at least one candidate model")
    for c in cands:
        missing = c.unsupported(meas.quantities)
        if missing:
            raise ValueError(
                f"model {c.name!r} does not predict {', '.join(missing)}: leave those out or "
                "choose other models"
            )
    names = [c.name for c in cands]
    if len(set(names)) != len(names):
        raise ValueError(f"two candidate models have the same name: {names}")
    nw, steps, nburn, seed = sampler_settings(len(params), walkers, steps, burn, seed)
    eng, g = engine_options(engine)
    check_engine_cells(eng, cands)
    notes: list[str] = []
    check_calibration_inputs(meas, params, cands, notes)
    usage = {c.name: parameter_usage(c, meas, params, evaluator, eng) for c in cands}
    for j, p in enumerate(params):
        users = [n for n in names if usage[n][j]]
        if not users:
            raise ValueError(
                f"free parameter {p.name!r} changes no prediction of any model ({', '.join(names)})"
                " over its prior: no model uses it; remove it"
            )
        notes += [
            f"model {n!r} does not use {p.name}: its posterior is its prior"
            for n in names
            if not usage[n][j]
        ]
    notes += [
        f"model {c.name!r} does not use its fixed {k} (= {c.fixed[k]:g}"
        f"{unit_text(INPUTS[k].unit)}): it changes none of the model's predictions of the "
        "measured values; remove it"
        for c in cands
        for k in unused_fixed(c, meas, params, evaluator, eng)
    ]
    for text in notes:
        warnings.warn(text, CalibrationWarning, stacklevel=3)
    unused = {n: tuple(p.name for j, p in enumerate(params) if not usage[n][j]) for n in names}
    run = _Run(meas, params, evaluator, eng, nw, steps, nburn, seed, restart, n_ppc, unused)
    states = [
        Path(state_dir) / f"{_slug(c.name)}.h5" if state_dir is not None else None for c in cands
    ]
    if scheduler is None:
        done = [run(c, s, progress) for c, s in zip(cands, states, strict=True)]
    else:
        done = map_on_dask(
            scheduler, run, [(c, s, None) for c, s in zip(cands, states, strict=True)]
        )
    posteriors = {c.name: p for c, p in zip(cands, done, strict=True)}
    found = misfits(posteriors) + _chain_warnings(posteriors, params, usage, cands)
    ranking = rank_models(posteriors)
    found += [ONE_DROP] if meas.n_drops < 2 else []
    found += _best_warnings(ranking)
    for text in found:
        warnings.warn(text, CalibrationWarning, stacklevel=3)
    settings = {
        "sampler": "emcee EnsembleSampler (stretch move), vectorised",
        "walkers": nw,
        "steps": steps,
        "burn": nburn,
        "seed": seed,
        "parameters": {p.name: p.describe() for p in params},
        "models": names,
        "model_definitions": {c.name: model_definition(c) for c in cands},
        "engine": {"gravity": g, "rtol": eng.get("rtol")}
        | {k: v for k, v in eng.items() if k == "partial_slip_cells" and v is not None},
        "likelihood": likelihood_text(meas),
        "references": [str(r) for r in REFERENCES],
    }
    return Calibration(posteriors, ranking, meas, settings, notes + found)
