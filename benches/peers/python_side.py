#!/usr/bin/env python3
"""stormer from Python against the same run from Rust and against REBOUND from Python.

1. The outer solar system (docs/scenes.md 4) in the Kepler split (Jacobi coordinates) with
   `wisdom_holman`, integrated over 10^5 days at the scene's step (10 days):
   - ours from Python: `stormer.Simulation.from_scene("outer-solar-system")`, `integrate(1e5)`;
   - ours from Rust: `app/examples/in_process_run.rs`, the same run (`cli::in_process::run`, the
     code under `Simulation.integrate`) without Python;
   - REBOUND WHFast from Python: the same bodies, `sim.dt = 10`, `sim.integrate(1e5)` with
     REBOUND's defaults (safe_mode 1: every step synchronized, as ours; exact finish time),
     and with safe_mode 0 (its half drifts of consecutive steps merged) for reference.
   Interleaved rounds; each figure is the minimum over the rounds (each round best of REPS).
2. An ensemble of 1681 free-kick runs (alpha 10..50 x spin 0..20, 41 x 41) from Python,
   `stormer.ensemble(..., jobs=1)` against `jobs=2`: the speedup of two threads, and the cores
   the run had (its processor time over its wall time: about 2 when both threads ran at once;
   on a machine busy with other work, less, and the speedup with it).

Run: bash benches/peers/run.sh python [--rounds N] [--reps N] [--ensemble-rounds N]
     (or, with stormer and REBOUND installed in one environment and the example built:
      python3 benches/peers/python_side.py [--rounds N])
Writes out/peers/python.md.
"""
import argparse
import json
import os
import subprocess
import sys
import time

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _HERE]
import rebound  # noqa: E402
import stormer  # noqa: E402

sys.path.insert(0, _HERE)
from common import G, MASSES, POSITIONS, VELOCITIES, load, write_report  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(_HERE))
EXAMPLE = os.path.join(ROOT, "target", "release", "examples", "in_process_run")
SPAN = 1e5
DT = 10.0


def best(run, reps):
    """The least wall time of `reps` calls of `run()`."""
    times = []
    for _ in range(reps):
        times.append(run())
    return min(times)


def ours_python():
    sim = stormer.Simulation.from_scene("outer-solar-system", method="wisdom_holman", split="kepler-jacobi")
    assert sim.dt == DT
    start = time.perf_counter()
    summary = sim.integrate(SPAN)
    seconds = time.perf_counter() - start
    assert summary["steps"] == SPAN / DT, summary
    return seconds


def ours_rust(reps):
    out = subprocess.run([EXAMPLE, "--t-end", repr(SPAN), "--reps", str(reps)], check=True,
                         capture_output=True, text=True)
    result = json.loads(out.stdout)
    assert result["steps"] == SPAN / DT, result
    return result["min"]


def whfast(safe_mode):
    def one():
        sim = rebound.Simulation()
        sim.G = G
        for m, q, v in zip(MASSES, POSITIONS, VELOCITIES):
            sim.add(m=m, x=q[0], y=q[1], z=q[2], vx=v[0], vy=v[1], vz=v[2])
        sim.integrator = "whfast"
        sim.integrator.safe_mode = safe_mode
        sim.dt = DT
        start = time.perf_counter()
        sim.integrate(SPAN)
        seconds = time.perf_counter() - start
        assert abs(sim.t - SPAN) < 1e-6 and SPAN / DT <= sim.steps_done <= SPAN / DT + 1, sim.steps_done
        return seconds
    return one


CPU = {}


def ensemble(jobs):
    def one():
        cpu = time.process_time()
        start = time.perf_counter()
        table = stormer.ensemble("free-kick", {"alpha": (10, 50, 41), "spin": (0, 20, 41)}, jobs=jobs)
        seconds = time.perf_counter() - start
        # the cores the run had: its processor time over its wall time
        CPU[jobs] = max(CPU.get(jobs, 0.0), (time.process_time() - cpu) / seconds)
        assert table.shape == (1681,) and table["stopped"].all()
        return seconds
    return one


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--reps", type=int, default=10)
    parser.add_argument("--ensemble-rounds", type=int, default=0,
                        help="rounds of the ensemble alone after the others (a quiet moment of a shared machine)")
    args = parser.parse_args()
    runs = {"python": [], "rust": [], "whfast": [], "whfast0": [], "ens1": [], "ens2": []}
    for r in range(args.rounds):
        runs["python"].append(best(ours_python, args.reps))
        runs["rust"].append(ours_rust(args.reps))
        runs["whfast"].append(best(whfast(1), args.reps))
        runs["whfast0"].append(best(whfast(0), args.reps))
        runs["ens1"].append(best(ensemble(1), 3))
        runs["ens2"].append(best(ensemble(2), 3))
        print(f"round {r + 1}: " + ", ".join(f"{k} {v[-1] * 1e3:.2f} ms" for k, v in runs.items()), file=sys.stderr)
    for r in range(args.ensemble_rounds):
        runs["ens1"].append(best(ensemble(1), 3))
        runs["ens2"].append(best(ensemble(2), 3))
    m = {k: min(v) for k, v in runs.items()}
    ms = lambda s: f"{s * 1e3:.2f} ms"  # noqa: E731
    lines = [
        f"# stormer from Python ({args.rounds} rounds, each best of {args.reps}, and {args.ensemble_rounds} rounds of "
        f"the ensemble alone; load {load()})",
        "",
        "| run (outer solar system, 10^5 days, dt = 10 d) | wall time (min) | / ours from Rust | / WHFast |",
        "|---|---|---|---|",
        f"| ours from Python: `Simulation.integrate`, `wisdom_holman`, Kepler split | {ms(m['python'])} "
        f"| **{m['python'] / m['rust']:.2f}** | **{m['python'] / m['whfast']:.2f}** |",
        f"| ours from Rust: the same run (`cli::in_process::run`) | {ms(m['rust'])} | 1.00 "
        f"| {m['rust'] / m['whfast']:.2f} |",
        f"| REBOUND WHFast from Python, `sim.integrate` (defaults: safe_mode 1) | {ms(m['whfast'])} "
        f"| {m['whfast'] / m['rust']:.2f} | 1.00 |",
        f"| REBOUND WHFast, safe_mode 0 | {ms(m['whfast0'])} | {m['whfast0'] / m['rust']:.2f} "
        f"| {m['whfast0'] / m['whfast']:.2f} |",
        "",
        "| ensemble of 1681 free-kick runs from Python | wall time (min) | speedup | cores used (max) |",
        "|---|---|---|---|",
        f"| `stormer.ensemble(..., jobs=1)` | {ms(m['ens1'])} | 1.00 | {CPU[1]:.2f} |",
        f"| `stormer.ensemble(..., jobs=2)` | {ms(m['ens2'])} | **{m['ens1'] / m['ens2']:.2f}** | {CPU[2]:.2f} |",
    ]
    out_dir = os.path.join(ROOT, "out", "peers")
    os.makedirs(out_dir, exist_ok=True)
    write_report(out_dir, "python.md", lines)


if __name__ == "__main__":
    main()
