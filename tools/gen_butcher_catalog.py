#!/usr/bin/env python3
"""Transcribe the Butcher tableaus of the method catalog into stormer's sources.

Used once to transcribe the shared method catalog; it can be re-run at any time,
either on the shared catalog or on the crate's own copy (the output is the same):

    python3 tools/gen_butcher_catalog.py path/to/catalog.toml
    python3 tools/gen_butcher_catalog.py data/butcher.toml

It reads every `family = "butcher"` entry and writes, relative to the repository root:

* src/catalog/{explicit,embedded,implicit}.rs -- one `tableau!` declaration per method,
  coefficients copied literally (integers, `p/q` rationals, decimal literals);
* src/catalog/mod.rs -- module declarations and the `for_each_butcher_method!` list;
* data/butcher.toml -- the Butcher entries copied verbatim (but for DROPPED_PAIRS), for
  cross-checking the declarations;
* docs/methods.md -- the method list.

An embedded pair listed in DROPPED_PAIRS is removed on the way (its `b_hat` and
`embedded_order`, with the reason added as the entry's `notes`), so the method is a
fixed-step one in both the data copy and the declarations, whichever file is read.

Python 3.11+, standard library only.
"""

import json
import re
import sys
import textwrap
import tomllib
from decimal import Decimal, localcontext
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
WIDTH = 100  # maximum width of generated Rust lines (comments may overflow by a long token)

# Human-readable name and one-line description for the first doc line.
TITLES = {
    "euler": ("Forward Euler", "the first-order explicit one-step method."),
    "midpoint": ("Explicit midpoint", "two-stage second-order method, embedded Euler step."),
    "heun2": ("Heun's method", "explicit trapezoidal rule with an embedded Euler step."),
    "ralston2": ("Ralston's second-order method", "two-stage method with minimal error bound."),
    "kutta3": ("Kutta's third-order method", "the classic three-stage third-order method."),
    "ssprk33": ("SSPRK(3,3)", "three-stage third-order strong-stability-preserving method."),
    "ssprk43": ("SSPRK(4,3)", "four-stage third-order strong-stability-preserving method."),
    "rk4": ("Classic Runge-Kutta", "the four-stage fourth-order method of Kutta."),
    "rk4_38": ("Kutta's 3/8 rule", "four-stage fourth-order variant of the classic method."),
    "ralston4": ("Ralston's fourth-order method", "four-stage method, minimal truncation error."),
    "bogacki_shampine3": ("Bogacki-Shampine 3(2)", "four-stage FSAL pair of orders 3 and 2."),
    "fehlberg45": ("Runge-Kutta-Fehlberg 4(5)", "six-stage pair of orders 5 and 4."),
    "cash_karp": ("Cash-Karp 5(4)", "six-stage pair of orders 5 and 4."),
    "dormand_prince5": ("Dormand-Prince 5(4)", "seven-stage FSAL pair of orders 5 and 4."),
    "tsitouras5": ("Tsitouras 5(4)", "seven-stage FSAL pair of orders 5 and 4."),
    "verner6": ("Verner 6(5)", "Verner's \"most efficient\" nine-stage FSAL pair."),
    "verner7": ("Verner 7(6)", "Verner's \"most efficient\" ten-stage pair."),
    "verner8": ("Verner 8(7)", "Verner's \"most efficient\" 13-stage pair."),
    "verner9": ("Verner 9(8)", "Verner's \"most efficient\" 16-stage pair."),
    "fehlberg78": ("Runge-Kutta-Fehlberg 7(8)", "13-stage pair of orders 8 and 7."),
    "dop853": ("Dormand-Prince 8(5,3)", "eighth-order method with two error estimators."),
    "backward_euler": ("Backward Euler", "the first-order implicit one-stage method."),
    "implicit_midpoint": ("Implicit midpoint rule", "the one-stage Gauss-Legendre method."),
    "trapezoidal": ("Trapezoidal rule", "two-stage Lobatto IIIA method, embedded Euler step."),
    "gauss_legendre4": ("Gauss-Legendre, 2 stages", "fourth-order collocation method."),
    "gauss_legendre6": ("Gauss-Legendre, 3 stages", "sixth-order collocation method."),
    "radau_iia3": ("Radau IIA, 2 stages", "third-order stiffly accurate collocation method."),
    "radau_iia5": ("Radau IIA, 3 stages", "fifth-order stiffly accurate collocation method."),
    "lobatto_iiia4": ("Lobatto IIIA, 3 stages", "fourth-order collocation method."),
    "lobatto_iiib4": ("Lobatto IIIB, 3 stages", "fourth-order partner of Lobatto IIIA."),
    "lobatto_iiic4": ("Lobatto IIIC, 3 stages", "fourth-order L-stable method."),
}
STRUCT_NAMES = {"rk4_38": "Rk4ThreeEighths"}  # names that plain CamelCase would garble

