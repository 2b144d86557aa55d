"""Benchmark: engagement-event detection and N_u extraction on a 10^7-sample log.

Simulates a branch-tension log with the virtual engagement bench (Paper 000's
example: 18x64 chain, z = 8, psi = 40 deg, omega = 20 1/s, 20 kHz, SNR 10),
then times, on one core (BLAS limited to one thread), for the log with and
without its angle channel:

* :func:`pipeline.condition.engagement.detect_events` (detection),
* :func:`pipeline.fit.impact.extract_impacts` (extraction, including the
  per-run lmfit of the branch's ringing),

and, as the baseline measured in the same run on the same array, one pass of
a second-order IIR filter (:func:`scipy.signal.lfilter`) over the force.

Prints the best of ``--repeat`` CPU times, the throughput in samples per second
(target: >= 2e7 for detection + extraction), its ratio to the baseline pass,
and the recovered medians against the truth::

    .venv/bin/python bench/bench_engagement.py              # 10^7 samples
    .venv/bin/python bench/bench_engagement.py --samples 1e6
"""

from __future__ import annotations

import os

for _variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")  # one core: set before numpy is imported

import argparse  # noqa: E402
import time  # noqa: E402

from scipy.signal import lfilter  # noqa: E402

from pipeline.condition.engagement import detect_events  # noqa: E402
from pipeline.fit.impact import extract_impacts  # noqa: E402
from pipeline.simulate.engagement import EngagementSettings, simulate_engagement  # noqa: E402

#: Target throughput of detection + extraction [samples/s] (quality.md).
TARGET = 2e7


def best_cpu_time(function, repeat: int):
    """Best CPU time [s] of `repeat` calls of `function` and its last result."""
    best, result = float("inf"), None
    for _ in range(repeat):
        start = time.process_time()
        result = function()
        best = min(best, time.process_time() - start)
    return best, result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=float, default=1e7, help="samples in the log")
    parser.add_argument("--rate", type=float, default=20e3, help="sampling rate [Hz]")
    parser.add_argument("--snr", type=float, default=10.0, help="N_u1 / noise std")
    parser.add_argument("--repeat", type=int, default=3, help="best of this many runs")
    args = parser.parse_args()

    settings = EngagementSettings(sample_rate=args.rate, duration=(args.samples - 1) / args.rate,
                                  snr=args.snr)
    table, truth = simulate_engagement(settings, seed=1)
    samples = len(table)
    force = table["force"].to_numpy()
    filter_a = [1.0, -1.9, 0.95]
    baseline, _ = best_cpu_time(lambda: lfilter([1.0], filter_a, force), args.repeat)
    print(f"log: {samples:.3g} samples at {args.rate:g} Hz ({samples / args.rate:g} s), "
          f"{truth['event_time'].size} seatings, SNR {args.snr:g}; one core")
    print(f"baseline (lfilter, one pass over the force): {baseline:.3f} s "
          f"= {samples / baseline:.3g} samples/s")
    for channels in (("time", "force", "angle"), ("time", "force")):
        log = table[list(channels)]
        detection, events = best_cpu_time(
            lambda log=log: detect_events(log, z=settings.z, omega=settings.omega), args.repeat)
        extraction, result = best_cpu_time(
            lambda log=log, events=events: extract_impacts(log, events), args.repeat)
        total = detection + extraction
        rate = samples / total
        print(f"\n{'with' if 'angle' in channels else 'without'} angle channel "
              f"(events from the {events.source}):")
        print(f"  detection  {detection:.3f} s   extraction {extraction:.3f} s   "
              f"total {total:.3f} s")
        print(f"  throughput {rate:.3g} samples/s (target >= {TARGET:.0e}: "
              f"{'met' if rate >= TARGET else 'NOT met'}); {total / baseline:.2f}x the "
              "baseline pass")
        for name in ("N_u1", "N_u2"):
            stats = result.statistics[name]
            print(f"  {name}: median {stats.median:.2f} N +- {stats.stderr:.2f} (truth "
                  f"{truth[name]:.2f} N, {stats.median / truth[name] - 1:+.3%}), "
                  f"{stats.count} events, excluded {sum(result.excluded.values())}")


if __name__ == "__main__":
    main()
