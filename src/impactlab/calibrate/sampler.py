"""The sampler: emcee's affine-invariant ensemble (Goodman & Weare 2010, emcee: Foreman-Mackey
et al. 2013), vectorised: each step proposes a position for every walker and evaluates all of
them on every drop in one batch. Why emcee: a calibration here has 1-5 parameters, a smooth
likelihood except where the number of contacts changes, and costs one batch call per step;
an ensemble sampler needs no gradients and no tuning, and the model ranking is PSIS-LOO from the
pointwise log likelihoods it stores (``impactlab.calibrate.ranking``), so no evidence integral
(nested sampling) is needed.

With ``state`` (a file path) the chain is kept in emcee's HDF5 backend: an interrupted run
continues from its last step when called again with the same inputs; a saved chain of other
inputs, or one that cannot be read, is never replaced unasked: ``SavedChainError`` names the
file and why (``restart`` discards it). Ctrl-C raises
``CalibrationInterrupted`` (the step reached, and whether it was saved); a chain file another
program holds open is a ``StateInUseError`` (``statelock.chain_in_use``), never HDF5's traceback.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import emcee
import numpy as np

from impactlab._interrupts import signals_held
from impactlab.calibrate.posterior import LogPosterior, initial_walkers
from impactlab.calibrate.statelock import CalibrationInterrupted, SavedChainError, chain_in_use
from impactlab.dynamics.input_checks import gravity_value
from impactlab.friction import PARTIAL_SLIP_CELLS
from impactlab.materials import G0

__all__ = ["ProgressFn", "run_chain"]

#: progress(model name, steps done, steps in all)
ProgressFn = Callable[[str, int, int], None]


def _engine(engine: Mapping[str, Any]) -> list[Any]:
    """The engine options as they act: the gravity [m/s^2], the rtol and a partial-slip cell
    count other than the default as numbers, so that
    ``gravity = true``, ``9.80665`` and ``{value = 9.80665, unit = "m/s^2"}`` are one setting;
    the default ones (standard gravity, the engine's rtol) as ``[]``, the form of a chain saved
    without engine options before these were normalised."""
    g = gravity_value(engine.get("gravity", True))
    rtol = engine.get("rtol")
    acting = {"gravity": g, "rtol": None if rtol is None else float(rtol)}
    cells = engine.get("partial_slip_cells")
    if cells is not None and int(cells) != PARTIAL_SLIP_CELLS:  # the default: as not given
        acting["partial_slip_cells"] = int(cells)
    return [] if acting == {"gravity": G0, "rtol": None} else sorted(acting.items())


def _inputs(post: LogPosterior, walkers: int, seed: int) -> dict[str, Any]:
    """Everything that determines the chain (data, model, priors, walkers, seed), by part."""
    m = post.meas
    doc: dict[str, Any] = {
        "model": repr(post.model),
        "params": [repr(p) for p in post.params],
        "walkers": walkers,
        "seed": seed,
        "engine": _engine(post.engine),
        "labels": list(m.labels),
        "cats": [sorted(c.items()) for c in m.categories],
        "inputs": {k: v.tolist() for k, v in m.inputs.items()},
        "observed": {k: v.tolist() for k, v in m.observed.items()},
        "sigma": {k: v.tolist() for k, v in m.sigma.items()},
    }
    acting = _acting_correlations(m.correlation)
    if acting:  # only when one acts: the fingerprints of chains without them stay valid
        doc["correlation"] = acting
    return doc


def _acting_correlations(correlation: Mapping[tuple[str, str], np.ndarray]) -> dict[str, Any]:
    """The correlation coefficients as the likelihood uses them: a blank one (NaN) as 0, and
    a pair that is 0 in every drop left out, so that a column absent, blank or of zeros is one
    input (the same chain)."""
    out = {}
    for (a, b), x in correlation.items():
        values = np.nan_to_num(np.asarray(x, dtype=np.float64), nan=0.0)
        if np.any(values != 0.0):
            out[f"{a},{b}"] = (values + 0.0).tolist()  # + 0.0: -0.0 as 0.0
    return out


def _hash(doc: Any) -> str:
    text = json.dumps(doc, sort_keys=True, default=str).replace("NaN", "null")
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def fingerprint(post: LogPosterior, walkers: int, seed: int) -> str:
    """A hash of everything that determines the chain (data, model, priors, walkers, seed)."""
    return _hash(_inputs(post, walkers, seed))


#: What each part of the inputs is, to say which changed since a chain was saved.
_PARTS = {
    "model": "the model",
    "params": "the priors",
    "walkers": "the number of walkers",
    "seed": "the seed",
    "engine": "the engine options",
    "labels": "the drops' labels",
    "cats": "the drops' bodies or materials",
    "inputs": "the drops' inputs",
    "observed": "the measured values",
    "sigma": "the measured values' uncertainties",
    "correlation": "the drops' correlation coefficients",
}


def _changed(saved: Any, parts: dict[str, str]) -> str:
    """Why a saved chain does not fit: the parts of its inputs that differ from ``parts``
    (the hashes stored with it), or all of them in general for a file without them."""
    try:
        old = json.loads(saved)
        differ = [_PARTS[k] for k in _PARTS if old.get(k) != parts.get(k)]
    except (TypeError, ValueError, AttributeError):
        differ = []
    what = ", ".join(differ) or "the measurements, priors, model, walkers, seed or engine options"
    return f"was made with other inputs ({what} changed)"


def _unreadable(exc: BaseException) -> str:
    if isinstance(exc, KeyError):
        return "holds no chain of a calibration"
    text = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
    return f"cannot be read ({text}): a run stopped while writing it, or another file"


def _backend(
    state: Path | None, keys: tuple[str, ...], parts: dict[str, str], restart: bool
) -> tuple[Any, bool]:
    """(backend, resumed): emcee's HDF backend at ``state`` (resumed when it holds a chain of
    the fingerprint ``keys[0]``, or of a later key: the same inputs hashed as chains were saved
    before, the engine options as given or the correlation coefficients as written; it is then
    stored as ``keys[0]``), or the in-memory
    one. A saved chain of other inputs, or one that cannot be read, is kept and refused
    (``SavedChainError``) unless ``restart``; one without a step (an empty file too) is
    replaced (it holds no work)."""
    if state is None:
        return emcee.backends.Backend(), False
    state.parent.mkdir(parents=True, exist_ok=True)
    empty = state.is_file() and state.stat().st_size == 0
    if state.exists() and not empty and not restart:
        backend = _WholeStepBackend(str(state), name="chain")
        try:
            with backend.open() as f:
                attrs = f["chain"].attrs
                same = attrs.get("impactlab_fingerprint") in keys
                saved_parts = attrs.get("impactlab_parts")
            steps = backend.iteration
        except BlockingIOError as exc:  # HDF5's lock: another program has the file open
            raise chain_in_use(state, exc, 0) from None
        except (OSError, KeyError) as exc:
            raise SavedChainError(state, _unreadable(exc)) from None
        if same and steps > 0:
            if saved_parts != json.dumps(parts):
                _stamp(backend, keys[0], parts)
            return backend, True
        if steps > 0:
            raise SavedChainError(state, _changed(saved_parts, parts))
    if state.exists():
        state.unlink()
    return _WholeStepBackend(str(state), name="chain"), False


class _WholeStepBackend(emcee.backends.HDFBackend):  # type: ignore[misc]
    """emcee's HDF backend that saves a step and the log posterior's counts (``counted``) as
    one: Ctrl-C or SIGTERM during the save arrives after it, so that a resumed chain never
    redoes a step half saved (its acceptances counted twice, its random state advanced)."""

    counted: LogPosterior | None = None

    def save_step(self, state: Any, accepted: Any) -> None:
        with signals_held():
            super().save_step(state, accepted)
            if self.counted is not None:
                _save_counts(self, self.counted)


def _check_samples(backend: Any, post: LogPosterior, state: Any) -> None:
    """SavedChainError for a saved chain holding a sample that is not finite or lies outside
    its prior's support: a chain damaged in place, which its file's own structure does not
    show (every sample a chain accepts lies where its prior is positive)."""
    chain = np.asarray(backend.get_chain(), dtype=np.float64)
    flat = chain.reshape(-1, chain.shape[-1])
    with np.errstate(all="ignore"):
        bad = ~np.isfinite(flat).all(axis=1) | ~np.isfinite(post.log_prior(flat))
    if bad.any():
        i = int(np.argmax(bad))
        step, walker = divmod(i, chain.shape[1])
        values = ", ".join(f"{p.name} = {v:g}" for p, v in zip(post.params, flat[i], strict=True))
        raise SavedChainError(
            state,
            f"holds a sample outside its prior's support or not finite (step {step}, walker "
            f"{walker}: {values}): damaged after it was written",
        )


def _stamp(backend: Any, key: str, parts: dict[str, str]) -> None:
    """Store the fingerprint ``key`` and the hashes of the parts with the chain."""
    with backend.open("a") as f:
        f["chain"].attrs["impactlab_fingerprint"] = key
        f["chain"].attrs["impactlab_parts"] = json.dumps(parts)


#: The attribute of a saved chain holding the log posterior's counts (failures by reason,
#: evaluations, draws, failed draws) of the steps it holds.
_COUNTS = "impactlab_counts"


def _save_counts(backend: Any, post: LogPosterior) -> None:
    """Store ``post``'s counts with the chain, so that a resumed run reports the whole chain's."""
    counts = {
        "failures": dict(post.failures),
        "evaluations": post.evaluations,
        "draws": post.draws,
        "failed_draws": post.failed_draws,
    }
    with backend.open("a") as f:
        f["chain"].attrs[_COUNTS] = json.dumps(counts)


def _load_counts(backend: Any, post: LogPosterior) -> None:
    """Add the counts saved with a resumed chain to ``post``'s (a chain saved without them, by
    an earlier version: none)."""
    with backend.open() as f:
        text = f["chain"].attrs.get(_COUNTS)
    if not text:
        return
    counts = json.loads(text)
    post.failures.update({str(k): int(v) for k, v in counts["failures"].items()})
    post.evaluations += int(counts["evaluations"])
    post.draws += int(counts["draws"])
    post.failed_draws += int(counts["failed_draws"])


def run_chain(
    post: LogPosterior,
    *,
    walkers: int,
    steps: int,
    seed: int,
    state: Path | None = None,
    restart: bool = False,
    progress: ProgressFn | None = None,
) -> emcee.EnsembleSampler:
    """Run (or continue) the ensemble for ``steps`` steps in all; returns the sampler."""
    ndim = len(post.params)
    doc = _inputs(post, walkers, seed)
    key, parts = _hash(doc), {k: _hash(v) for k, v in doc.items()}
    given = sorted((k, repr(v)) for k, v in post.engine.items())  # as chains were saved before
    written = {f"{a},{b}": x.tolist() for (a, b), x in post.meas.correlation.items()}
    earlier = (
        _hash({**doc, "engine": given}),
        _hash({**doc, "correlation": written}),  # coefficients as written, as saved before
    )
    backend, resumed = _backend(state, (key, *earlier), parts, restart)
    sampler = emcee.EnsembleSampler(walkers, ndim, post, vectorize=True, backend=backend)
    # the log posterior itself, not emcee's wrapper: that prints a traceback of any exception
    # (Ctrl-C included) before passing it on
    sampler.log_prob_fn = post
    if state is not None:  # the counts of the steps saved, with them
        backend.counted = post
    if resumed:
        _check_samples(backend, post, state)
        done = backend.iteration
        start: Any = backend.get_last_sample()  # with its random state
        _load_counts(backend, post)
    else:
        rng = np.random.default_rng(seed)
        start = initial_walkers(post, walkers, rng)
        sampler.random_state = np.random.RandomState(seed).get_state()
        backend.reset(walkers, ndim)
        if state is not None:
            _stamp(backend, key, parts)
        done = 0
    if progress is not None:
        progress(post.model.name, done, steps)
    every = max(1, steps // 100)
    # -inf log probabilities of refusals: numpy's floating-point state, which is per thread
    # (warnings.catch_warnings is process-wide: chains on a threaded Dask worker undid each
    # other's filters, and ArviZ's advisories reached the user)
    try:
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            chain = sampler.sample(start, iterations=max(steps - done, 0))
            for i, _ in enumerate(chain, done + 1):
                if progress is not None and (i % every == 0 or i == steps):
                    progress(post.model.name, i, steps)
    except KeyboardInterrupt:
        raise CalibrationInterrupted(
            post.model.name, backend.iteration, steps, state is not None
        ) from None
    except BlockingIOError as exc:
        if state is None:  # only the HDF5 backend locks a file
            raise
        raise chain_in_use(state, exc, backend.iteration) from None
    return sampler
