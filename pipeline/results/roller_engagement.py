"""The result of one roller-engagement run, and its dataset: the run file ``<run id>.nc``.

A roller chain's engagement log is read by the one engagement pipeline as a
wheel of half the sprocket's teeth
(:func:`pipeline.fit.roller_engagement.engagement_teeth`): its run file has
the layout of an engagement run's (:mod:`pipeline.results.engagement`), where
``N_u1`` and ``N_u2`` are the amplitudes of two successive roller strikes, and
beside it the run's strike amplitude, both slots pooled
(:func:`pipeline.fit.roller_engagement.strike_statistics`): ``strike_amplitude``
(the median), ``strike_amplitude_iqr``, ``strike_amplitude_stderr`` [N] and
``strike_count``. The global attributes add ``sprocket``, ``sprocket_teeth``
and ``engagement_teeth`` (the teeth the pipeline was given).
"""

from __future__ import annotations

from dataclasses import dataclass

import xarray as xr

from pipeline.fit.roller_engagement import strike_statistics
from pipeline.results.engagement import EngagementResult
from pipeline.statistics import MedianStatistics

#: The pooled strike statistics stored: field of :class:`MedianStatistics`, variable
#: name, units and long name.
STRIKE_VARIABLES = (
    ("median", "strike_amplitude", "N", "roller strike amplitude: median over both strikes "
                                        "of every valid seating"),
    ("iqr", "strike_amplitude_iqr", "N", "interquartile range of the strike amplitudes"),
    ("stderr", "strike_amplitude_stderr", "N", "standard error of strike_amplitude"),
    ("count", "strike_count", "1", "strikes pooled"),
)


@dataclass(frozen=True, eq=False)
class RollerEngagementResult(EngagementResult):
    """What one roller-engagement run gave: an engagement result whose two impact slots
    are two successive roller strikes (fields as :class:`EngagementResult`)."""

    @property
    def strike(self) -> MedianStatistics:
        """The run's strike amplitude, both slots of every valid seating pooled [N]."""
        return strike_statistics(self.impact)

    def to_dataset(self) -> xr.Dataset:
        """The run file: an engagement run's and the pooled strike amplitude."""
        dataset = super().to_dataset()
        strike = self.strike
        for field, name, units, text in STRIKE_VARIABLES:
            dataset[name] = ((), float(getattr(strike, field)),
                             {"units": units, "long_name": text})
        return dataset
