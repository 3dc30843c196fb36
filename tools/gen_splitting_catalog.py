#!/usr/bin/env python3
"""Transcribe the splittings and compositions of the method catalog into stormer's sources.

Used once to transcribe the shared method catalog; it can be re-run at any time, either
on the shared catalog or on the crate's own copy (the output is the same):

    python3 tools/gen_splitting_catalog.py path/to/catalog.toml
    python3 tools/gen_splitting_catalog.py data/splitting.toml

It reads every `family = "splitting"` and `family = "composition"` entry and writes,
relative to the repository root:

* src/catalog/splitting.rs -- one `splitting!` declaration per method (drift-first arrays);
* src/catalog/composition.rs -- one `composition!` declaration per method (weights);
* src/catalog/splitting_list.rs -- the `for_each_splitting_method!` list, general methods
  apart from those that need a quadratic kinetic energy;
* data/splitting.toml -- the entries copied verbatim, for cross-checking the declarations;
* docs/splitting-methods.md -- the method list.

Python 3.11+, standard library only; shares the coefficient and doc helpers of
tools/gen_butcher_catalog.py.
"""

import re
import sys
import textwrap
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import gen_butcher_catalog as g  # noqa: E402

WIDTH = g.WIDTH

CLASS_TEXT = {
    "general": "general splitting",
    "rkn": "built for quadratic kinetic energy (Runge-Kutta-Nystrom problems)",
    "near_integrable": "near-integrable splitting (`H = A + eps B`)",
    "near_integrable_rkn": "near-integrable splitting with `[B,[B,[B,A]]] = 0`",
}

def upper_first(text):
    """The text with its first letter upper-cased (`str.capitalize` lower-cases the rest)."""
    return text[:1].upper() + text[1:]


HEADER = g.generated_header("gen_splitting_catalog.py", "data/splitting.toml")

TRANSCRIBED = """\
//! Coefficients are transcribed from the project's `data/splitting.toml` by
//! `tools/gen_splitting_catalog.py` and checked at compile time by the `{macro}!` macro.
"""


def word(m):
    """`D(1/2) K(1) D(1/2)`: the declared sequence with zero entries dropped."""
    parts = []
    for d, k in zip(m["drift"], m["kick"]):
        for flow, x in (("D", d), ("K", k)):
            if g.value(x) != 0:
                parts.append(f"{flow}({g.show(x)})")
    return parts


def doc_comment(m):
    aliases = ", ".join(m["aliases"])
    out = g.wrap(f"{g.md_escape(m['reference'])} ({g.md_escape(aliases)}).") + [""]
    if m["family"] == "splitting":
        out += ["One step of size `h` applies, left to right (drift-first fractions of `h`):", "", "```text"]
        out += textwrap.wrap(" ".join(word(m)), WIDTH - 8)
        out += ["```", ""]
        orders = f"order {m['order']}"
        if m["order_general"] != m["order_rkn"]:
            orders += f" (measured {m['order_general']} for a general kinetic energy, {m['order_rkn']} for a quadratic one)"
        s = m["stages"]
        summary = (f"{upper_first(CLASS_TEXT[m['class']])}, {orders}, {s} force evaluation{'s' * (s > 1)} per step"
                   f"{' (FSAL)' if m['fsal'] else ''}; {'symmetric' if m['symmetric'] else 'not symmetric'}.")
        if m["requires_quadratic_kinetic"]:
            summary += " Accepts only problems with a quadratic kinetic energy (`QuadraticKinetic`)."
        if "generalized_order" in m:
            summary += f" Generalized order {tuple(m['generalized_order'])} in (eps, eps^2, eps^3)."
    else:
        out += ["Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:", "", "```text"]
        out += textwrap.wrap(", ".join(g.show(x) for x in m["gamma"]), WIDTH - 8)
        out += ["```", ""]
        s = m["stages"]
        summary = (f"Composition of order {m['order']} over a symmetric second-order base, {s} base steps "
                   f"({s} force evaluations with Stormer-Verlet); symmetric.")
    out += g.wrap(summary)
    out += [""] + g.wrap(f"Coefficients from {m['source_repo']} `{m['source_path']}`"
                         + (f" at {m['source_commit'][:7]}." if "source_commit" in m else "."))
    out += g.wrap(f"Precision: {g.md_escape(m['precision'])}.")
    return out + g.notes_and_closed_form(m)


def declaration(m):
    def lit(xs):
        return [g.rust_literal(x) for x in xs]

    macro = m["family"]
    out = [f"crate::{macro}! {{"]
    out += [f"    /// {line}".rstrip() for line in doc_comment(m)]
    out += [f"    pub struct {g.struct_name(m['name'])} {{",
            f'        name: "{m["name"]}",',
            f"        order: {m['order']},"]
    if macro == "splitting":
        out += g.array("drift: ", lit(m["drift"]), 8)
        out += g.array("kick: ", lit(m["kick"]), 8)
        if m["requires_quadratic_kinetic"]:
            out += ["        quadratic_kinetic: true,"]
        if "generalized_order" in m:
            out += [f"        generalized_order: [{', '.join(str(p) for p in m['generalized_order'])}],"]
    else:
        out += g.array("gamma: ", lit(m["gamma"]), 8)
    return out + ["    }", "}"]


