#!/usr/bin/env python3
"""What a call from Python costs on top of the C++ call it makes, and what the
released GIL buys: prints two tables (docs/python.md, "From Python").

  PYTHONPATH=build/python /usr/bin/python3 scripts/benchmarks/python_overhead.py \\
      --sim-benchmark build/tests/benchmarks/railjoint_sim_benchmark \\
      --models-benchmark build/tests/benchmarks/railjoint_models_benchmark

Per call, on the default scene (scenes/default.toml): railjoint.analytic()
against predict_impact() and railjoint.simulate() against simulate_crossing()
(Google Benchmark, the same scene and settings). Each side is timed in several
repetitions and the fastest repetition kept, the usual estimate of a call's
cost on a machine shared with other work. Then N simulations on one Python
thread and the same N split over two threads: with the GIL released they run
side by side on two cores.
"""

import argparse
import json
import os
import subprocess
import threading
import time
from pathlib import Path

import railjoint

SOURCE_DIR = Path(os.environ.get("RAILJOINT_SOURCE_DIR", Path(__file__).resolve().parents[2]))


def best_seconds_per_call(call, calls, repetitions):
    """Fastest repetition of `calls` calls, per call [s]."""
    best = float("inf")
    for _ in range(repetitions):
        start = time.perf_counter()
        for _ in range(calls):
            call()
        best = min(best, (time.perf_counter() - start) / calls)
    return best


def cpp_seconds_per_call(executable, name, repetitions):
    """Google Benchmark's fastest repetition of benchmark `name`, per iteration [s]."""
    out = subprocess.run([executable, f"--benchmark_filter=^{name}$", "--benchmark_format=json",
                          f"--benchmark_repetitions={repetitions}", "--benchmark_min_time=0.2"],
                         capture_output=True, text=True, check=True).stdout
    units = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
    runs = [b for b in json.loads(out)["benchmarks"] if b.get("run_type") == "iteration"]
    return min(b["real_time"] * units[b["time_unit"]] for b in runs)


def threads_wall_seconds(scene, crossings, threads):
    """Wall time of `crossings` simulations split over `threads` Python threads [s]."""
    share = crossings // threads

    def work():
        for _ in range(share):
            railjoint.simulate(scene)

    workers = [threading.Thread(target=work) for _ in range(threads)]
    start = time.perf_counter()
    for worker in workers:
        worker.start()
    for worker in workers:
        worker.join()
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sim-benchmark", required=True, help="railjoint_sim_benchmark executable")
    parser.add_argument("--models-benchmark", required=True, help="railjoint_models_benchmark executable")
    parser.add_argument("--repetitions", type=int, default=7)
    args = parser.parse_args()

    scene = railjoint.load_scene(SOURCE_DIR / "scenes" / "default.toml")
    railjoint.simulate(scene)  # the scene's model check, read once and kept
    rows = []
    py_analytic = best_seconds_per_call(lambda: railjoint.analytic(scene), 20000, args.repetitions)
    cpp_analytic = cpp_seconds_per_call(args.models_benchmark, "BM_PredictScenario2", args.repetitions)
    rows.append(("analytic(scene)", "predict_impact", cpp_analytic, py_analytic))
    py_simulate = best_seconds_per_call(lambda: railjoint.simulate(scene), 300, args.repetitions)
    cpp_simulate = cpp_seconds_per_call(args.sim_benchmark, "simulate_crossing/default", args.repetitions)
    rows.append(("simulate(scene)", "simulate_crossing", cpp_simulate, py_simulate))
    prediction = railjoint.analytic(scene)
    run = railjoint.simulate(scene)
    extras = [
        ("analytic(scene).as_dict()", best_seconds_per_call(prediction.as_dict, 2000, args.repetitions)),
        ("simulate(scene).as_dict()", best_seconds_per_call(run.as_dict, 300, args.repetitions)),
        ("simulate(scene).trajectory (first use)",
         best_seconds_per_call(lambda: railjoint.simulate(scene).trajectory, 300, args.repetitions) - py_simulate),
        ("load_scene(default.toml)",
         best_seconds_per_call(lambda: railjoint.load_scene(SOURCE_DIR / "scenes" / "default.toml"), 2000,
                               args.repetitions)),
    ]

    print("| call (default scene) | C++ call | C++ [us] | Python [us] | overhead [us] |")
    print("|---|---|---:|---:|---:|")
    for python_call, cpp_call, cpp_s, py_s in rows:
        print(f"| `railjoint.{python_call}` | `{cpp_call}` | {cpp_s * 1e6:.2f} | {py_s * 1e6:.2f} | "
              f"{(py_s - cpp_s) * 1e6:+.2f} |")
    print()
    print("| extra, on demand | Python [us] |")
    print("|---|---:|")
    for name, seconds in extras:
        print(f"| `{name}` | {seconds * 1e6:.1f} |")
    print()

    crossings = 2000
    one = min(threads_wall_seconds(scene, crossings, 1) for _ in range(3))
    two = min(threads_wall_seconds(scene, crossings, 2) for _ in range(3))
    print(f"| {crossings} simulate() calls | wall [s] | crossings/s | speed-up |")
    print("|---|---:|---:|---:|")
    print(f"| 1 Python thread | {one:.3f} | {crossings / one:.0f} | 1.00 |")
    print(f"| 2 Python threads | {two:.3f} | {crossings / two:.0f} | {one / two:.2f} |")


if __name__ == "__main__":
    main()
