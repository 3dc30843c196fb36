#!/usr/bin/env python3
"""REBOUND WHFast's cost per step on the outer solar system (SCENES.md 4), dt = 10 days,
Jacobi coordinates, safe_mode = 0, no correctors: the peer of `cargo bench --bench
kepler_drift` (`outer_solar_system_step/wisdom_holman_jacobi`). Best of 7 runs of 36000
steps, in ns per step.

Run: python3 benches/peers/whfast_step.py (with `pip install rebound`)
"""
import os
import sys
import time

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _HERE]
import rebound  # noqa: E402

G = 2.95912208286e-4
MASSES = [1.00000597682, 0.000954786104043, 0.000285583733151, 0.0000437273164546]
POSITIONS = [
    (0.0, 0.0, 0.0),
    (-3.5023653, -3.8169847, -1.5507963),
    (9.0755314, -3.0458353, -1.6483708),
    (8.3101420, -16.2901086, -7.2521278),
]
VELOCITIES = [
    (0.0, 0.0, 0.0),
    (0.00565429, -0.00412490, -0.00190589),
    (0.00168318, 0.00483525, 0.00192462),
    (0.00354178, 0.00137102, 0.00055029),
]
STEPS, DT = 36000, 10.0


def run(corrector):
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
    sim.integrate(STEPS * DT, exact_finish_time=0)
    seconds = time.perf_counter() - start
    return seconds, abs((sim.energy() - e0) / e0)


def main():
    print(f"REBOUND {rebound.__version__}, outer solar system, dt = {DT} days, {STEPS} steps", flush=True)
    for corrector in (0, 11):
        best = min(run(corrector)[0] for _ in range(7))
        error = run(corrector)[1]
        print(f"WHFast corrector {corrector:2}: {best / STEPS * 1e9:.0f} ns/step, |dE/E| at the end {error:.1e}")


if __name__ == "__main__":
    main()
