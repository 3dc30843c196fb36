# The MEGNO stability map of REBOUND's tutorial (two planets, 80 x 80 in a and e, WHFast at dt = 5, 500
# years) timed with REBOUND on 2 processes and compared, point by point, with the table of
#   stormer ensemble two-planets --vary bodies.2.orbit.a=7:10:80 --vary bodies.2.orbit.e=0:0.5:80 --indicator megno
# Run: target/peers/venv/bin/python benches/peers/megno_map.py out/ensemble-two-planets-a+e.csv
# or, both maps timed side by side in one command (alternately, best of ROUNDS each; the table
# compared is the one this run writes): bash benches/peers/run.sh megno --rounds 3
import csv, math, os, sys, time
# this folder's rebound.py (the other comparison) would shadow the package
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]
import rebound
from multiprocessing import Pool
N = 80
def val(lo, hi, k): return (lo * (N - 1 - k) + hi * k) / (N - 1)
def splitmix64(seed, n):
    """stormer's draws (src/models/splitmix64.rs): n numbers in [-1, 1) from seed."""
    out, x, m = [], seed, (1 << 64) - 1
    for _ in range(n):
        x = (x + 0x9E3779B97F4A7C15) & m
        z = x
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & m
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & m
        z ^= z >> 31
        out.append((z >> 11) / float(1 << 52) - 1.0)
    return out
# the initial variation stormer's `--indicator` draws for three bodies in 3-D (app/src/scenes/chaos.rs:
# seed 2026, positions then velocities, body by body)
OURS = splitmix64(2026, 18)
def megno(par):
    a, e, seed = par
    sim = rebound.Simulation()
    sim.rand_seed = seed if seed != "ours" else 1  # the initial variation is drawn at random
    sim.integrator = "whfast"; sim.dt = 5.0
    sim.add(m=1.)
    sim.add(m=0.000954, a=5.204, M=0.600, omega=0.257, e=0.048)
    sim.add(m=0.000285, a=a, M=0.871, omega=1.616, e=e)
    sim.move_to_com()
    sim.init_megno()
    if seed == "ours":
        # REBOUND started from stormer's initial variation: what is left is the two codes
        for b in range(3):
            v = sim.var_config[0].particles[b]
            v.x, v.y, v.z = OURS[3 * b:3 * b + 3]
            v.vx, v.vy, v.vz = OURS[9 + 3 * b:9 + 3 * b + 3]
    sim.exit_max_distance = 20.
    try:
        sim.integrate(5e2 * 2. * math.pi, exact_finish_time=0)
        return sim.megno()
    except rebound.Escape:
        return 10.
STORMER_MAP = ["ensemble", "two-planets", "--vary", "bodies.2.orbit.a=7:10:80", "--vary",
               "bodies.2.orbit.e=0:0.5:80", "--indicator", "megno"]
def rebound_map(grid):
    start = time.time()
    with Pool(2) as pool:
        res = pool.map(megno, [(a, e, 1) for a, e in grid])
    return res, time.time() - start
def stormer_map(binary, out):
    """Our map, by the command a user runs (both cores), writing its table under `out`."""
    import subprocess
    start = time.time()
    subprocess.run([binary] + STORMER_MAP + ["--out", out], check=True, stdout=subprocess.DEVNULL)
    return time.time() - start
if __name__ == "__main__":
    grid = [(val(7, 10, i), val(0, 0.5, j)) for i in range(N) for j in range(N)]
    # with --stormer BINARY: both maps timed side by side, alternately, best of --rounds each
    if "--stormer" in sys.argv:
        binary = sys.argv[sys.argv.index("--stormer") + 1]
        rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 3
        out = "out/peers/megno_map"
        ours_s, theirs_s = [], []
        for _ in range(rounds):
            ours_s.append(stormer_map(binary, out))
            res, secs = rebound_map(grid)
            theirs_s.append(secs)
        print(f"stormer {N}x{N} map: best {min(ours_s):.3f} s of {', '.join(f'{t:.3f}' for t in ours_s)}")
        print(f"REBOUND {rebound.__version__} {N}x{N} map on 2 processes: best {min(theirs_s):.3f} s of "
              f"{', '.join(f'{t:.3f}' for t in theirs_s)}")
        print(f"stormer / REBOUND: {min(ours_s) / min(theirs_s):.3f} (REBOUND {min(theirs_s) / min(ours_s):.2f}x stormer's time)")
        sys.argv[1:] = [os.path.join(out, "ensemble-two-planets-a+e.csv")]
    res, secs = rebound_map(grid)
    # REBOUND against itself, another random variation: how far its own maps agree
    with Pool(2) as pool:
        again = pool.map(megno, [(a, e, 2) for a, e in grid])
    with Pool(2) as pool:
        same_start = pool.map(megno, [(a, e, "ours") for a, e in grid])
    ours = {}
    with open(sys.argv[1]) as f:
        r = csv.DictReader(f)
        for row in r:
            m = row["megno"]
            ours[int(row["member"])] = float(m) if m not in ("", None) else float("nan")
    agree = 0; regular_diffs = []
    for k, (g, v) in enumerate(zip(grid, res)):
        o = ours[k]
        ours_chaotic = not (o <= 2.5)  # failures (nan) count as chaotic, as REBOUND's escapes
        if ours_chaotic == (v > 2.5): agree += 1
        if v <= 2.5 and o <= 2.5: regular_diffs.append(abs(o - v))
    regular_diffs.sort()
    same = sum((x > 2.5) == (y > 2.5) for x, y in zip(res, again))
    own = sorted(abs(x - y) for x, y in zip(res, again) if x <= 2.5 and y <= 2.5)
    print(f"REBOUND against itself (rand_seed 1 and 2): same verdict at {same} of {len(grid)} points "
          f"({100*same/len(grid):.1f}%), |mean MEGNO difference| where both say regular: median "
          f"{own[len(own)//2]:.3f}, 90% {own[int(.9*len(own))]:.3f}")
    print(f"REBOUND {rebound.__version__}: {N}x{N} map in {secs:.2f} s on 2 processes")
    print(f"same verdict at {agree} of {len(grid)} points ({100*agree/len(grid):.1f}%)")
    agree_same = 0; same_diffs = []
    for k, v in enumerate(same_start):
        o = ours[k]
        if (not (o <= 2.5)) == (v > 2.5): agree_same += 1
        if v <= 2.5 and o <= 2.5: same_diffs.append(abs(o - v))
    same_diffs.sort()
    print(f"REBOUND from stormer's initial variation: same verdict at {agree_same} of {len(grid)} points "
          f"({100*agree_same/len(grid):.1f}%), |mean MEGNO difference| where both say regular: median "
          f"{same_diffs[len(same_diffs)//2]:.2e}, 90% {same_diffs[int(.9*len(same_diffs))]:.2e}, "
          f"99% {same_diffs[int(.99*len(same_diffs))]:.2e}, max {same_diffs[-1]:.2e}")
    if regular_diffs:
        print(f"|mean MEGNO difference| at points both call regular: median {regular_diffs[len(regular_diffs)//2]:.3f}, 90% {regular_diffs[int(.9*len(regular_diffs))]:.3f}, max {regular_diffs[-1]:.3f}")
