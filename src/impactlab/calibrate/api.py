"""``calibrate``: the posterior of each candidate model's free parameters given measured drops,
and the models ranked by PSIS-LOO."""

from __future__ import annotations

import math
import re
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._display import display_unit, format_number
from impactlab.calibrate.cluster import map_on_dask
from impactlab.calibrate.measurements import Measurements, read_measurements
from impactlab.calibrate.models import CandidateModel, predict
from impactlab.calibrate.posterior import LogPosterior
from impactlab.calibrate.priors import Parameter, parse_parameter
from impactlab.calibrate.ranking import rank_models
from impactlab.calibrate.result import ModelPosterior, summarise
from impactlab.calibrate.sampler import ProgressFn, run_chain
from impactlab.references import cite
from impactlab.sweep.engine import ENGINE, Evaluator

__all__ = ["REFERENCES", "Calibration", "CalibrationWarning", "calibrate", "parse_model"]

#: The methods' sources: the affine-invariant ensemble and emcee, PSIS-LOO, ArviZ and its R-hat.
REFERENCES = cite(
    "goodman-weare-2010", "foreman-mackey-2013", "vehtari-2017", "kumar-2019-arviz",
    "vehtari-2021-rhat",
)  # fmt: skip


class CalibrationWarning(UserWarning):
    """Something the calibration ran through but the user should know (a parameter a model
    does not use, a drop value replaced by a free parameter, a misfit)."""