def module(family, methods):
    title = {"splitting": "Splitting methods (drift/kick sequences), drift-first as in the catalog.",
             "composition": "Composition methods: weights over a symmetric second-order base."}[family]
    body = [line for m in methods for line in [""] + declaration(m)]
    return f"{HEADER}//! {title}\n//!\n{TRANSCRIBED.format(macro=family)}" + "\n".join(body) + "\n"


LIST_RS = """\
//! The list of compiled splittings and compositions, for the registry.
//!
//! Generated by `tools/gen_splitting_catalog.py`.

/// Invokes `$callback! {{ general: [..], quadratic: [..] }}` with the type names of every
/// splitting and composition ({count} in all), in catalog order: `general` methods are
/// valid for every splittable problem, `quadratic` ones need a quadratic kinetic energy.
macro_rules! for_each_splitting_method {{
    ($callback:ident) => {{
        $callback! {{
            general: [
{general}
            ],
            quadratic: [
{quadratic}
            ],
        }}
    }};
}}
pub(crate) use for_each_splitting_method;
"""


def list_rs(methods):
    def names(ms):
        listed = ", ".join(g.struct_name(m["name"]) for m in ms)
        return "\n".join(textwrap.wrap(listed, WIDTH - 16, initial_indent=" " * 16, subsequent_indent=" " * 16))

    general = [m for m in methods if not m.get("requires_quadratic_kinetic", False)]
    quadratic = [m for m in methods if m.get("requires_quadratic_kinetic", False)]
    return HEADER + LIST_RS.format(count=len(methods), general=names(general), quadratic=names(quadratic))


DATA_HEADER = """\
# Splittings and compositions of the stormer method catalog, copied verbatim (same keys,
# sources and independent mpmath `checked` results) by tools/gen_splitting_catalog.py. The
# crate's tests cross-check the `splitting!` / `composition!` declarations in src/catalog/
# against this file. Coefficients are TOML strings: integer, exact rational "p/q", or
# decimal copied literally from the source.
"""


def data_toml(text, catalog, methods):
    conventions = "".join(re.search(rf'^{key} = """.*?"""\n', text, re.S | re.M)[0]
                          for key in ("splitting", "composition", "near_integrable"))
    return g.data_copy(DATA_HEADER, text, catalog, methods, conventions, "(splitting|composition)")


METHODS_MD = """\
# Splitting and composition methods

The splittings and compositions stormer ships, generated from `data/splitting.toml` by
`tools/gen_splitting_catalog.py`; `stormer methods` prints the same table from the compiled
catalog. Consistency (sums, the second-order condition, `sum gamma^k = 0`) is checked at
compile time; the orders are measured (see docs/verification.md). `stages` = force
evaluations per step after FSAL reuse. RKN-only methods accept only problems with a quadratic
kinetic energy. See ../shared-free notes in docs/hamiltonian.md for how to choose.
"""


def methods_md(methods):
    def row(cells):
        return "| " + " | ".join(str(x) for x in cells) + " |"

    yn = {True: "yes", False: "no"}
    out = [METHODS_MD.replace("See ../shared-free notes in docs/hamiltonian.md", "See docs/hamiltonian.md")]
    cols = ["name", "order", "stages", "class", "FSAL", "symmetric", "reference"]
    out += ["## Splittings", "", row(cols), row(["---"] * len(cols))]
    out += [row([f"`{m['name']}`", m["order"], m["stages"], m["class"], yn[m["fsal"]], yn[m["symmetric"]],
                 m["reference"].replace("|", "/")]) for m in methods if m["family"] == "splitting"]
    cols = ["name", "order", "stages", "reference"]
    out += ["", "## Compositions", "", row(cols), row(["---"] * len(cols))]
    out += [row([f"`{m['name']}`", m["order"], m["stages"], m["reference"].replace("|", "/")])
            for m in methods if m["family"] == "composition"]
    return "\n".join(out) + "\n"


def main(path):
    text = Path(path).read_text(encoding="utf-8")
    catalog = tomllib.loads(text)
    methods = [m for m in catalog["method"] if m["family"] in ("splitting", "composition")]
    for m in methods:
        if m["family"] == "splitting":
            assert len(m["drift"]) == len(m["kick"]), m["name"]
        else:
            assert len(m["gamma"]) == m["stages"], m["name"]
    files = {
        "src/catalog/splitting.rs": module("splitting", [m for m in methods if m["family"] == "splitting"]),
        "src/catalog/composition.rs": module("composition", [m for m in methods if m["family"] == "composition"]),
        "src/catalog/splitting_list.rs": list_rs(methods),
        "data/splitting.toml": data_toml(text, catalog, methods),
        "docs/splitting-methods.md": methods_md(methods),
    }
    g.write(files)


if __name__ == "__main__":
    g.run(main)
