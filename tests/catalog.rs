//! The compiled catalog against independent data: every `tableau!` declaration in
//! `src/catalog/` equals the entry of `data/butcher.toml` (a verbatim copy of the
//! project's checked method catalog), bitwise, with the same derived flags.

use stormer::{registry, Tableau};

fn catalog() -> Vec<Tableau> {
    let text = include_str!("../data/butcher.toml");
    Tableau::all_from_toml_str(text, "data/butcher.toml").expect("the data file is valid")
}

#[test]
fn every_compiled_method_matches_the_data_file() {
    let file = catalog();
    assert_eq!(file.len(), 31);
    assert_eq!(registry::BUTCHER.len(), file.len());
    for (data, entry) in registry::BUTCHER.iter().zip(&file) {
        assert_eq!(data.name, entry.name(), "catalog order");
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(data.a), bits(entry.a()), "{}: a", data.name);
        assert_eq!(bits(data.b), bits(entry.b()), "{}: b", data.name);
        assert_eq!(bits(data.c), bits(entry.c()), "{}: c", data.name);
        assert_eq!(data.b_hat.map(bits), entry.b_hat().map(bits), "{}: b_hat", data.name);
        assert_eq!(data.b_hat3.map(bits), entry.b_hat3().map(bits), "{}: b_hat3", data.name);
        assert_eq!(data.order, entry.order(), "{}: order", data.name);
        assert_eq!(
            data.embedded_order,
            entry.embedded_order(),
            "{}: embedded order",
            data.name
        );
        assert_eq!(data.flags, entry.flags(), "{}: flags", data.name);
        assert_eq!(data.stages, entry.stages(), "{}: stages", data.name);
    }
}

#[test]
fn declared_order_is_exact() {
    // The data reach their declared order and no more (the next order's conditions fail),
    // so no method is listed below what it achieves.
    for data in registry::BUTCHER {
        let limit = (data.order + 1).min(stormer::order::MAX_ORDER);
        let reached = stormer::order::achieved_order(data.a, data.b, limit, stormer::order::DEFAULT_TOLERANCE);
        assert_eq!(reached, data.order, "{}", data.name);
    }
}

#[test]
fn a_changed_rk4_coefficient_is_a_runtime_error_naming_the_condition() {
    let rk4 = r#"
        name = "rk4-typo"
        order = 4
        c = ["0", "1/2", "1/2", "1"]
        a = [["0"], ["1/2"], ["0", "1/2"], ["0", "0", "1"]]
        b = ["1/6", "1/3", "1/3", "1/6"]
    "#;
    assert!(Tableau::from_toml_str(rk4, "inline").is_ok());
    let typo = rk4.replace(
        r#"b = ["1/6", "1/3", "1/3", "1/6"]"#,
        r#"b = ["1/6", "1/3", "1/4", "1/4"]"#,
    );
    let err = Tableau::from_toml_str(&typo, "inline").unwrap_err().to_string();
    assert!(err.contains("order 2 condition sum b_i c_i = 1/2 fails"), "{err}");
}

#[test]
fn flags_declared_in_a_file_must_agree_with_the_data() {
    let text = r#"
        name = "heun-claimed-symplectic"
        order = 2
        symplectic = true
        a = [["0", "0"], ["1", "0"]]
        b = ["1/2", "1/2"]
    "#;
    let err = Tableau::from_toml_str(text, "inline").unwrap_err().to_string();
    assert!(err.contains("declares symplectic = true"), "{err}");
}

/// Every `splitting!` / `composition!` declaration equals its entry of
/// `data/splitting.toml`, bitwise; the file's declared stages (force evaluations per step
/// after FSAL, from the catalog), FSAL and symmetry agree with what the macros derived
/// (the file loader rejects a disagreement).
#[test]
fn every_compiled_splitting_matches_the_data_file() {
    use stormer::Splitting;
    let text = include_str!("../data/splitting.toml");
    let file = Splitting::all_from_toml_str(text, "data/splitting.toml").expect("the data file is valid");
    assert_eq!(file.len(), 58);
    assert_eq!(registry::SPLITTING.len(), file.len());
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    for entry in &file {
        let data = registry::SPLITTING
            .iter()
            .find(|d| d.name == entry.name())
            .unwrap_or_else(|| panic!("{} is not compiled", entry.name()));
        assert_eq!(data.family, entry.family(), "{}: family", data.name);
        assert_eq!(bits(data.drift), bits(entry.drift()), "{}: drift", data.name);
        assert_eq!(bits(data.kick), bits(entry.kick()), "{}: kick", data.name);
        assert_eq!(data.gamma.map(bits), entry.gamma().map(bits), "{}: gamma", data.name);
        assert_eq!(data.order, entry.order(), "{}: order", data.name);
        assert_eq!(data.stages, entry.stages(), "{}: stages", data.name);
        assert_eq!(data.flags, entry.flags(), "{}: flags", data.name);
        assert_eq!(
            data.requires_quadratic_kinetic,
            entry.requires_quadratic_kinetic(),
            "{}: quadratic kinetic",
            data.name
        );
    }
}