# Embedded pairs of the catalog that stormer does not offer: method -> why (the entry's
# `notes` in the data copy, hence the declaration's doc; also listed in docs/methods.md).
DROPPED_PAIRS = {
    "lobatto_iiib4": (
        "Embedded pair dropped: the source's b_hat = [-1/2, 2, -1/2] (order 2) gives "
        "b - b_hat = 2/3 (1, -2, 1), and the rows of A satisfy a_1 - 2 a_2 + a_3 = 0, so the "
        "error estimate h sum (b_i - b_hat_i) k_i is exactly zero on every linear problem "
        "(y' = lambda y, the harmonic oscillator) and adaptive steps would grow without "
        "limit. Fixed steps only."
    ),
}

KINDS = {  # file stem -> (module doc line, docs section title)
    "explicit": ("Explicit Runge-Kutta methods without an embedded error estimator.",
                 "Explicit methods"),
    "embedded": ("Explicit Runge-Kutta methods with an embedded error estimator (`b_hat`).",
                 "Embedded pairs (explicit, with `b_hat`)"),
    "implicit": ("Implicit Runge-Kutta methods (collocation and related).",
                 "Implicit methods"),
}


def struct_name(name):
    return STRUCT_NAMES.get(name) or "".join(p.capitalize() for p in name.split("_"))


def kind(m):
    if not m["explicit"]:
        return "implicit"
    return "embedded" if "b_hat" in m else "explicit"


# ---------------------------------------------------------------- coefficients

INT = re.compile(r"-?\d+")
RAT = re.compile(r"-?\d+/\d+")
DEC = re.compile(r"(-?)(\d*)(?:\.(\d*))?([eE][-+]?\d+)?")


def rust_literal(s):
    """The catalog string as a Rust expression token sequence (literal apart from `.5`/`1.`)."""
    s = s.strip()
    if INT.fullmatch(s) or RAT.fullmatch(s):
        return s
    m = DEC.fullmatch(s)
    if not m or not (m[2] or m[3]):
        raise ValueError(f"not a coefficient: {s!r}")
    sign, whole, frac, exp = m[1], m[2] or "0", m[3], m[4] or ""
    if frac is None:
        return f"{sign}{whole}{exp}"  # e.g. 5e-2, a valid Rust float literal
    return f"{sign}{whole}.{frac or '0'}{exp}"


def value(s):
    return Fraction(s.strip())


def show(s):
    """Display form for the doc tableau: exact if short, else ~12 significant digits."""
    if INT.fullmatch(s) or (RAT.fullmatch(s) and len(s) <= 16):
        return s
    x = value(s)
    with localcontext() as ctx:
        ctx.prec = 40
        mant, e, exp = format(Decimal(x.numerator) / x.denominator, ".12g").partition("e")
    if "." in mant:
        mant = mant.rstrip("0").rstrip(".")
    return mant + e + exp


# ---------------------------------------------------------------- doc comments

