#!/usr/bin/env python3
"""What `--save-at` with 1000 points costs on the command line (issue #11): the release
`stormer` run on kepler-e06 (100 orbits, dop853 at rtol = atol = 1e-11) plain, with 1000 output
times in its first orbit and with 1000 spread over the whole run, interleaved, wall time of the
whole process (CSV and pictures included), min and median over the rounds; and, for scale,
the plain run writing about as many rows from its step grid (`--every 6`).

Run: cargo build --release && python3 benches/save_at_cli.py [--rounds 20]
"""
import argparse
import os
import statistics
import subprocess
import tempfile
import time

CASES = [
    ("plain", []),
    ("1000 times in the first orbit", ["--save-at", "0.00314:0.00628:6.28"]),
    ("1000 times over the run", ["--save-at", "0.314:0.628:628"]),
    # the same number of rows on the step grid (5668 steps): what the rows themselves cost
    ("every 6th step (945 rows)", ["--every", "6"]),
]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=20)
    parser.add_argument("--binary", default=os.path.abspath("target/release/stormer"))
    args = parser.parse_args()
    base = [args.binary, "run", "kepler-e06", "--method", "dop853", "--rtol", "1e-11", "--atol", "1e-11"]
    times = {name: [] for name, _ in CASES}
    with tempfile.TemporaryDirectory() as out:
        for _ in range(args.rounds):
            for name, extra in CASES:
                start = time.perf_counter()
                subprocess.run(base + extra, cwd=out, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                times[name].append(time.perf_counter() - start)
    plain = min(times["plain"])
    print(f"{args.rounds} interleaved rounds, ms per run (min, median), ratio to plain by min:")
    for name, _ in CASES:
        t = times[name]
        print(f"  {name:<32} {1e3 * min(t):8.2f} {1e3 * statistics.median(t):8.2f}   {min(t) / plain:.3f}")


if __name__ == "__main__":
    main()
