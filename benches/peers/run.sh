#!/usr/bin/env bash
# Benchmarks against peers, in one command:
#   bash benches/peers/run.sh               # REBOUND vs stormer on the outer solar system
#   bash benches/peers/run.sh --rounds 3    # any option of rebound.py
#   bash benches/peers/run.sh --whfast-step # a Wisdom-Holman step against WHFast's (whfast_step.py;
#                                           # the options after it are whfast_step.py's)
#   bash benches/peers/run.sh nbody         # REBOUND vs stormer on 10 to 3000 bodies (nbody.py)
#   bash benches/peers/run.sh nbody --sizes 1000 --rounds 5
#   bash benches/peers/run.sh megno         # the two-planet MEGNO map, REBOUND's tutorial vs ours,
#                                           # timed alternately (megno_map.py; --rounds)
#   bash benches/peers/run.sh pythagorean   # REBOUND IAS15 vs stormer's TTL on Burrau's problem
#                                           # (pythagorean.py; --method, --dt, --rounds)
#   bash benches/peers/run.sh python        # stormer from Python vs the same run from Rust and vs
#                                           # REBOUND WHFast from Python; an ensemble on 1 and 2
#                                           # threads (python_side.py; --rounds, --reps)
# Installs what it needs: a virtual environment under target/peers/venv with REBOUND
# (PyPI package `rebound`), or the one named by $PEERS_VENV; our side is
# `app/examples/outer_solar_front.rs` (release build).
# Results: out/peers/rebound.md, rebound_front.json, rebound_front.svg; out/peers/nbody.md;
# out/peers/python.md.
# The ode_solvers comparison (free kick) is a criterion bench: cargo bench --bench free_kick_peers
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
venv="${PEERS_VENV:-target/peers/venv}"
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
if ! "$venv/bin/python" -c "import rebound" 2>/dev/null; then
    "$venv/bin/pip" install --quiet "rebound>=4.4"
fi
if [ "${1:-}" = nbody ]; then
    shift
    cargo build --release --example nbody_timing --features parallel
    exec "$venv/bin/python" benches/peers/nbody.py "$@"
fi
if [ "${1:-}" = megno ]; then
    shift
    cargo build --release -p stormer-app
    exec "$venv/bin/python" benches/peers/megno_map.py --stormer target/release/stormer "$@"
fi
if [ "${1:-}" = python ]; then
    shift
    # the package as its users install it (a release build by maturin), beside REBOUND
    "$venv/bin/pip" install --quiet ./python
    cargo build --release -p stormer-app --example in_process_run
    exec "$venv/bin/python" benches/peers/python_side.py "$@"
fi
if [ "${1:-}" = pythagorean ]; then
    shift
    cargo build --release -p stormer-app
    exec "$venv/bin/python" benches/peers/pythagorean.py "$@"
fi
cargo build --release -p stormer-app --example outer_solar_front
if [ "${1:-}" = "--whfast-step" ]; then
    shift
    exec "$venv/bin/python" benches/peers/whfast_step.py "$@"
fi
exec "$venv/bin/python" benches/peers/rebound.py "$@"