def md_escape(text):
    """Escape Markdown that free text from the catalog could trigger in rustdoc."""
    text = re.sub(r"([\\`*\[\]<~])", r"\\\1", text)
    return re.sub(r"(?<![A-Za-z0-9])_|_(?![A-Za-z0-9])", r"\\_", text)  # keep intraword b_hat


def wrap(text, width=WIDTH - 8):
    """Word-wrap without starting a line with something Markdown reads as a list or heading."""
    lines = []
    for word in text.split():
        risky = re.match(r"[-+*#>=|]|\d+[.)]", word)
        if lines and (len(lines[-1]) + 1 + len(word) <= width or risky):
            lines[-1] += " " + word
        else:
            lines.append(word)
    return lines


def grid(m, cells):
    """Butcher layout as in textbooks; None if it would be too wide."""
    s, explicit = len(m["c"]), m["explicit"]
    weights = [(k, cells[k]) for k in ("b", "b_hat", "b_hat3") if k in m]
    labels = [""] if len(weights) == 1 else [k for k, _ in weights]
    cw = max(len(x) for x in cells["c"] + labels)
    w = max(len(x) for row in cells["a"] + [v for _, v in weights] for x in row)

    def line(left, row):
        return (left.center(cw + 2) + "| " + "  ".join(x.center(w) for x in row)).rstrip()

    rows = [line(ci, row[:i] if explicit else row)
            for i, (ci, row) in enumerate(zip(cells["c"], cells["a"]))]
    rows.append("-" * (cw + 2) + "+" + "-" * (s * (w + 2)))
    rows += [line(lab, v) for lab, (_, v) in zip(labels, weights)]
    return rows if max(map(len, rows)) <= WIDTH - 8 else None


