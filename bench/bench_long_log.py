"""Benchmark: a 10^8-sample engagement log processed from its file, chunk by chunk.

Two figures (docs/quality.md):

* **Memory of a long log.** A log of ``--samples`` samples (10^8 by default,
  10^7 with ``--quick``) is written as CSV and as TDMS, then processed in a
  fresh interpreter from the file: :func:`pipeline.ingest.open_log` and
  :func:`pipeline.engagement_log.analyse_log` with chunks of ``--chunk``
  samples. Printed: wall time, throughput, the process's peak resident memory
  against the 1 GiB target, and the events found.
* **Same result.** A 10^6-sample log read chunk by chunk from each file
  against the whole-log path on the table in memory (one chunk): events,
  statuses and the largest relative N_u difference (target: the same events,
  N_u within 1e-6).

The long log tiles a simulated piece of 2400 seating periods (300 whole turns
of the 8-tooth wheel at a seating period of exactly 40 ms, 10 kHz), its times
running on, so the angle and the seatings continue across the joins (the
ringing restarts at each join: a handful of events there may be excluded).
Files go to ``--folder`` (default: a temporary folder, removed afterwards)::

    .venv/bin/python bench/bench_long_log.py            # 10^8 samples: ~3 GB CSV, ~2 GB TDMS
    .venv/bin/python bench/bench_long_log.py --quick    # 10^7 samples
"""

from __future__ import annotations

import os

for _variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")  # one core: set before numpy is imported

import argparse  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from _common import KIB, peak_kib, run_json  # noqa: E402

#: Peak resident memory allowed while a long log is processed [MiB].
MEMORY_TARGET_MIB = 1024
#: Largest relative N_u difference between the file read in chunks and the whole log.
SAME_TARGET = 1e-6
#: Seating periods in the simulated piece the long log tiles: whole turns of the wheel.
PIECE_PERIODS = 2400
#: Seating period [s], teeth and sampling rate of the simulated log.
PERIOD, TEETH, RATE = 0.04, 8, 10e3


def settings(duration: float):
    """The virtual bench's settings: Paper 000's example chain, a 40 ms seating period."""
    from pipeline.simulate.engagement import EngagementSettings

    return EngagementSettings(z=TEETH, omega=2 * math.pi / (TEETH * PERIOD), sample_rate=RATE,
                              duration=duration, snr=10.0)


def piece():
    """The simulated piece: time [s], force [N], angle [rad] of PIECE_PERIODS periods."""
    from pipeline.simulate.engagement import simulate_engagement

    rows = int(round(PIECE_PERIODS * PERIOD * RATE))
    table = simulate_engagement(settings(rows / RATE), seed=1)[0].iloc[:rows]
    return table["force"].to_numpy(), table["angle"].to_numpy()


def write_long_log(folder: Path, samples: int) -> dict[str, Path]:
    """Write the tiled log of `samples` samples as CSV and TDMS; return their paths."""
    import pyarrow as pa
    import pyarrow.csv as pa_csv
    from nptdms import ChannelObject, GroupObject, RootObject, TdmsWriter

    from pipeline.simulate.engagement import TDMS_CHANNELS, TDMS_GROUP

    force, angle = piece()
    paths = {"csv": folder / "long.csv", "tdms": folder / "long.tdms"}
    with paths["csv"].open("wb") as csv, TdmsWriter(paths["tdms"]) as tdms:
        csv.write(b"time [s],force [N],angle [rad]\n")
        for first in range(0, samples, force.size):
            rows = min(force.size, samples - first)
            times = (first + np.arange(rows)) / RATE
            pa_csv.write_csv(pa.table({"time": times, "force": force[:rows],
                                       "angle": angle[:rows]}), csv,
                             pa_csv.WriteOptions(include_header=False))
            properties = {"wf_start_offset": 0.0, "wf_increment": 1 / RATE,
                          "wf_samples": rows}
            objects = [ChannelObject(TDMS_GROUP, TDMS_CHANNELS["force"], force[:rows],
                                     properties={**properties, "unit_string": "N"}),
                       ChannelObject(TDMS_GROUP, TDMS_CHANNELS["angle"], angle[:rows],
                                     properties={**properties, "unit_string": "rad"})]
            if first == 0:
                objects = [RootObject({"title": "chainbench long-log benchmark"}),
                           GroupObject(TDMS_GROUP), *objects]
            tdms.write_segment(objects)
    return paths


