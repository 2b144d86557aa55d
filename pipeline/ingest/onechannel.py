"""Files of one channel's samples, one a line, under a header that states their sampling
(an ISO-MME channel file, a LineScale dynamometer's log): the time is built, not read."""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import replace

import numpy as np

from pipeline.ingest.delimited import TextLayout, read_contiguous
from pipeline.ingest.raw import RawTable
from pipeline.ingest.roles import Candidates
from pipeline.ingest.sniff import Head, TableSpec, is_number


def settings_over_samples(head: Head, setting: re.Pattern, lead: bool = False
                          ) -> tuple[dict[str, str], int | None]:
    """The header's settings, each a line `setting` matches whole (groups ``key`` and
    ``value``; keys folded, both stripped), and the index of the first sample's line, the
    first of one number after them (None when another line follows them). Lines before
    the first setting are passed over when `lead` (a device's name, a date), else they end
    the header."""
    settings: dict[str, str] = {}
    for index, line in enumerate(head.lines):
        found = setting.fullmatch(line.strip())
        if found is not None:
            settings[found["key"].strip().casefold()] = found["value"].strip()
        elif is_number(line.strip(), ".") and (settings or not lead):
            return settings, index
        elif line.strip() and (settings or not lead):
            return settings, None
    return settings, None


def read_samples(layout: TextLayout, head: Head, spec: TableSpec, columns: Mapping | None,
                 start: float, interval: float) -> RawTable:
    """Read the samples of a file sniffed as `head` / `spec` (two columns: the time, then
    the channel the file holds) in `layout`, the time of the i-th being ``start + i ·
    interval`` [s]."""
    header = layout.header(head, spec, columns)
    samples = replace(spec, names=spec.names[1:], units=spec.units[1:], width=1)
    channel = replace(header, names=header.names[1:], units=header.units[1:], candidates=(
        Candidates({"channel": [0]}, frozenset()) if 1 in header.candidates.indexes()
        else Candidates({}, frozenset())))
    read = read_contiguous(head, samples, channel)
    arrays = {0: start + interval * np.arange(read.rows)}
    if 0 in read.arrays:
        arrays[1] = read.arrays[0]
    return header.table(arrays=arrays, rows=read.rows, line_of=read.line_of)