def compact(m, cells):
    """One labelled, wrapped line group per vector / row of `a` (used for large tableaus)."""
    explicit = m["explicit"]
    groups = [("c", cells["c"])]
    groups += [(f"a[{i + 1}]", row[:i] if explicit else row)
               for i, row in enumerate(cells["a"]) if i or not explicit]
    groups += [(k, cells[k]) for k in ("b", "b_hat", "b_hat3") if k in m]
    lw = max(len(k) for k, _ in groups) + 2
    w = max(len(x) for _, v in groups for x in v)
    per_line = max(1, (WIDTH - 8 - lw) // (w + 2))
    rows = []
    for label, v in groups:
        for j in range(0, len(v), per_line):
            left = label + ":" if j == 0 else ""
            chunk = "  ".join(x.rjust(w) for x in v[j:j + per_line])
            rows.append((left.ljust(lw) + chunk).rstrip())
    return rows


def doc_comment(m):
    title, desc = TITLES[m["name"]]
    aliases = ", ".join(m["aliases"])
    out = wrap(f"{title} ({md_escape(aliases)}) — {desc}") + [""]
    vectors = ["c", "b"] + [k for k in ("b_hat", "b_hat3") if k in m]
    cells = {k: [show(x) for x in m[k]] for k in vectors}
    cells["a"] = [[show(x) for x in row] for row in m["a"]]
    shown = [x for k in vectors for x in m[k]] + [x for row in m["a"] for x in row]
    abbreviated = any(value(show(x)) != value(x) for x in shown)
    rows = None if len(m["c"]) > 7 else grid(m, cells)
    if rows is None:
        rows = compact(m, cells)
        span = "a[i][1..i-1]" if m["explicit"] else "a[i][1..s]"
        out += [f"Compact listing: the line `a[i]` holds `{span}`.", ""]
    out += ["```text"] + rows + ["```", ""]
    if abbreviated:
        out += ["(coefficients abbreviated here; the declaration below is exact)", ""]
    emb = f" (embedded {m['embedded_order']})" if "embedded_order" in m else ""
    if "b_hat3" in m:
        emb = f" (embedded {m['embedded_order']}; `b_hat3` is a third-order estimator)"
    flags = [f for f, on in (("FSAL", m["fsal"]), ("symplectic", m["symplectic"]),
                             ("symmetric", m["symmetric"])) if on]
    s = len(m["c"])
    summary = f"Order {m['order']}{emb}, {s} stage{'s' * (s > 1)}; "
    out += wrap(summary + "; ".join(["explicit" if m["explicit"] else "implicit"] + flags) + ".")
    out += wrap(f"Reference: {md_escape(m['reference'])}.") + [""]
    out += wrap(f"Coefficients from {m['source_repo']} `{m['source_path']}`"
                f" at {m['source_commit'][:7]}.")
    return out + notes_and_closed_form(m)


def notes_and_closed_form(m):
    """The doc comment's last paragraphs, shared by every catalog: the entry's notes and its
    closed form, when it has them."""
    out = []
    if "notes" in m:
        out += [""] + wrap(f"Note: {md_escape(m['notes'])}")
    if "closed_form" in m:
        out += ["", "Closed form:", "", "```text"]
        for part in m["closed_form"].split("; "):
            out += textwrap.wrap(part, WIDTH - 8, subsequent_indent="    ", break_on_hyphens=False)
        out += ["```"]
    return out


# ---------------------------------------------------------------- Rust source

def array(prefix, items, indent, suffix=","):
    """`prefix[items]suffix` on one line if it fits, else wrapped with 4 extra spaces."""
    pad = " " * indent
    one = f"{pad}{prefix}[{', '.join(items)}]{suffix}"
    if len(one) <= WIDTH:
        return [one]
    lines, inner = [f"{pad}{prefix}["], pad + "    "
    for item in items:
        if len(lines) > 1 and len(lines[-1]) + len(item) + 2 <= WIDTH:
            lines[-1] += f" {item},"
        else:
            lines.append(f"{inner}{item},")
    return lines + [f"{pad}]{suffix}"]


def declaration(m):
    def lit(xs):
        return [rust_literal(x) for x in xs]

    out = ["crate::tableau! {"]
    out += [f"    /// {line}".rstrip() for line in doc_comment(m)]
    out += [f"    pub struct {struct_name(m['name'])} {{",
            f'        name: "{m["name"]}",',
            f"        order: {m['order']},"]
    out += array("c: ", lit(m["c"]), 8)
    out += ["        a: ["]
    out += [line for row in m["a"] for line in array("", lit(row), 12)]
    out += ["        ],"]
    out += array("b: ", lit(m["b"]), 8)
    if "b_hat" in m:
        out += array("b_hat: ", lit(m["b_hat"]), 8)
    if "embedded_order" in m:
        out += [f"        embedded_order: {m['embedded_order']},"]
    if "b_hat3" in m:
        out += array("b_hat3: ", lit(m["b_hat3"]), 8)
    if "dense" in m:
        out += ["        dense: ["]
        out += [line for row in m["dense"] for line in array("", lit(row), 12)]
        out += ["        ],", f"        dense_order: {m['dense_order']},"]
    if "dense_c" in m:
        out += array("dense_c: ", lit(m["dense_c"]), 8)
        out += ["        dense_a: ["]
        out += [line for row in m["dense_a"] for line in array("", lit(row), 12)]
        out += ["        ],"]
    return out + ["    }", "}"]


def generated_header(script, data):
    """The first lines of every generated Rust file: where it comes from, how to remake it."""
    return (f"// Generated by tools/{script}; do not edit. To change a method, edit\n"
            f"// {data} and run `python3 tools/{script} {data}`.\n")


HEADER = generated_header("gen_butcher_catalog.py", "data/butcher.toml")

TRANSCRIBED = """\
//! Coefficients are transcribed from the project's `data/butcher.toml` by
//! `tools/gen_butcher_catalog.py` and checked at compile time by the `tableau!` macro. The
//! same methods as data, by name: [`BUTCHER`], [`SPLITTING`], [`find`], [`names`] and the
//! names other libraries give them ([`ALIASES`]).
"""

MOD_RS = """\
//! The Butcher tableaus of the method catalog, one type per method.
//!
{transcribed}
mod composition;
mod embedded;
mod explicit;
mod implicit;
mod splitting;
mod splitting_list;

pub use composition::*;
pub use embedded::*;
pub use explicit::*;
pub use implicit::*;
pub use splitting::*;
pub(crate) use splitting_list::for_each_splitting_method;

// The same catalog as data lists, by name (src/registry.rs).
pub use crate::registry::{aliases_of, find, find_splitting, names, normalize, theta, ALIASES, BUTCHER, SPLITTING};

/// Invokes `$callback! {{ Euler, Midpoint, ... }}` with the type names of all {count} Butcher
/// tableaus above, in catalog order (used to build the method registry).
macro_rules! for_each_butcher_method {{
    ($callback:ident) => {{
        $callback! {{
{names}
        }}
    }};
}}
pub(crate) use for_each_butcher_method;
"""

DATA_HEADER = """\
# Butcher tableaus of the stormer method catalog, copied verbatim (same keys, sources and
# independent mpmath `checked` results) by tools/gen_butcher_catalog.py, except that an
# embedded pair the crate does not offer is removed (its `b_hat` and `embedded_order`;
# `notes` says why, `checked` still reports the source's pair). The crate's tests
# cross-check the `tableau!` declarations in src/catalog/ against this file.
# Coefficients are TOML strings: integer, exact rational "p/q", or decimal copied
# literally from the source; irrational closed forms are 40-digit decimals plus a
# `closed_form` text.
"""

# What follows the header of every data copy: the catalog's schema, conventions and sources.
DATA_TABLES = """\
schema_version = {schema_version}

[conventions]
{conventions}
[sources]  # repository -> commit the values were read at
{sources}

"""

METHODS_MD = """\
# The method list

The Butcher tableaus stormer ships, generated from `data/butcher.toml` by
`tools/gen_butcher_catalog.py`. `stormer methods` prints the same table from the compiled
catalog. Orders are verified (all rooted-tree conditions, mpmath); FSAL, symplectic and
symmetric are derived from the coefficients.
"""
COLUMNS = ["name", "order", "embedded order", "stages", "explicit", "FSAL", "symplectic",
           "symmetric", "reference"]


def module(stem, methods):
    body = [line for m in methods for line in [""] + declaration(m)]
    return f"{HEADER}//! {KINDS[stem][0]}\n//!\n{TRANSCRIBED}" + "\n".join(body) + "\n"


def mod_rs(methods):
    names = [struct_name(m["name"]) for m in methods]
    listed = textwrap.wrap(", ".join(names), WIDTH - 12,
                           initial_indent=" " * 12, subsequent_indent=" " * 12)
    return HEADER + MOD_RS.format(transcribed=TRANSCRIBED, count=len(names), names="\n".join(listed))


# ---------------------------------------------------------------- data copy and docs

def drop_pairs(text):
    """The catalog text without the embedded pairs of DROPPED_PAIRS: each such entry loses
    `b_hat` and `embedded_order` and gains its reason as `notes` (idempotent)."""
    head, *blocks = re.split(r"^(?=\[\[method\]\]$)", text, flags=re.M)
    out = [head]
    for block in blocks:
        name = re.search(r'^name = "(.*)"$', block, re.M)[1]
        if name in DROPPED_PAIRS:
            block = re.sub(r"^(?:b_hat|embedded_order) = (?:\[[^\]]*\]|.*)\n", "", block,
                           flags=re.M)
            note = f"notes = {json.dumps(DROPPED_PAIRS[name])}\n"
            if note not in block:
                assert not re.search(r"^notes = ", block, re.M), f"{name}: notes already set"
                block = re.sub(r"^(?=checked_ok = )", lambda _: note, block, count=1, flags=re.M)
                assert note in block, f"{name}: no checked_ok to put the note before"
        out.append(block)
    return "".join(out)


def data_copy(header, text, catalog, methods, conventions, families):
    """`header`, the tables of DATA_TABLES filled in (schema version, `conventions`, the sources
    of `methods`), then the verbatim text of each `[[method]]` block whose family matches the
    regex `families`."""
    repos = {m["source_repo"] for m in methods}
    blocks = re.split(r"^(?=\[\[method\]\]$)", text, flags=re.M)[1:]
    out = (header + "\n" + DATA_TABLES).format(
        schema_version=catalog["schema_version"],
        conventions=conventions,
        sources="\n".join(f'"{r}" = "{c}"' for r, c in catalog["sources"].items() if r in repos),
    ) + "\n".join(b.rstrip() + "\n" for b in blocks
                  if re.search(rf'^family = "{families}"$', b, re.M))
    assert tomllib.loads(out)["method"] == methods, "data copy differs from the catalog"
    return out


def data_toml(text, catalog, methods):
    """Header, conventions, sources and the verbatim text of each Butcher `[[method]]` block."""
    conventions = re.search(r'^butcher = """.*?"""\n', text, re.S | re.M)[0]
    return data_copy(DATA_HEADER, text, catalog, methods, conventions, "butcher")


def methods_md(methods):
    def row(cells):
        return "| " + " | ".join(str(x) for x in cells) + " |"

    yn = {True: "yes", False: "no"}
    out = [METHODS_MD]
    for stem, (_, title) in KINDS.items():
        out += [f"## {title}", "", row(COLUMNS), row(["---"] * len(COLUMNS))]
        out += [row([f"`{m['name']}`", m["order"], m.get("embedded_order", "—"), len(m["c"]),
                     yn[m["explicit"]], yn[m["fsal"]], yn[m["symplectic"]], yn[m["symmetric"]],
                     m["reference"].replace("|", "/")])
                for m in methods if kind(m) == stem]
        out += [""]
    out += ["## Embedded pairs not offered", ""]
    out += wrap("The reference catalog gives these methods an embedded `b_hat` that stormer "
                "leaves out, so they take fixed steps only (`--dt`; adaptive steps are "
                "refused, as for any method without an embedded order):") + [""]
    for name, why in DROPPED_PAIRS.items():
        lines = wrap(f"`{name}`: {why.removeprefix('Embedded pair dropped: ')}", WIDTH - 10)
        out += ["- " + lines[0]] + ["  " + line for line in lines[1:]]
    out += [""]
    return "\n".join(out)


# ---------------------------------------------------------------- main

def check(m):
    s = len(m["c"])
    assert m["stages"] == s and len(m["a"]) == s and all(len(r) == s for r in m["a"]), m["name"]
    assert all(len(m[k]) == s for k in ("b", "b_hat", "b_hat3") if k in m), m["name"]
    assert ("embedded_order" in m) == ("b_hat" in m), m["name"]


def main(path):
    text = drop_pairs(Path(path).read_text(encoding="utf-8"))
    catalog = tomllib.loads(text)
    methods = [m for m in catalog["method"] if m["family"] == "butcher"]
    for m in methods:
        check(m)
    files = {f"src/catalog/{stem}.rs": module(stem, [m for m in methods if kind(m) == stem])
             for stem in KINDS}
    files["src/catalog/mod.rs"] = mod_rs(methods)
    files["data/butcher.toml"] = data_toml(text, catalog, methods)
    files["docs/methods.md"] = methods_md(methods)
    write(files)


def write(files):
    """Writes each generated file (path relative to the repository -> content)."""
    for rel, content in files.items():
        (ROOT / rel).parent.mkdir(parents=True, exist_ok=True)
        (ROOT / rel).write_text(content, encoding="utf-8")
        print(f"wrote {rel}")


def run(main):
    """`main(path)` with the catalog path given on the command line."""
    if len(sys.argv) != 2:
        sys.exit(f"usage: {sys.argv[0]} path/to/catalog.toml")
    main(sys.argv[1])


if __name__ == "__main__":
    run(main)
