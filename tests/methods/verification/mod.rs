//! The verification module on the whole catalog: symplecticity to round-off for every
//! symplectic method (property tests over random states and steps, with negative
//! controls), measured order equal to the declared one, and the algebraic symplecticity
//! and symmetry of the Butcher tableaus agreeing with the numerical checks.
//!
//! A module of the `methods` test binary, with a submodule per concept.

mod agreement;
mod dual;
mod order;
mod structure;
mod symplectic;

use std::sync::OnceLock;
use stormer::catalog;
use stormer::verify::{report, Report};
use stormer::Method;

/// `stormer::verify::report` (what `stormer verify` prints) of every catalog method, in
/// the order of `catalog::names()`: computed once for the tests that read it.
pub fn catalog_reports() -> &'static [Report] {
    static REPORTS: OnceLock<Vec<Report>> = OnceLock::new();
    REPORTS.get_or_init(|| {
        catalog::names()
            .map(|name| report(&Method::named(name).unwrap()).unwrap())
            .collect()
    })
}

/// The report of one catalog method.
pub fn catalog_report(name: &str) -> &'static Report {
    catalog_reports()
        .iter()
        .find(|r| r.info.name == name)
        .unwrap_or_else(|| panic!("{name} is not in the catalog"))
}

/// The catalog's splittings and compositions, by the class of problems they are valid
/// for, invoked as `$callback! { general: [..], quadratic: [..] }`. Every entry of
/// `catalog::SPLITTING` must be here: `order::every_splitting_has_its_generated_tests`
/// checks it, so a new catalog method cannot be left untested.
#[macro_export]
macro_rules! for_each_catalog_splitting {
    ($callback:ident) => {
        $callback! {
            general: [
                symplectic_euler_dk, symplectic_euler_kd, stormer_verlet_dkd, velocity_verlet_kdk,
                mclachlan_atela2, mclachlan_s2, ruth3, mclachlan_atela3, forest_ruth4, pefrl,
                mclachlan_s4, mclachlan_s5, mclachlan_sb3a4, mclachlan_sb3a5, blanes_moan_s6,
                blanes_moan_s10, blanes_moan_srkn6b, saba1, saba2, saba3, saba4, sbab1, sbab2,
                sbab3, sbab4, aba1004, aba864, aba1064, abah844, abah864, abah1064, triple_jump4,
                suzuki_fractal4, mclachlan_ss5, yoshida6a, yoshida6b, yoshida6c, triple_jump6,
                mclachlan_ss9, kahan_li6, sofroniou_spaletta6_s11, sofroniou_spaletta6_s13,
                yoshida8a, yoshida8b, yoshida8c, yoshida8d, yoshida8e, mclachlan_ss15,
                mclachlan_ss17, kahan_li8, sofroniou_spaletta8_s21, sofroniou_spaletta10
            ],
            quadratic: [
                mclachlan_atela4, mclachlan_atela5, calvo_sanz_serna4, blanes_moan_srkn11b,
                blanes_moan_srkn14a, okunbor_skeel6
            ],
        }
    };
}