def worker(path: Path, chunk: int) -> None:
    """Process `path` chunk by chunk; print wall time, peak memory and events as JSON."""
    from pipeline.engagement_log import analyse_log
    from pipeline.ingest import open_log

    start = time.perf_counter()
    source = open_log(path, kind="engagement")
    s = settings(1.0)
    analysis = analyse_log(source, z=s.z, omega=s.omega, chunk_samples=chunk,
                           preview_samples=200_000, file=path)
    impacts = analysis.impacts
    print(json.dumps({
        "seconds": time.perf_counter() - start, "peak_mib": peak_kib() / KIB,
        "samples": source.n_rows, "events": analysis.events.count,
        "ok": impacts.N_u2.count, "excluded": impacts.excluded,
        "N_u2_median": impacts.N_u2.median}))


def same_result(folder: Path, chunk: int) -> dict[str, dict]:
    """The 10^6-sample log from each file, in chunks, against the whole log in memory."""
    from pipeline.engagement_log import TableSource, analyse_log
    from pipeline.ingest import open_log

    paths = write_long_log(folder, 1_000_000)
    s = settings(1.0)
    table = open_log(paths["csv"], kind="engagement")
    whole = analyse_log(TableSource(table.read(0, table.n_rows)[0]), z=s.z, omega=s.omega)
    figures = {}
    for kind, path in paths.items():
        chunked = analyse_log(open_log(path, kind="engagement"), z=s.z, omega=s.omega,
                              chunk_samples=chunk // 4, file=path)
        a, b = whole.impacts.events, chunked.impacts.events
        same_events = len(a) == len(b) and list(a["status"]) == list(b["status"])
        difference = (float(np.nanmax(np.abs(b[["N_u1", "N_u2"]].to_numpy()
                                             / a[["N_u1", "N_u2"]].to_numpy() - 1)))
                      if same_events else math.inf)
        figures[kind] = {"events": [len(a), len(b)], "same_events": same_events,
                         "max_relative_difference": difference}
    for path in paths.values():
        path.unlink()
    return figures


def main() -> None:
    """Write the logs, process them in fresh interpreters, print the figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=float, default=1e8, help="samples in the long log")
    parser.add_argument("--quick", action="store_true", help="10^7 samples")
    parser.add_argument("--chunk", type=float, default=1e6, help="samples per chunk")
    parser.add_argument("--folder", type=Path, help="where the logs are written")
    parser.add_argument("--worker", type=Path, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        worker(args.worker, int(args.chunk))
        return
    samples = int(1e7 if args.quick else args.samples)
    with tempfile.TemporaryDirectory(dir=args.folder) as temporary:
        folder = Path(temporary)
        print(f"same result, a 10^6-sample log in chunks of {int(args.chunk) // 4} (target: same "
              f"events, N_u within {SAME_TARGET:g}):")
        for kind, figures in same_result(folder, int(args.chunk)).items():
            verdict = ("met" if figures["same_events"]
                       and figures["max_relative_difference"] <= SAME_TARGET else "MISSED")
            print(f"  {kind:4s}: events {figures['events'][0]} / {figures['events'][1]}, largest "
                  f"relative N_u difference {figures['max_relative_difference']:.1e}  {verdict}")
        started = time.perf_counter()
        paths = write_long_log(folder, samples)
        print(f"\nlong log: {samples:.3g} samples written in {time.perf_counter() - started:.0f} s "
              + ", ".join(f"{kind} {path.stat().st_size / KIB**3:.2f} GiB"
                          for kind, path in paths.items()))
        for kind, path in paths.items():
            figures = run_json([sys.executable, __file__, "--worker", str(path),
                                "--chunk", str(int(args.chunk))])
            verdict = "met" if figures["peak_mib"] < MEMORY_TARGET_MIB else "MISSED"
            print(f"  {kind:4s}: {figures['seconds']:.0f} s "
                  f"({figures['samples'] / figures['seconds']:.3g} samples/s), peak memory "
                  f"{figures['peak_mib']:.0f} MiB (target < {MEMORY_TARGET_MIB} MiB)  {verdict}; "
                  f"{figures['events']} events, {figures['ok']} ok, excluded "
                  f"{ {k: v for k, v in figures['excluded'].items() if v} }, "
                  f"N_u2 median {figures['N_u2_median']:.5g} N")


if __name__ == "__main__":
    main()
