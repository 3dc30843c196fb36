//! Every method of the catalog through `stormer::verify::report`: the table of
//! `docs/verification.md`.
//!
//! ```sh
//! cargo run --release --example verify_catalog            # every method
//! cargo run --release --example verify_catalog -- rk4     # some methods
//! ```

use stormer::registry;
use stormer::verify::{report, Scheme};

fn main() -> Result<(), stormer::Error> {
    let only: Vec<String> = std::env::args().skip(1).collect();
    println!(
        "| method | family | order | measured | on | symplectic: max abs(J^T S J - S) | reversible: abs(back - y) |"
    );
    println!("|---|---|---|---|---|---|---|");
    for name in registry::names() {
        if !only.is_empty() && !only.iter().any(|o| o == name) {
            continue;
        }
        let r = report(&Scheme::named(name)?)?;
        let measured = match &r.order {
            Ok(m) => format!("{:.2}", m.order),
            Err(e) => format!("({e})"),
        };
        let verdict = |holds: bool| if holds { "yes" } else { "no" };
        println!(
            "| {name} | {} | {} | {measured} | {} | {} {:.1e} | {} {:.1e} |",
            r.info.family,
            r.info.order,
            r.order_problem,
            verdict(r.symplectic.holds),
            r.symplectic.defect,
            verdict(r.reversible.holds),
            r.reversible.defect,
        );
    }
    Ok(())
}
