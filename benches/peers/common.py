"""What the peer scripts share: the outer solar system of docs/scenes.md 4 (as REBOUND gets it),
the machine's load average, and writing a report table."""

import os
import sys

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


def load():
    """The 1, 5 and 15-minute load averages, as the machine reports them."""
    try:
        return " ".join(open("/proc/loadavg").read().split()[:3])
    except OSError:
        return "?"


def write_report(out_dir, name, lines, wrote=None):
    """Writes `lines` to `out_dir/name`, prints them, and says on stderr what was written."""
    with open(os.path.join(out_dir, name), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"\nwrote {out_dir}/{wrote or name}", file=sys.stderr)
