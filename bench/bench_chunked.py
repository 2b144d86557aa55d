"""Benchmark: chunked against whole-log event detection and N_u extraction, 10^7 samples.

Simulates a branch-tension log with the virtual engagement bench (Paper 000's
example: 18x64 chain, z = 8, psi = 40 deg, omega = 20 1/s, 20 kHz, SNR 10),
then, for the log with and without its angle channel, on one core (BLAS
limited to one thread):

* the baseline, measured in the same run on the same table:
  :func:`pipeline.engagement_log.analyse_log` with the whole log as one chunk;
* the same with chunks of ``--chunk`` samples.

Prints the best of ``--repeat`` CPU times and the throughput [samples/s] of
each, the chunked throughput as a ratio of the baseline's, the peak memory
each call allocates on top of the decoded log (tracemalloc, which numpy reports
its arrays to; measured in a separate call, untimed) and its ratio, log plus
that peak over the decoded arrays (docs/quality.md: under 3x on a 10^7-sample log),
and how far the two results differ (events, largest relative N_u difference);
``--json`` prints the figures as one JSON line instead::

    .venv/bin/python bench/bench_chunked.py                     # 10^7 samples, 10^6 a chunk
    .venv/bin/python bench/bench_chunked.py --samples 2e6 --chunk 250000
"""

from __future__ import annotations

import os

for _variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")  # one core: set before numpy is imported

import argparse  # noqa: E402
import json  # noqa: E402
import tracemalloc  # noqa: E402
from collections.abc import Callable  # noqa: E402
from typing import Any  # noqa: E402

import numpy as np  # noqa: E402
from _common import KIB, best_cpu_time, peak_kib  # noqa: E402

from pipeline.engagement_log import TableSource, analyse_log  # noqa: E402
from pipeline.fit.impact import ImpactResult  # noqa: E402
from pipeline.simulate.engagement import EngagementSettings, simulate_engagement  # noqa: E402

#: Largest peak memory over the decoded arrays of a 10^7-sample log (docs/quality.md).
MEMORY_TARGET = 3.0


def added_peak_mib(function: Callable[[], Any]) -> float:
    """Peak memory [MiB] a call of `function` allocates on top of what exists (tracemalloc).

    numpy reports its arrays to :mod:`tracemalloc`, so this is the peak of the
    arrays and objects the call holds at once, whatever the allocator keeps.
    """
    tracemalloc.start()
    try:
        function()
        return tracemalloc.get_traced_memory()[1] / KIB**2
    finally:
        tracemalloc.stop()


def measure(samples: float, rate: float, snr: float, chunk: int, repeat: int) -> dict[str, Any]:
    """Simulate the log; time and weigh both paths on it, with and without the angle.

    Returns
    -------
    dict
        ``samples``, ``chunk`` and per channel set (``"with_angle"``,
        ``"without_angle"``): ``decoded_mib`` (the log's arrays), ``whole`` and
        ``chunked``, each with ``seconds`` (best CPU time [s]),
        ``samples_per_second`` and ``added_peak_mib``; ``throughput_ratio``
        (chunked over whole), ``memory_ratio`` (chunked over whole), ``events``
        and ``max_relative_difference`` of N_u1, N_u2 between the two; and
        ``process_peak_mib``, the process's peak (simulation included).
    """
    settings = EngagementSettings(sample_rate=rate, duration=(samples - 1) / rate, snr=snr)
    table = simulate_engagement(settings, seed=1)[0]
    z, omega = settings.z, settings.omega
    figures: dict[str, Any] = {"samples": len(table), "rate": rate, "snr": snr, "chunk": chunk}
    for label, channels in (("with_angle", ["time", "force", "angle"]),
                            ("without_angle", ["time", "force"])):
        log = table[channels]
        paths: dict[str, Callable[[], ImpactResult]] = {
            "whole": lambda log=log: analyse_log(TableSource(log), z=z, omega=omega).impacts,
            "chunked": lambda log=log: analyse_log(TableSource(log), z=z, omega=omega,
                                                   chunk_samples=chunk).impacts,
        }
        run: dict[str, Any] = {"decoded_mib": log.memory_usage(index=False).sum() / KIB**2}
        results = {}
        for name, path in paths.items():
            seconds, results[name] = best_cpu_time(path, repeat)
            run[name] = {"seconds": seconds, "samples_per_second": len(log) / seconds,
                         "added_peak_mib": added_peak_mib(path)}
        whole, chunked = results["whole"].events, results["chunked"].events
        run["throughput_ratio"] = (run["chunked"]["samples_per_second"]
                                   / run["whole"]["samples_per_second"])
        run["memory_ratio"] = run["chunked"]["added_peak_mib"] / run["whole"]["added_peak_mib"]
        run["events"] = [len(whole), len(chunked)]
        run["max_relative_difference"] = (
            float(np.nanmax(np.abs(chunked[["N_u1", "N_u2"]].to_numpy()
                                   / whole[["N_u1", "N_u2"]].to_numpy() - 1)))
            if len(whole) == len(chunked) else None)
        figures[label] = run
    figures["process_peak_mib"] = peak_kib() / KIB
    return figures


def main() -> None:
    """Simulate, measure, print the figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=float, default=1e7, help="samples in the log")
    parser.add_argument("--rate", type=float, default=20e3, help="sampling rate [Hz]")
    parser.add_argument("--snr", type=float, default=10.0, help="N_u1 / noise std")
    parser.add_argument("--chunk", type=float, default=1e6, help="samples per chunk")
    parser.add_argument("--repeat", type=int, default=3, help="best of this many runs")
    parser.add_argument("--json", action="store_true", help="print the figures as JSON")
    args = parser.parse_args()
    figures = measure(args.samples, args.rate, args.snr, int(args.chunk), args.repeat)
    if args.json:
        print(json.dumps(figures))
        return
    print(f"log: {figures['samples']:.3g} samples at {args.rate:g} Hz; chunks of "
          f"{figures['chunk']:.3g} samples; one core")
    for label in ("with_angle", "without_angle"):
        run = figures[label]
        decoded = run["decoded_mib"]
        print(f"\n{label.replace('_', ' ')} channel (decoded arrays {decoded:.0f} MiB):")
        for name in ("whole", "chunked"):
            path = run[name]
            print(f"  {name:8s} {path['seconds']:.3f} s  {path['samples_per_second']:.3g} "
                  f"samples/s  peak +{path['added_peak_mib']:.0f} MiB "
                  f"(log + peak = {1 + path['added_peak_mib'] / decoded:.2f}x the decoded "
                  f"arrays; target < {MEMORY_TARGET:g}x)")
        print(f"  chunked / whole: throughput {run['throughput_ratio']:.2f}x, added peak "
              f"memory {run['memory_ratio']:.2f}x")
        difference = run["max_relative_difference"]
        print(f"  events {run['events'][0]} / {run['events'][1]}, largest relative N_u "
              f"difference {'n/a' if difference is None else f'{difference:.1e}'}")
    print(f"\nprocess peak {figures['process_peak_mib']:.0f} MiB (simulating the log included)")


if __name__ == "__main__":
    main()
