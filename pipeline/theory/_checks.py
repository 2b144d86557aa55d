"""Domain checks shared by the theory modules.

A model never returns NaN silently for an invalid input: these helpers raise a
``ValueError`` that names the offending parameter.
"""

from __future__ import annotations

import numpy as np


def positive(name: str, value) -> np.ndarray:
    """Return `value` as a float array, raising if any element is not > 0."""
    array = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(array)) or np.any(array <= 0):
        raise ValueError(f"{name} must be a finite positive number, got {value!r}")
    return array


def non_negative(name: str, value) -> np.ndarray:
    """Return `value` as a float array, raising if any element is < 0."""
    array = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(array)) or np.any(array < 0):
        raise ValueError(f"{name} must be a finite number >= 0, got {value!r}")
    return array


def teeth(name: str, value, minimum: int = 3) -> np.ndarray:
    """Return a number of teeth as a float array, raising if not an integer >= `minimum`."""
    array = np.asarray(value, dtype=float)
    whole = np.all(np.isfinite(array)) and np.all(array == np.round(array))
    if not whole or np.any(array < minimum):
        raise ValueError(f"{name} must be a whole number of teeth >= {minimum}, got {value!r}")
    return array


def arcsin(name: str, argument) -> np.ndarray:
    """``np.arcsin`` that raises when the argument (derived from `name`) leaves [-1, 1]."""
    argument = np.asarray(argument, dtype=float)
    if np.any(np.abs(argument) > 1):
        raise ValueError(f"arcsin argument out of [-1, 1] for the given {name}: {argument!r}")
    return np.arcsin(argument)


def arccos(name: str, argument) -> np.ndarray:
    """``np.arccos`` that raises when the argument (derived from `name`) leaves [-1, 1]."""
    argument = np.asarray(argument, dtype=float)
    if np.any(np.abs(argument) > 1):
        raise ValueError(f"arccos argument out of [-1, 1] for the given {name}: {argument!r}")
    return np.arccos(argument)


def scalar_or_array(value: np.ndarray):
    """Return a Python float for 0-d results, the array otherwise."""
    return float(value) if np.ndim(value) == 0 else value
