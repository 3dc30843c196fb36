//! Every method of the catalog through `stormer::verify::report`: the table of
//! `docs/verification.md` (measured order and embedded order, stability interval,
//! symplecticity and reversibility).
//!
//! ```sh
//! cargo run --release --example verify_catalog            # every method
//! cargo run --release --example verify_catalog -- rk4     # some methods
//! ```

use stormer::catalog;
use stormer::verify::conditions::stability::Interval;
use stormer::verify::report;
use stormer::Method;

fn main() -> Result<(), stormer::Error> {
    let only: Vec<String> = std::env::args().skip(1).collect();
    println!("| method | family | order | measured | on | embedded | stability | symplectic | reversible |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for name in catalog::names() {
        if !only.is_empty() && !only.iter().any(|o| o == name) {
            continue;
        }
        let r = report(&Method::named(name)?)?;
        let measured = match &r.order {
            Ok(m) => format!("{:.2}", m.order),
            Err(e) => format!("({e})"),
        };
        // declared and measured order of the embedded solution
        let embedded = match (&r.embedded_order, r.info.embedded_order) {
            (Some(Ok(m)), Some(q)) => format!("{q}: {:.2}", m.order),
            (Some(Err(e)), Some(q)) => format!("{q}: ({e})"),
            _ => String::new(),
        };
        let stability = match r.stability {
            Interval::Bounded(x) if x <= 0.0 => "0".into(),
            Interval::Bounded(x) => format!("{x:.4}"),
            Interval::Unbounded => "unbounded".into(),
        };
        let verdict = |holds: bool| if holds { "yes" } else { "no" };
        println!(
            "| {name} | {} | {} | {measured} | {} | {embedded} | {stability} | {} {:.1e} | {} {:.1e} |",
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
