#!/usr/bin/env python3
"""A Wisdom-Holman step against REBOUND WHFast's, in one run: the outer solar system (docs/scenes.md 4),
dt = 10 days, Jacobi coordinates. REBOUND: WHFast with safe_mode = 0 (its half drifts of
consecutive steps merged), without and with corrector 11. Ours: `app/examples/outer_solar_front.rs
time` (release), `kepler/wisdom_holman` (drift-kick-drift, two half drifts per step) and
`kepler/velocity_verlet_kdk` (kick-drift-kick over the same split: one drift per step), both through
`Stepper::step_in_place`, the fixed-step driver's loop.

Interleaved: ROUNDS rounds, each one call of our example (each method best of 5 runs of STEPS
steps) then each REBOUND run (best of 5 runs of STEPS steps). Prints ns per step, min and median over
the rounds, and the ratios ours / WHFast of the minima and of the medians.

Run: bash benches/peers/run.sh --whfast-step   (or, with REBOUND installed and the example built,
     python3 benches/peers/whfast_step.py [--rounds N] [--steps N])
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _HERE]
import rebound  # noqa: E402

# this folder after the package: its rebound.py must not shadow REBOUND
sys.path.insert(0, _HERE)
from common import G, MASSES, POSITIONS, VELOCITIES, load  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(_HERE))
EXAMPLE = os.path.join(ROOT, "target", "release", "examples", "outer_solar_front")
OURS = ["kepler/wisdom_holman", "kepler/velocity_verlet_kdk"]

DT = 10.0


def whfast(corrector, steps):
    """Seconds of `steps` WHFast steps, and |dE/E| at the end."""
    sim = rebound.Simulation()
    sim.G = G
    for m, q, v in zip(MASSES, POSITIONS, VELOCITIES):
        sim.add(m=m, x=q[0], y=q[1], z=q[2], vx=v[0], vy=v[1], vz=v[2])
    sim.integrator = "whfast"
    sim.integrator.safe_mode = 0
    sim.integrator.corrector = corrector
    sim.dt = DT
    e0 = sim.energy()
    start = time.perf_counter()
    sim.integrate(steps * DT, exact_finish_time=0)
    seconds = time.perf_counter() - start
    assert steps <= sim.steps_done <= steps + 1, sim.steps_done
    return seconds, abs((sim.energy() - e0) / e0)


def ours(steps):
    out = subprocess.run(
        [EXAMPLE, "time", "--span", repr(steps * DT), "--dt", repr(DT), "--reps", "5", "--methods", ",".join(OURS)],
        check=True, capture_output=True, text=True)
    return {row["method"]: row["ns_per_step"] for row in json.loads(out.stdout)["rows"]}



def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=9)
    ap.add_argument("--steps", type=int, default=3600, help="steps per timed run (default 3600: 36000 days)")
    args = ap.parse_args()
    load_start = load()
    times = {}
    for r in range(args.rounds):
        for name, ns in ours(args.steps).items():
            times.setdefault(name, []).append(ns)
        for corrector in (0, 11):
            best = min(whfast(corrector, args.steps)[0] for _ in range(5))
            times.setdefault(f"whfast corrector {corrector}", []).append(best * 1e9 / args.steps)
        print(f"round {r + 1}/{args.rounds} done", file=sys.stderr)
    error = whfast(0, args.steps)[1]
    print(f"REBOUND {rebound.__version__}, outer solar system, dt = {DT:g} days, runs of {args.steps} steps, "
          f"{args.rounds} interleaved rounds (best of 5 each); load average {load_start} at the start, {load()} "
          f"at the end; WHFast |dE/E| after one run {error:.1e}")
    print()
    print("| step | ns/step (min / median) | / WHFast (min / median) |")
    print("|---|---:|---:|")
    base = times["whfast corrector 0"]
    for name, v in times.items():
        lo, med = min(v), statistics.median(v)
        print(f"| {name} | {lo:.0f} / {med:.0f} | {lo / min(base):.2f} / {med / statistics.median(base):.2f} |")


if __name__ == "__main__":
    main()
