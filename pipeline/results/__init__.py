"""Typed per-run results, and the datasets (run files) they are stored as.

:mod:`pipeline.runs` returns a :class:`TensileResult`, an
:class:`EngagementResult` or a :class:`WearResult` per run; :mod:`pipeline.campaign` stores it with
``to_dataset()`` (the store, :mod:`pipeline.store.netcdf`, only reads and
writes datasets) and reads a stored one back with ``from_dataset()``, so that
the campaign summary is built from the same types whether a run was processed
now or reused. The layouts are in ``docs/outputs.md``.
"""

from __future__ import annotations

import xarray as xr

from pipeline.results.engagement import EngagementResult
from pipeline.results.roller_engagement import RollerEngagementResult
from pipeline.results.segment_load import SegmentLoadResult
from pipeline.results.tensile import TensileResult
from pipeline.results.wear import WearResult

#: A run's result, by its kind (the run file's ``kind`` attribute).
RESULT_TYPES = {"tensile": TensileResult, "engagement": EngagementResult, "wear": WearResult,
                "roller-engagement": RollerEngagementResult,
                "segment-load": SegmentLoadResult}

RunResult = (TensileResult | EngagementResult | WearResult | RollerEngagementResult
             | SegmentLoadResult)


def result_from_dataset(dataset: xr.Dataset) -> RunResult:
    """The result a run file holds, of the type its ``kind`` attribute names.

    Parameters
    ----------
    dataset : xarray.Dataset
        A run file, loaded (:func:`pipeline.store.netcdf.read_dataset`).

    Raises
    ------
    KeyError
        When the dataset is no run file (no known ``kind``).
    """
    return RESULT_TYPES[str(dataset.attrs.get("kind"))].from_dataset(dataset)


__all__ = ["RESULT_TYPES", "EngagementResult", "RollerEngagementResult", "RunResult",
           "SegmentLoadResult", "TensileResult", "WearResult", "result_from_dataset"]
