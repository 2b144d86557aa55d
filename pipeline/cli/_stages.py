"""Loading the stages into a command-line process: once, without the collector's passes.

Importing :mod:`pipeline.campaign` (numpy, scipy, pandas, xarray, lmfit,
matplotlib and the stages) creates about half a million objects that live as
long as the process. With the garbage collector running, each of its full
passes during the import walks every object created so far (about 0.2 s of a
1.5 s import), and every full pass afterwards walks them again. Paused for the
import, and with what the import created frozen out of its reach
(:func:`gc.freeze`), the collector only ever looks at what the runs create.

Only processes the command line owns load the stages this way (the command's
own process and the local cluster's workers): a library caller's process keeps
its collector as it is.
"""

from __future__ import annotations

import gc
import sys
from types import ModuleType


def load_stages() -> ModuleType:
    """:mod:`pipeline.campaign`, imported with the garbage collector paused if not yet loaded."""
    loaded = sys.modules.get("pipeline.campaign")
    if loaded is not None:
        return loaded
    enabled = gc.isenabled()
    gc.disable()
    try:
        import pipeline.campaign
    finally:
        gc.freeze()
        if enabled:
            gc.enable()
    return pipeline.campaign
