"""Which of the specimens in one file a run reads (the run sheet's ``specimen_in_file``).

A file may hold several specimens: their columns side by side (a Shimadzu
multi-specimen export) or their tables one below the other (an Instron Merlin
sample). A run reads one, named by its label or by its place from 1; a file
of several read without saying which is refused, listing them, so that
``chainbench init`` can draft one run per specimen.
"""

from __future__ import annotations

import json

from pipeline.errors import LayoutError, SpecimensError


def choose(labels: list[str], count: int, specimen: str | int | None, said: str,
           order: str, *, file: str | None, row: int | None) -> int:
    """The index (from 0) of the specimen `specimen` names, of the `count` in a file.

    Parameters
    ----------
    labels : list of str
        The specimens' labels as the file writes them, or none (then only places
        name them).
    count : int
        How many specimens the file holds.
    specimen : str or int, optional
        The run sheet's ``specimen_in_file``: a label, or a place from 1.
    said : str
        What the file holds, for the messages (``"the file holds 3 specimens ..."``).
    order : str
        Where the places count from (``"from the left"``, ``"from the top"``).
    file, row
        Where the messages point.

    Raises
    ------
    LayoutError
        When the file holds one specimen and `specimen` is given, or `specimen`
        names none of them.
    SpecimensError
        When the file holds several and `specimen` is None.
    """
    if count == 1:
        if specimen is not None:
            raise LayoutError(
                f"specimen_in_file = {json.dumps(specimen)}, but the file holds one specimen",
                file=file, row=row,
                hint="specimen_in_file is for a file that holds several specimens: leave it "
                     "out")
        return 0
    places = [str(place) for place in range(1, count + 1)]
    shown = [*labels[:3], "...", labels[-1]] if len(labels) > 4 else labels
    choices = (f"specimen_in_file = {json.dumps(labels[0] if labels else 1)}: "
               + (f"the file's labels {', '.join(shown)}, or " if labels else "")
               + f"the places 1 to {count} {order}")
    if specimen is None:
        raise SpecimensError(
            said, specimens=labels or places, file=file, row=row,
            hint=f"say which one a run reads in the run sheet ({choices}; one run per "
                 "specimen may name the same file; chainbench inspect --specimen shows "
                 "one), or export each specimen to a file of its own")
    if specimen in labels:
        return labels.index(specimen)
    if str(specimen) in places:
        return places.index(str(specimen))
    raise LayoutError(f"{said}, none of them {json.dumps(specimen)}", file=file, row=row,
                      hint=f"name one: {choices}")
