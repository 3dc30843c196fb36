#!/usr/bin/env python3
"""REBOUND against stormer on many bodies, in one run: a star and N - 1 light bodies
(benches/support/star_and_disc.rs, G = 1), velocity Verlet / leapfrog at dt = 0.001.

Run through `bash benches/peers/run.sh nbody` (it makes the virtual environment under
target/peers/ and builds our example `nbody_timing`). For each N, ROUNDS interleaved rounds:
our example on 1 thread and on 2 threads (f64; best of 3 runs each), then REBOUND with
gravity "basic" (the direct sum over pairs, Newton's third law) and integrator "leapfrog"
on the same initial values (our example prints them), best of 3. Min over the rounds; ns
per step and per pair (N (N - 1) / 2 pairs per step for both). Writes out/peers/nbody.md.
"""

import argparse
import json
import os
import platform
import subprocess
import sys
import time

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _HERE]
import rebound  # noqa: E402

# this folder after the package: its rebound.py must not shadow REBOUND
sys.path.insert(0, _HERE)
from common import load, write_report  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLE = os.path.join(ROOT, "target", "release", "examples", "nbody_timing")


def ours(*args):
    out = subprocess.run([EXAMPLE, *map(str, args)], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def rebound_ns_per_step(state, steps, reps=3):
    n = len(state["mass"])
    best = float("inf")
    for _ in range(reps):
        sim = rebound.Simulation()
        sim.G = state["G"]
        sim.gravity = "basic"
        sim.integrator = "leapfrog"
        sim.dt = state["dt"]
        q, v = state["position"], state["velocity"]
        for k in range(n):
            sim.add(m=state["mass"][k], x=q[3 * k], y=q[3 * k + 1], z=q[3 * k + 2],
                    vx=v[3 * k], vy=v[3 * k + 1], vz=v[3 * k + 2])
        start = time.perf_counter()
        sim.steps(steps)
        best = min(best, time.perf_counter() - start)
    return best * 1e9 / steps



def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", default="10,100,1000,3000", help="numbers of bodies (default 10,100,1000,3000)")
    ap.add_argument("--rounds", type=int, default=3, help="interleaved rounds (default 3)")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "peers"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    sizes = [int(x) for x in args.sizes.split(",")]
    load_start = load()
    rows = []
    for n in sizes:
        pairs = n * (n - 1) // 2
        steps = max(3, min(100000, int(2e7 / max(pairs, 1))))
        state = ours("state", n)
        t1, t2, tr = [], [], []
        for _ in range(args.rounds):
            t1.append(ours("time", n, "--threads", 1, "--steps", steps)["ns_per_step"])
            t2.append(ours("time", n, "--threads", 2, "--steps", steps)["ns_per_step"])
            tr.append(rebound_ns_per_step(state, steps))
        rows.append((n, pairs, steps, min(t1), min(t2), min(tr)))
        print(f"N = {n} done", file=sys.stderr)
    lines = [
        f"REBOUND {rebound.__version__} (Python {platform.python_version()}, gravity basic, leapfrog) and stormer "
        f"(velocity_verlet_kdk, f64), star and N - 1 light bodies, G = 1, dt = 0.001; {args.rounds} interleaved "
        f"rounds, best of 3 runs each, min over rounds; load average {load_start} at the start, {load()} at the end "
        f"(2 cores).",
        "",
        "| N | pairs | steps | REBOUND ns/step | ns/pair | stormer 1 thread ns/step | ns/pair | 2 threads ns/step "
        "| ns/pair | REBOUND / stormer 1 thread | 1 thread / 2 threads |",
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for n, pairs, steps, a, b, r in rows:
        p = max(pairs, 1)
        lines.append(f"| {n} | {pairs} | {steps} | {r:.0f} | {r / p:.2f} | {a:.0f} | {a / p:.2f} | {b:.0f} | "
                     f"{b / p:.2f} | **{r / a:.2f}x** | **{a / b:.2f}x** |")
    write_report(args.out, "nbody.md", lines)


if __name__ == "__main__":
    main()
