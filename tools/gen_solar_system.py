#!/usr/bin/env python3
"""Writes scenes/solar-system-8.toml: the Sun and the eight planets at J2000 (JD 2451545.0,
TDB) from the mean orbital elements of E. M. Standish, "Keplerian Elements for Approximate
Positions of the Major Planets" (JPL, Table 1, valid 1800-2050 AD; mean ecliptic and
equinox of J2000), and the Sun/planet mass ratios of DE405 (IAU). Heliocentric positions
and velocities, the Sun at rest at the origin, as in outer-solar-system.toml.

Run from the repository's root: python3 tools/gen_solar_system.py
"""
import math

K = 0.01720209895  # Gauss's constant: G = k^2 in AU^3 / (day^2 solar mass)
G = K * K

# name, Sun/planet mass ratio, a (AU), e, I (deg), L (deg), long. perihelion (deg), long. node (deg)
PLANETS = [
    ("Mercury", 6023600.0, 0.38709927, 0.20563593, 7.00497902, 252.25032350, 77.45779628, 48.33076593),
    ("Venus", 408523.71, 0.72333566, 0.00677672, 3.39467605, 181.97909950, 131.60246718, 76.67984255),
    ("Earth", 328900.56, 1.00000261, 0.01671123, -0.00001531, 100.46457166, 102.93768193, 0.0),
    ("Mars", 3098708.0, 1.52371034, 0.09339410, 1.84969142, -4.55343205, -23.94362959, 49.55953891),
    ("Jupiter", 1047.3486, 5.20288700, 0.04838624, 1.30439695, 34.39644051, 14.72847983, 100.47390909),
    ("Saturn", 3497.898, 9.53667594, 0.05386179, 2.48599187, 49.95424423, 92.59887831, 113.66242448),
    ("Uranus", 22902.98, 19.18916464, 0.04725744, 0.77263783, 313.23810451, 170.95427630, 74.01692503),
    ("Neptune", 19412.24, 30.06992276, 0.00859048, 1.77004347, -55.12002969, 44.96476227, 131.78422574),
]


def state(mu, a, e, inc, mean_longitude, perihelion, node):
    """Heliocentric position and velocity from the elements (angles in degrees)."""
    d = math.radians
    m = math.remainder(d(mean_longitude - perihelion), 2 * math.pi)
    w, o, i = d(perihelion - node), d(node), d(inc)
    big_e = m + e * math.sin(m)
    for _ in range(50):
        big_e -= (big_e - e * math.sin(big_e) - m) / (1 - e * math.cos(big_e))
    c, s = math.cos(big_e), math.sin(big_e)
    b = math.sqrt(1 - e * e)
    n = math.sqrt(mu / a**3)
    x, y = a * (c - e), a * b * s
    vx, vy = -a * n * s / (1 - e * c), a * n * b * c / (1 - e * c)

    def rotate(px, py):
        # R_z(node) R_x(inc) R_z(w)
        x1, y1 = px * math.cos(w) - py * math.sin(w), px * math.sin(w) + py * math.cos(w)
        y2, z2 = y1 * math.cos(i), y1 * math.sin(i)
        return [x1 * math.cos(o) - y2 * math.sin(o), x1 * math.sin(o) + y2 * math.cos(o), z2]

    return rotate(x, y), rotate(vx, vy)


def main():
    out = [
        "# The Sun and the eight planets at J2000 (JD 2451545.0 TDB), heliocentric, mean ecliptic and",
        "# equinox of J2000, AU and days. Written by tools/gen_solar_system.py from the mean orbital",
        "# elements of E. M. Standish, \"Keplerian Elements for Approximate Positions of the Major",
        "# Planets\" (JPL, Table 1, valid 1800-2050 AD: positions within arcminutes of the ephemeris, a",
        "# realistic rather than an exact solar system) and the Sun/planet mass ratios of DE405",
        "# (Mercury 6023600, Venus 408523.71, Earth+Moon 328900.56, Mars 3098708, Jupiter 1047.3486,",
        "# Saturn 3497.898, Uranus 22902.98, Neptune 19412.24); Earth is the Earth-Moon barycentre.",
        "# G = k^2, k = 0.01720209895 (Gauss). Each orbit converted with mu = G (1 + m_planet).",
        'model = "n-body"',
        'description = "Sun and the eight planets at J2000 (AU, days), Standish mean elements, DE405 masses"',
        "",
        "[parameters]",
        f"G = {G!r}",
        "",
        "[[bodies]]",
        'name = "Sun"',
        "mass = 1.0",
        "position = [0.0, 0.0, 0.0]",
        "velocity = [0.0, 0.0, 0.0]",
    ]
    for name, ratio, a, e, inc, lam, peri, node in PLANETS:
        mass = 1.0 / ratio
        q, v = state(G * (1.0 + mass), a, e, inc, lam, peri, node)
        out += [
            "",
            "[[bodies]]",
            f'name = "{name}"',
            f"mass = {mass!r}",
            "position = [" + ", ".join(repr(x) for x in q) + "]",
            "velocity = [" + ", ".join(repr(x) for x in v) + "]",
        ]
    out += [
        "",
        "[run]",
        'method = "wisdom_holman"',
        'split = "kepler-jacobi"        # Wisdom-Holman: Kepler orbits about the Sun, the planets\' pulls as kicks',
        "dt = 4.0                       # days (Mercury's period / 22)",
        "t_end = 365250.0               # days (1000 years)",
        "every = 100",
        "",
        "[units]                        # printed on the pictures' axes",
        'time = "days"',
        'length = "AU"',
    ]
    with open("scenes/solar-system-8.toml", "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
