"""Benchmark: engagement-event detection and N_u extraction on a 10^7-sample log.

Simulates a branch-tension log with the virtual engagement bench (Paper 000's
example: 18x64 chain, z = 8, psi = 40 deg, omega = 20 1/s, 20 kHz, SNR 10),
then times, on one core (BLAS limited to one thread), for the log with and
without its angle channel:

* :func:`pipeline.condition.engagement.detect_events` (detection),
* :func:`pipeline.fit.impact.extract_impacts` (extraction, including the
  per-run lmfit of the branch's ringing),

and, as the baseline measured in the same run on the same array, one plain
numpy pass over the force: ``np.abs(np.diff(force))``.

Prints the best of ``--repeat`` CPU times, the throughput in samples per second
(target: >= 2e7 for detection + extraction), its time as a multiple of the
baseline pass, the peak memory, and the recovered medians
against the truth; ``--json`` prints the figures as one JSON line instead::

    .venv/bin/python bench/bench_engagement.py              # 10^7 samples
    .venv/bin/python bench/bench_engagement.py --samples 1e6
"""

from __future__ import annotations

import os

for _variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")  # one core: set before numpy is imported

import argparse  # noqa: E402
import json  # noqa: E402
from typing import Any  # noqa: E402

import numpy as np  # noqa: E402
from _common import KIB, best_cpu_time, peak_kib  # noqa: E402

from pipeline.engagement_log import detect_events, extract_impacts  # noqa: E402
from pipeline.simulate.engagement import EngagementSettings, simulate_engagement  # noqa: E402

#: Target throughput of detection + extraction [samples/s] (docs/quality.md).
TARGET = 2e7

#: What the baseline is.
BASELINE = "np.abs(np.diff(force)), one numpy pass"


def measure(samples: float, rate: float, snr: float, repeat: int) -> dict[str, Any]:
    """Simulate the log and time the baseline, detection and extraction on it.

    Returns
    -------
    dict
        ``samples``, ``seatings``, ``baseline_seconds`` and per channel set
        (``"with_angle"``, ``"without_angle"``): ``source`` of the events,
        ``detection_seconds``, ``extraction_seconds``, ``samples_per_second``,
        ``excluded`` and per impact the ``median``, ``stderr``, ``count`` and
        ``truth`` [N]; all CPU times [s]; ``peak_mib``, the peak memory of the
        process (simulation included).
    """
    settings = EngagementSettings(sample_rate=rate, duration=(samples - 1) / rate, snr=snr)
    table, truth = simulate_engagement(settings, seed=1)
    force = table["force"].to_numpy()
    baseline, _ = best_cpu_time(lambda: np.abs(np.diff(force)), repeat)
    figures: dict[str, Any] = {"samples": len(table), "rate": rate, "snr": snr,
                               "seatings": int(truth["event_time"].size),
                               "baseline": BASELINE, "baseline_seconds": baseline}
    for label, channels in (("with_angle", ["time", "force", "angle"]),
                            ("without_angle", ["time", "force"])):
        log = table[channels]
        detection, events = best_cpu_time(
            lambda log=log: detect_events(log, z=settings.z, omega=settings.omega), repeat)
        extraction, result = best_cpu_time(
            lambda log=log, events=events: extract_impacts(log, events), repeat)
        figures[label] = {
            "source": events.source, "detection_seconds": detection,
            "extraction_seconds": extraction,
            "samples_per_second": len(table) / (detection + extraction),
            "excluded": int(sum(result.excluded.values())),
            **{name: {"median": float(result.statistics[name].median),
                      "stderr": float(result.statistics[name].stderr),
                      "count": int(result.statistics[name].count),
                      "truth": float(truth[name])} for name in ("N_u1", "N_u2")},
        }
    figures["peak_mib"] = peak_kib() / KIB
    return figures


def main() -> None:
    """Simulate, measure, print the figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=float, default=1e7, help="samples in the log")
    parser.add_argument("--rate", type=float, default=20e3, help="sampling rate [Hz]")
    parser.add_argument("--snr", type=float, default=10.0, help="N_u1 / noise std")
    parser.add_argument("--repeat", type=int, default=3, help="best of this many runs")
    parser.add_argument("--json", action="store_true", help="print the figures as JSON")
    args = parser.parse_args()
    figures = measure(args.samples, args.rate, args.snr, args.repeat)
    if args.json:
        print(json.dumps(figures))
        return
    samples, baseline = figures["samples"], figures["baseline_seconds"]
    print(f"log: {samples:.3g} samples at {args.rate:g} Hz ({samples / args.rate:g} s), "
          f"{figures['seatings']} seatings, SNR {args.snr:g}; one core")
    print(f"baseline ({BASELINE}): {baseline:.3f} s = {samples / baseline:.3g} samples/s")
    print(f"peak RSS {figures['peak_mib']:.0f} MiB (simulating the log included)")
    for label in ("with_angle", "without_angle"):
        run = figures[label]
        total = run["detection_seconds"] + run["extraction_seconds"]
        rate = run["samples_per_second"]
        print(f"\n{label.replace('_', ' ')} channel (events from the {run['source']}):")
        print(f"  detection  {run['detection_seconds']:.3f} s   extraction "
              f"{run['extraction_seconds']:.3f} s   total {total:.3f} s")
        print(f"  throughput {rate:.3g} samples/s (target >= {TARGET:.0e}: "
              f"{'met' if rate >= TARGET else 'NOT met'}); {total / baseline:.2f}x the "
              "baseline pass")
        for name in ("N_u1", "N_u2"):
            stats = run[name]
            print(f"  {name}: median {stats['median']:.2f} N +- {stats['stderr']:.2f} (truth "
                  f"{stats['truth']:.2f} N, {stats['median'] / stats['truth'] - 1:+.3%}), "
                  f"{stats['count']} events, excluded {run['excluded']}")


if __name__ == "__main__":
    main()
