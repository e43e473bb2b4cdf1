"""The warning class of calibrations (its own module: every calibration module may issue it)."""

__all__ = ["CalibrationWarning"]


class CalibrationWarning(UserWarning):
    """Something the calibration ran through but the user should know (a parameter a model
    does not use, a drop value replaced by a free parameter, a misfit, a chain that has not
    converged, a posterior against its prior's bound, a contact law extrapolated in the
    predicted impacts, a model that fails on more than 5 % of the parameter values it ran, a
    best model the data do not single out, a ranking over one drop)."""
