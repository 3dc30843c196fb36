#!/usr/bin/env bash
# Benchmarks against peers, in one command:
#   bash benches/peers/run.sh            # REBOUND vs stormer on the outer solar system
#   bash benches/peers/run.sh --rounds 3 # any option of rebound.py
# Installs what it needs: a virtual environment under target/peers/venv with REBOUND
# (PyPI package `rebound`); our side is `app/examples/outer_solar_front.rs` (release build).
# Results: out/peers/rebound.md, rebound_front.json, rebound_front.svg.
# The ode_solvers comparison (free kick) is a criterion bench: cargo bench --bench free_kick_peers
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"
venv="target/peers/venv"
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
if ! "$venv/bin/python" -c "import rebound" 2>/dev/null; then
    "$venv/bin/pip" install --quiet "rebound>=4.4"
fi
cargo build --release --example outer_solar_front
exec "$venv/bin/python" benches/peers/rebound.py "$@"
