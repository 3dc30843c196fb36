#!/usr/bin/env python3
"""Write the collocation polynomial of each collocation method in data/butcher.toml as
its dense output (`dense`, `dense_order`), then regenerate with gen_butcher_catalog.py.

A collocation method with nodes c_1 .. c_s is the polynomial u of degree s with u(0) = y
and u'(t + c_i h) = f(Y_i): u(t + theta h) = y + h sum_i b_i(theta) k_i with
b_i(theta) = int_0^theta l_i(x) dx, l_i the Lagrange basis on the nodes. Its order is s
for every theta (Hairer, Norsett and Wanner I, II.7, Theorem 7.10); b_i(1) = b_i.

    python3 tools/collocation_dense.py && python3 tools/gen_butcher_catalog.py data/butcher.toml

Exact rational arithmetic on the nodes as written (irrational nodes are decimals with
40 digits); values within 1e-35 of a rational with a small denominator are written as p/q, others as decimals with
36 significant digits. Python 3.11+, standard library only.
"""

import re
import tomllib
from decimal import Decimal, localcontext
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "data" / "butcher.toml"
# Gauss, Radau IIA and Lobatto IIIA: the catalog's collocation methods.
COLLOCATION = [
    "backward_euler",
    "implicit_midpoint",
    "trapezoidal",
    "gauss_legendre4",
    "gauss_legendre6",
    "radau_iia3",
    "radau_iia5",
    "lobatto_iiia4",
]


def number(text):
    if "/" in text:
        p, q = text.split("/")
        return Fraction(int(p), int(q))
    return Fraction(Decimal(text))


def poly_mul(p, q):
    out = [Fraction(0)] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        for j, b in enumerate(q):
            out[i + j] += a * b
    return out


def dense_rows(c):
    """Row i: the coefficients of theta^1 .. theta^s of int_0^theta l_i."""
    rows = []
    for i, ci in enumerate(c):
        l = [Fraction(1)]
        for j, cj in enumerate(c):
            if j != i:
                l = poly_mul(l, [-cj / (ci - cj), 1 / (ci - cj)])
        rows.append([a / (k + 1) for k, a in enumerate(l)])
    return rows


def text(x):
    # a node written with 40 digits leaves its rationals off by about 1e-40
    r = x.limit_denominator(10**4)
    if abs(x - r) < Fraction(1, 10**35):
        return str(r.numerator) if r.denominator == 1 else f"{r.numerator}/{r.denominator}"
    with localcontext() as ctx:
        ctx.prec = 36
        return format(Decimal(x.numerator) / Decimal(x.denominator), "e")


def main():
    source = DATA.read_text()
    methods = {m["name"]: m for m in tomllib.loads(source)["method"]}
    for name in COLLOCATION:
        m = methods[name]
        c = [number(x) for x in m["c"]]
        rows = dense_rows(c)
        b = [number(x) for x in m["b"]]
        for row, bi in zip(rows, b):
            assert abs(sum(row) - bi) < Fraction(1, 10**30), (name, row, bi)
        block = (
            "# The collocation polynomial (tools/collocation_dense.py): b_i(theta) = int_0^theta l_i,\n"
            "# l_i the Lagrange basis on the nodes; order s for every theta.\n"
            "dense = [\n"
            + "".join("  [" + ", ".join(f'"{text(x)}"' for x in row) + "],\n" for row in rows)
            + f"]\ndense_order = {len(c)}\n"
        )
        start = source.index(f'name = "{name}"\n')
        end = source.find("[[method]]", start)
        end = len(source) if end < 0 else end
        entry = source[start:end]
        entry = re.sub(r"# The collocation polynomial.*?dense_order = \d+\n", "", entry, flags=re.S)
        at = re.search(r"^b = .*\n", entry, flags=re.M).end()
        entry = entry[:at] + block + entry[at:]
        source = source[:start] + entry + source[end:]
    DATA.write_text(source)


if __name__ == "__main__":
    main()