@dataclass
class Calibration:
    """What ``calibrate`` returns: ``posteriors`` (model name -> ModelPosterior), ``ranking``
    (rows best first, ``rank_models``), the ``measurements``, the sampler settings and the
    ``warnings`` issued."""

    posteriors: dict[str, ModelPosterior]
    ranking: list[dict[str, Any]]
    measurements: Measurements
    settings: dict[str, Any]
    warnings: list[str] = field(default_factory=list)

    @property
    def best(self) -> ModelPosterior:
        """The best-ranked model's posterior."""
        name = self.ranking[0]["model"] if self.ranking else next(iter(self.posteriors))
        return self.posteriors[name]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready (SI units)."""
        return {
            "measurements": {
                "source": self.measurements.source,
                "drops": list(self.measurements.labels),
                "quantities": list(self.measurements.quantities),
                "values": self.measurements.n_values,
            },
            "settings": self.settings,
            "ranking": self.ranking,
            "criterion": "PSIS-LOO elpd over drops (higher is better)",
            "models": {k: v.to_dict() for k, v in self.posteriors.items()},
            "warnings": self.warnings,
        }


def parse_model(spec: str | CandidateModel | Mapping[str, Any]) -> CandidateModel:
    """A CandidateModel from ``"law/friction[/flexible_rod[/rate]]"`` (the form of its
    ``name``), a mapping of its fields or itself."""
    if isinstance(spec, CandidateModel):
        return spec
    if isinstance(spec, Mapping):
        return CandidateModel(**dict(spec))
    parts = [p.strip() for p in str(spec).split("/")]
    if not 1 <= len(parts) <= 4 or not all(parts):
        raise ValueError(
            f"model {spec!r}: expected 'law', 'law/friction', 'law/friction/body' or "
            "'law/friction/flexible_rod/rate'"
        )
    friction = parts[1] if len(parts) > 1 else "coulomb"
    body = parts[2] if len(parts) > 2 else None
    rate = parts[3] if len(parts) > 3 else None
    try:
        return CandidateModel(parts[0], friction, body, rate=rate)
    except ValueError as exc:
        raise ValueError(f"model {spec!r}: {exc}") from None


def _params(parameters: Sequence[Parameter] | Mapping[str, Any]) -> tuple[Parameter, ...]:
    if isinstance(parameters, Mapping):
        out = tuple(
            v if isinstance(v, Parameter) else parse_parameter(k, v) for k, v in parameters.items()
        )
    else:
        out = tuple(parameters)
    if not out:
        raise ValueError("calibrate needs at least one free parameter")
    names = [p.name for p in out]
    if len(set(names)) != len(names):
        raise ValueError(f"a free parameter is given twice: {names}")
    return out


def _check_inputs(meas: Measurements, params: Sequence[Parameter], note: list[str]) -> None:
    free = {p.name for p in params}
    if "mu" not in free and not np.isfinite(meas.inputs["mu"]).all():
        missing = [
            lab for lab, m in zip(meas.labels, meas.inputs["mu"], strict=True) if math.isnan(m)
        ]
        raise ValueError(
            f"drops {missing} give no mu: give it in the measurements file or make mu a free "
            "parameter"
        )
    for p in params:
        given = np.isfinite(meas.inputs[p.name])
        if given.any():
            note.append(
                f"{p.name} is a free parameter: the value given for {int(given.sum())} drop(s) "
                "in the measurements is not used"
            )


def _uses(
    model: CandidateModel,
    meas: Measurements,
    params: Sequence[Parameter],
    evaluator: Evaluator,
    engine: Mapping[str, Any],
) -> list[bool]:
    """For each parameter: does changing it (over the prior's deciles 1, 3, 5, 7, 9, the
    others at their medians) change any prediction of ``model``? One batch of 5P + 1 vectors.
    (A parameter whose every value fails counts as used: the prior check names the reason.)"""
    med = np.array([float(p.quantile(0.5)) for p in params])
    levels = (0.1, 0.3, 0.5, 0.7, 0.9)
    rows = [med]
    for j, p in enumerate(params):
        for q in levels:
            t = med.copy()
            t[j] = float(p.quantile(q))
            rows.append(t)
    pred = predict(model, meas, params, np.array(rows), evaluator=evaluator, engine=engine)
    used = []
    k = len(levels)
    for j in range(len(params)):
        idx = list(range(1 + k * j, 1 + k * (j + 1)))
        same = all(
            np.array_equal(v[i], v[idx[0]], equal_nan=True)
            for v in pred.values.values()
            for i in idx[1:]
        ) and all(np.array_equal(pred.status[i], pred.status[idx[0]]) for i in idx[1:])
        all_failed = bool((pred.status[idx] != 0).all())
        used.append(not same or all_failed)
    return used


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

    def __call__(
        self, model: CandidateModel, state: Path | None, progress: ProgressFn | None
    ) -> ModelPosterior:
        post = LogPosterior(model, self.meas, self.params, self.evaluator, self.engine)
        sampler = run_chain(
            post, walkers=self.walkers, steps=self.steps, seed=self.seed, state=state,
            restart=self.restart, progress=progress,
        )  # fmt: skip
        return summarise(
            post, sampler, steps=self.steps, burn=self.burn, seed=self.seed, n_ppc=self.n_ppc
        )


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
    walkers : ensemble size (default max(16, 4 P), even); steps : steps per walker in all;
    burn : steps discarded (default steps // 2); seed : the random seed (same inputs and seed:
    the same chain); state_dir : a folder keeping each model's chain (emcee HDF5), so that an
    interrupted calibration resumes (``restart`` discards it); progress(model, done, total);
    evaluator, engine : the engine adapter and its options (gravity, rtol; default: the
    compiled engine, gravity on); scheduler : a Dask ``distributed.Client`` or scheduler
    address: each model's chain runs as one task there (no progress display; ``state_dir``
    must be a folder the workers share).

    ValueError for a parameter no model uses, a prior in which a model cannot produce the
    measurements, and bad input in general; a CalibrationWarning for a parameter some models do
    not use and for values of the file that a free parameter replaces.
    """
    meas = (
        measurements if isinstance(measurements, Measurements) else read_measurements(measurements)
    )
    params = _params(parameters)
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
    least = max(4, 2 * len(params))
    if walkers is not None and walkers < least:
        raise ValueError(f"walkers must be >= {least} (4 and 2 x parameters), got {walkers}")
    nw = walkers if walkers is not None else max(16, 4 * len(params))
    nw += nw % 2
    if steps < 10:
        raise ValueError(f"steps must be >= 10, got {steps}")
    nburn = steps // 2 if burn is None else int(burn)
    if not 0 <= nburn < steps:
        raise ValueError(f"burn must lie in [0, steps), got {burn}")
    eng = dict(engine or {})
    notes: list[str] = []
    _check_inputs(meas, params, notes)
    usage = {c.name: _uses(c, meas, params, evaluator, eng) for c in cands}
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
    for text in notes:
        warnings.warn(text, CalibrationWarning, stacklevel=2)
    run = _Run(meas, params, evaluator, eng, nw, steps, nburn, seed, restart, n_ppc)
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
    misfits = _misfits(posteriors)
    for text in misfits:
        warnings.warn(text, CalibrationWarning, stacklevel=2)
    settings = {
        "sampler": "emcee EnsembleSampler (stretch move), vectorised",
        "walkers": nw,
        "steps": steps,
        "burn": nburn,
        "seed": seed,
        "parameters": {p.name: p.describe() for p in params},
        "models": names,
        "likelihood": "independent Gaussian errors with the stated standard uncertainties",
        "references": [str(r) for r in REFERENCES],
    }
    return Calibration(posteriors, rank_models(posteriors), meas, settings, notes + misfits)


#: A best fit farther than this many standard uncertainties from a measured value is a misfit.
MISFIT_SIGMAS = 5.0


def _misfits(posteriors: Mapping[str, ModelPosterior]) -> list[str]:
    """One line per measured value that no model's best fit comes within MISFIT_SIGMAS of."""
    worst: dict[tuple[str, str], tuple[float, str, dict[str, Any]]] = {}
    for name, p in posteriors.items():
        for r in p.ppc:
            key, z = (r["drop"], r["quantity"]), abs(r["z_best"])
            z = z if math.isfinite(z) else math.inf
            if key not in worst or z < worst[key][0]:
                worst[key] = (z, name, r)
    lines = []
    for (d, q), (z, name, r) in worst.items():
        if z <= MISFIT_SIGMAS:
            continue
        show = display_unit(q, r["unit"])  # dent-scale lengths in um, as the tables
        unit = "" if show.unit in ("1", "") else f" {show.unit}"
        value, sigma, best = (format_number(r[k] * show.scale, n)
                              for k, n in (("observed", 4), ("sigma", 2), ("best", 4)))  # fmt: skip
        lines.append(
            f"no model reproduces {d} {q} = {value} +- {sigma}{unit}: the closest best fit "
            f"({name}: {best}{unit}) is {z:.1f} sigma away"
        )
    return lines
