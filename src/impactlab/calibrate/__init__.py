"""Calibration from measurements: which model and which parameters explain measured drops, with
their uncertainty (docs/calibrate.md).

``calibrate(measurements, parameters, models)`` samples each candidate model's posterior with
emcee on the compiled batch engine (every walker on every drop in one call), checks it against
every measured value and ranks the models by PSIS-LOO.
"""

from impactlab.calibrate.api import Calibration, CalibrationWarning, calibrate, parse_model
from impactlab.calibrate.drop_predictions import DropPredictions
from impactlab.calibrate.measurements import Measurements, read_measurements
from impactlab.calibrate.models import CandidateModel, Prediction, predict
from impactlab.calibrate.priors import Parameter, parse_parameter
from impactlab.calibrate.quantities import MEASURABLE
from impactlab.calibrate.result import ModelPosterior

__all__ = [
    "MEASURABLE",
    "Calibration",
    "CalibrationWarning",
    "CandidateModel",
    "DropPredictions",
    "Measurements",
    "ModelPosterior",
    "Parameter",
    "Prediction",
    "calibrate",
    "parse_model",
    "parse_parameter",
    "predict",
    "read_measurements",
]
