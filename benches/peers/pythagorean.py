# Burrau's Pythagorean problem (masses 3, 4, 5 at rest at (1, 3), (-2, -1), (1, -1), G = 1) to t = 70,
# side by side: REBOUND IAS15 (epsilon 1e-9) and
#   stormer run pythagorean --time-transform ttl --method METHOD --dt DT
# Both outcomes are read from the state at t = 70 by the same definitions as stormer's summary
# (app/src/scenes/three_body_outcome.rs, docs/close-approaches.md): the escaping body (positive
# two-body energy relative to the other two's centre of mass, receding, the other two bound), the
# binary's semi-major axis and eccentricity, and the escape time (the pericentre passage of the
# escaper's hyperbola about the binary's centre of mass). Wall times: the best of --rounds; REBOUND's
# is its integrate() call in this process, ours the whole command (start, scene, CSV of a few rows).
# Run: bash benches/peers/run.sh pythagorean   (or target/peers/venv/bin/python benches/peers/pythagorean.py)
import argparse, math, os, re, subprocess, sys, time
# this folder's rebound.py (the other comparison) would shadow the package
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]
import rebound

MASSES = [3.0, 4.0, 5.0]
POSITIONS = [(1.0, 3.0), (-2.0, -1.0), (1.0, -1.0)]
T_END = 70.0


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def two_body(mu, r, v):
    """Energy per unit reduced mass, squared angular momentum, r . v."""
    r2, v2, rv = dot(r, r), dot(v, v), dot(r, v)
    return 0.5 * v2 - mu / math.sqrt(r2), r2 * v2 - rv * rv, rv


def outcome(t, q, v, g=1.0):
    """The escape of three bodies at positions q and velocities v (lists of 2-vectors), as stormer's."""
    found = None
    for k in range(3):
        i, j = sorted(((k + 1) % 3, (k + 2) % 3))
        mi, mj = MASSES[i], MASSES[j]
        cq = [(mi * a + mj * b) / (mi + mj) for a, b in zip(q[i], q[j])]
        cv = [(mi * a + mj * b) / (mi + mj) for a, b in zip(v[i], v[j])]
        r = [a - b for a, b in zip(q[k], cq)]
        w = [a - b for a, b in zip(v[k], cv)]
        mu = g * (MASSES[k] + mi + mj)
        energy, h2, rv = two_body(mu, r, w)
        rb = [b - a for a, b in zip(q[i], q[j])]
        vb = [b - a for a, b in zip(v[i], v[j])]
        mu_b = g * (mi + mj)
        energy_b, h2_b, _ = two_body(mu_b, rb, vb)
        distance = math.sqrt(dot(r, r))
        if not (energy > 0 and rv > 0 and energy_b < 0) or (found and found["distance"] >= distance):
            continue
        a_h = mu / (2 * energy)
        e_h = math.sqrt(1 + 2 * energy * h2 / mu**2)
        cosh_f = max(1.0, (1 + distance / a_h) / e_h)
        f = math.copysign(math.acosh(cosh_f), rv)
        decided = t - (e_h * math.sinh(f) - f) / math.sqrt(mu / a_h**3)
        found = dict(escaper=f"m{MASSES[k]:.0f}", binary=f"m{mi:.0f}-m{mj:.0f}", distance=distance,
                     a=-mu_b / (2 * energy_b), e=math.sqrt(max(0.0, 1 + 2 * energy_b * h2_b / mu_b**2)),
                     decided=decided)
    return found


def rebound_run(epsilon):
    sim = rebound.Simulation()
    sim.G = 1.0
    for m, (x, y) in zip(MASSES, POSITIONS):
        sim.add(m=m, x=x, y=y)
    sim.integrator = "ias15"
    sim.integrator.epsilon = epsilon  # REBOUND 4.4+: the integrator object holds its settings
    e0 = sim.energy()
    start = time.perf_counter()
    sim.integrate(T_END)  # exact_finish_time: the last step ends at 70
    secs = time.perf_counter() - start
    q = [(p.x, p.y) for p in sim.particles]
    v = [(p.vx, p.vy) for p in sim.particles]
    return secs, outcome(sim.t, q, v), abs(sim.energy() / e0 - 1), sim.steps_done


def stormer_run(binary, method, dt):
    out = os.path.join("out", "peers", "pythagorean-stormer.csv")
    cmd = [binary, "run", "pythagorean", "--time-transform", "ttl", "--method", method, "--dt", str(dt),
           "--every", "100", "-o", out]
    start = time.perf_counter()
    res = subprocess.run(cmd, capture_output=True, text=True, check=True)
    secs = time.perf_counter() - start
    text = res.stderr
    number = lambda label: float(re.search(re.escape(label) + r"\s*([-+0-9.e]+)", text).group(1))
    found = dict(escaper=re.search(r"(m\d) escapes", text).group(1),
                 binary=re.search(r"the binary (m\d-m\d)", text).group(1),
                 a=number("has a ="), e=number("e ="), decided=number("decided at t ="))
    return secs, found, number("max |dE/E0|"), int(number(":")), " ".join(cmd), text


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--method", default="yoshida6a")
    ap.add_argument("--dt", type=float, default=0.05)
    ap.add_argument("--epsilon", type=float, default=1e-9)
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--binary", default="target/release/stormer")
    args = ap.parse_args()
    os.makedirs(os.path.join("out", "peers"), exist_ok=True)
    theirs = min((rebound_run(args.epsilon) for _ in range(args.rounds)), key=lambda r: r[0])
    ours = min((stormer_run(args.binary, args.method, args.dt) for _ in range(args.rounds)), key=lambda r: r[0])
    r, s = theirs[1], ours[1]
    lines = [
        f"Pythagorean problem to t = 70 (load {open('/proc/loadavg').read().split()[:3]}), best of {args.rounds}:",
        f"REBOUND {rebound.__version__} IAS15 eps {args.epsilon:g}: {theirs[0]*1e3:.1f} ms, {theirs[3]} steps, "
        f"|dE/E0| at t = 70 {theirs[2]:.1e}; {r['escaper']} escapes, binary {r['binary']} a = {r['a']:.6f}, "
        f"e = {r['e']:.6f}, escape decided at t = {r['decided']:.5f}",
        f"stormer TTL {args.method} dt {args.dt:g} in s: {ours[0]*1e3:.1f} ms (whole command), {ours[3]} steps, "
        f"max |dE/E0| over the records {ours[2]:.1e}; {s['escaper']} escapes, binary {s['binary']} a = {s['a']:.6f}, "
        f"e = {s['e']:.6f}, escape decided at t = {s['decided']:.5f}",
        f"  command: {ours[4]}",
        f"agreement: same escaper {r['escaper'] == s['escaper']}, a {abs(s['a'] / r['a'] - 1):.1e}, "
        f"escape time {abs(s['decided'] / r['decided'] - 1):.1e} (relative); wall time ours / IAS15 "
        f"{ours[0] / theirs[0]:.2f}",
    ]
    print("\n".join(lines))


if __name__ == "__main__":
    main()
