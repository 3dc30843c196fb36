//! The library builds without the application's dependencies: a crate that depends on
//! `stormer` with its default features compiles no clap, no plotters and none of the
//! application's other crates.

use std::process::Command;

#[test]
fn the_library_compiles_none_of_the_applications_dependencies() {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let out = Command::new(cargo)
        .args([
            "tree",
            "--offline",
            "-p",
            "stormer",
            "-e",
            "normal,build",
            "--prefix",
            "none",
            "--format",
            "{p}",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo runs");
    let tree = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "cargo tree failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let crates: Vec<&str> = tree.lines().filter_map(|l| l.split_whitespace().next()).collect();
    assert!(crates.contains(&"nalgebra"), "the tree was read: {crates:?}");
    for application_only in [
        "clap",
        "plotters",
        "indicatif",
        "rayon",
        "ctrlc",
        "anyhow",
        "serde_json",
    ] {
        assert!(
            !crates.contains(&application_only),
            "the library depends on {application_only}: {tree}"
        );
    }
}
