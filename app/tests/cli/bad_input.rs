//! Bad input never panics: the binary on a corpus of bad scene and method files
//! and shards (tests/bad_input/, with what each must get in EXPECTED.txt) answers with one
//! clear error line and a non-zero exit, and the
//! parsers, fed arbitrary text, return errors instead of panicking (proptest).

use crate::support::binary::{self, stormer_ok, workdir};
use proptest::prelude::*;
use std::collections::HashMap;
use std::path::Path;
use std::process::Command;
use stormer::method::{Splitting, Tableau};
use stormer_app::scenes;

fn corpus() -> Vec<std::path::PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_input");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml" || e == "json"))
        .collect();
    files.sort();
    files
}

/// `bad_input/EXPECTED.txt`: what each file must get.
fn expected() -> HashMap<String, String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_input/EXPECTED.txt");
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let (file, text) = l.split_once(": ").expect("FILE: TEXT");
            (file.to_string(), text.to_string())
        })
        .collect()
}

/// Runs the binary with `args` in `dir` and checks the refusal every bad input gets (`what`
/// names the case in a failure): exit code 1, no panic, one line starting `error: `, which
/// it returns.
fn refusal(dir: &Path, args: &[&str], what: &str) -> String {
    let out = binary::stormer(dir, args);
    let stderr = binary::stderr(&out);
    assert_eq!(out.status.code(), Some(1), "{what}: exit code\n{stderr}");
    assert!(!stderr.contains("panicked"), "{what}: {stderr}");
    assert_eq!(stderr.trim().lines().count(), 1, "{what}: not one line:\n{stderr}");
    assert!(stderr.starts_with("error: "), "{what}: {stderr}");
    stderr
}

/// Every bad file: non-zero exit, one line on stderr with what EXPECTED.txt says it must
/// get, no panic.
#[test]
fn the_binary_refuses_every_bad_file_without_panicking() {
    let files = corpus();
    let expected = expected();
    assert!(files.len() >= 30);
    assert_eq!(files.len(), expected.len(), "one line of EXPECTED.txt per file");
    let dir = workdir("bad-input", "files");
    for file in files {
        let name = file.file_name().unwrap().to_string_lossy().to_string();
        let path = file.to_string_lossy().to_string();
        let args: Vec<&str> = if name.starts_with("scene_") {
            vec!["run", &path, "--t-end", "0.1"]
        } else if name.starts_with("shard_") {
            vec!["merge", &path]
        } else {
            vec!["verify", &path]
        };
        let stderr = refusal(&dir, &args, &name);
        let must = expected
            .get(&name)
            .unwrap_or_else(|| panic!("{name} is not in EXPECTED.txt"));
        assert!(stderr.contains(must), "{name}: expected {must:?} in\n{stderr}");
        assert!(stderr.contains(&name), "{name}: the file is not named in\n{stderr}");
    }
}

/// Bad values of the output flags: one clear line each, exit 1 (2 for flags clap refuses
/// together), no output created.
#[test]
fn the_binary_refuses_bad_output_flags_without_panicking() {
    let dir = workdir("bad-input", "output-flags");
    for (args, code, must) in [
        (
            &["run", "henon-heiles", "--section", "q = 0"][..],
            1,
            "--section: unknown column 'q'; this scene's columns are x, y, px, py (in 'q = 0')",
        ),
        (
            &["run", "henon-heiles", "--section", "x = 0, px >= zero"],
            1,
            "'= zero' is not a finite number",
        ),
        (
            &["run", "kepler", "--save-at", "5:-1:10"],
            1,
            "the step -1 does not lead from 5 to 10",
        ),
        (
            &["run", "kepler", "--save-at", "0:1:10", "--every", "3"],
            2,
            "'--save-at <TIMES>' cannot be used with '--every <N>'",
        ),
    ] {
        let out = binary::stormer(&dir, args);
        let stderr = binary::stderr(&out);
        assert_eq!(out.status.code(), Some(code), "{args:?}: exit code\n{stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(
            stderr.starts_with("error: ") && stderr.contains(must),
            "{args:?}: {stderr}"
        );
        if code == 1 {
            assert_eq!(stderr.trim().lines().count(), 1, "{args:?}: not one line:\n{stderr}");
        }
    }
    assert!(!dir.join("out").exists(), "no output for a refused run");
}

/// Bad `--vary` values of `stormer ensemble` (issue 15): an unknown key, an empty range, a
/// count of 0, and their kin: one clear line each, exit 1, no panic, nothing written.
#[test]
fn the_binary_refuses_bad_vary_flags_without_panicking() {
    let dir = workdir("bad-input", "vary");
    for (vary, must) in [
        (
            "alpah=10:50:41",
            "invalid --vary: unknown key 'alpah': did you mean 'initial.alpha'? the scene file's numbers are \
             parameters.g, parameters.rho,",
        ),
        ("method=1:2:3", "invalid --vary: unknown key 'method'"),
        (
            "alpha=50:10:41",
            "invalid --vary: the range 50.0:10.0 is empty: END must be above START (or equal to it, with COUNT 1) \
             (in 'alpha=50:10:41')",
        ),
        ("alpha=30:30:5", "the range 30.0:30.0 is empty"),
        (
            "alpha=10:50:0",
            "invalid --vary: COUNT must be >= 1, got 0 (in 'alpha=10:50:0')",
        ),
        ("alpha=10:50:many", "COUNT 'many' is not a whole number >= 1"),
        ("alpha=10:nan:4", "END 'nan' is not a finite number"),
        (
            "alpha",
            "expected NAME=START:END:COUNT, such as alpha=10:50:41 (in 'alpha')",
        ),
        (
            "every=1:2:4",
            "run.every is written as an integer in the scene file; 1.3333333333333333 is not one",
        ),
        (
            "alpha=10:50:100000000000",
            "more than the 10000000 members an ensemble runs",
        ),
    ] {
        let stderr = refusal(&dir, &["ensemble", "free-kick", "--vary", vary], vary);
        assert!(stderr.contains(must), "{vary}: {stderr}");
    }
    assert!(!dir.join("out").exists(), "no output for a refused ensemble");
}

/// Newton on many particles (issue #30, defect 2): gauss_legendre4's dense Newton matrices
/// for the 10^4 particles of `scenes/particles-bottle.toml` (60000 components) would take
/// 134 GiB; it aborted with "memory allocation of 28800000000 bytes failed" (exit 134).
/// Refused now at the first step, before the matrices are allocated: one error line with
/// the sizes, the limit and the fixed-point solver, exit 1, the initial record kept.
#[test]
fn newton_on_too_many_components_is_refused_before_allocating() {
    let dir = workdir("bad-input", "newton-size");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/particles-bottle.toml");
    let scene = scene.to_string_lossy();
    let args = [
        "run",
        &scene,
        "--method",
        "gauss_legendre4",
        "--solver",
        "newton",
        "--t-end",
        "0.02",
    ];
    let stderr = refusal(&dir, &args, "newton on particles-bottle");
    for must in [
        "method gauss_legendre4 cannot be used here: its Newton solver would need 134.1 GiB",
        "the 120000 x 120000 matrix of 2 stages of 60000 components and the 60000 x 60000 Jacobian",
        "more than the limit of 1.0 GiB (ImplicitOptions::newton_memory)",
        "use the fixed-point solver (--solver fixed-point)",
        "stopped after 0 steps; 1 records kept",
    ] {
        assert!(stderr.contains(must), "{must:?} not in {stderr}");
    }
}

/// A file the refused command must leave as it was: written, then read back after.
fn input(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).unwrap();
    }
    std::fs::write(&path, text).unwrap();
    text.to_string()
}

/// The text of the built-in scene `name`.
fn scene_text(name: &str) -> String {
    let out = stormer_ok(Path::new("."), &["scene", "show", name]);
    String::from_utf8(out.stdout).unwrap()
}

/// Velocity Verlet as a method file.
const VERLET: &str =
    "name = \"m\"\nfamily = \"splitting\"\norder = 2\ndrift = [\"0\", \"1\"]\nkick = [\"1/2\", \"1/2\"]\n";

/// Issue #30, item 12: no file a command writes (its CSV, its pictures, its section, its
/// tables) may be one of its inputs (the scene file, a method file), whatever the input is
/// named: `stormer scene show harmonic > h-state.svg; stormer run h-state.svg --out h.csv`
/// drew the state picture over the scene. Every output kind of `run`, each refused before
/// anything is written, the input intact.
#[test]
fn no_output_of_a_run_replaces_its_input() {
    let dir = workdir("bad-input", "run-outputs");
    for (file, scene, args) in [
        // the pictures beside the CSV: state, energy (harmonic), x-y (kepler), x-z (3-D)
        ("h-state.svg", "harmonic", &["--out", "h.csv"][..]),
        ("h-energy.svg", "harmonic", &["--out", "h.csv"]),
        ("k-xy.svg", "kepler", &["--out", "k.csv"]),
        ("s-xz.svg", "outer-solar-system", &["--out", "s.csv", "--t-end", "100"]),
        // the section's CSV and picture
        (
            "p-section.csv",
            "henon-heiles",
            &["--out", "p.csv", "--section", "x = 0, px > 0"],
        ),
        (
            "p-section.svg",
            "henon-heiles",
            &["--out", "p.csv", "--section", "x = 0, px > 0"],
        ),
        // the CSV itself
        ("c.csv", "harmonic", &["--out", "c.csv"]),
    ] {
        let kept = input(&dir, file, &scene_text(scene));
        let mut all = vec!["run", file];
        all.extend(args);
        let stderr = refusal(&dir, &all, file);
        assert!(
            stderr.contains(&format!("{file} is the input file")),
            "{file}: {stderr}"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join(file)).unwrap(),
            kept,
            "{file} was replaced"
        );
    }
    // a method file named like a picture, by a bare name and by a path
    for method in ["h-energy.svg", "./h-state.svg"] {
        let kept = input(&dir, method.trim_start_matches("./"), VERLET);
        let stderr = refusal(&dir, &["run", "harmonic", "--method", method, "--out", "h.csv"], method);
        assert!(stderr.contains("is the input file"), "{method}: {stderr}");
        assert_eq!(
            std::fs::read_to_string(dir.join(method)).unwrap(),
            kept,
            "{method} was replaced"
        );
    }
    // with the CSV on stdout the pictures go beside the default output
    let kept = input(&dir, "out/harmonic-m-energy.svg", VERLET);
    let args = ["run", "harmonic", "--method", "out/harmonic-m-energy.svg", "--out", "-"];
    let stderr = refusal(&dir, &args, "stdout");
    assert!(stderr.contains("is the input file"), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(dir.join("out/harmonic-m-energy.svg")).unwrap(),
        kept
    );
    assert!(
        !dir.join("h.csv").exists() && !dir.join("p.csv").exists(),
        "nothing written"
    );
}

/// Issue #30, item 12, for the studies: `compare`'s table and charts, `scan`'s, an
/// ensemble's table and heat map, a shard's partial table and `merge`'s outputs never
/// replace a method file or a part named like them.
#[test]
fn no_output_of_a_study_replaces_its_input() {
    let dir = workdir("bad-input", "study-outputs");
    let study = ["--dt", "0.1", "--t-end", "1", "--out", "d"];
    for (file, command) in [
        (
            "d/compare-harmonic-energy.svg",
            &["compare", "harmonic", "--methods"][..],
        ),
        ("d/compare-harmonic.md", &["compare", "harmonic", "--methods"]),
        (
            "d/compare-harmonic.shard-1-of-2.json",
            &["compare", "harmonic", "--shard", "1/2", "--methods"],
        ),
        (
            "d/scan-harmonic-m.svg",
            &["scan", "harmonic", "--steps", "10,20", "--method"],
        ),
        (
            "d/ensemble-harmonic-w0.svg",
            &["ensemble", "harmonic", "--vary", "w0=1:2:2", "--method"],
        ),
    ] {
        let kept = input(&dir, file, VERLET);
        let mut args = command.to_vec();
        args.push(file);
        // scan takes steps, not step sizes
        let skip = if command[0] == "scan" { 2 } else { 0 };
        args.extend(&study[skip..]);
        let stderr = refusal(&dir, &args, file);
        assert!(stderr.contains("is the input file"), "{file}: {stderr}");
        assert_eq!(
            std::fs::read_to_string(dir.join(file)).unwrap(),
            kept,
            "{file} was replaced"
        );
    }
    // the parts of a sharded study, one named like the merged study's chart
    let base = [
        "compare",
        "harmonic",
        "--methods",
        "rk4",
        "--dt",
        "0.1",
        "--t-end",
        "1",
        "--out",
        "p",
    ];
    for shard in ["1/2", "2/2"] {
        let mut args = base.to_vec();
        args.extend(["--shard", shard]);
        stormer_ok(&dir, &args);
    }
    let chart = dir.join("p/compare-harmonic-energy.svg");
    std::fs::rename(dir.join("p/compare-harmonic.shard-1-of-2.json"), &chart).unwrap();
    let kept = std::fs::read_to_string(&chart).unwrap();
    let args = [
        "merge",
        "p/compare-harmonic-energy.svg",
        "p/compare-harmonic.shard-2-of-2.json",
        "--out",
        "p",
    ];
    let stderr = refusal(&dir, &args, "merge");
    assert!(stderr.contains("is the input file"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&chart).unwrap(), kept);
}

/// Issue #30, item 13: a file named `rk4` in the working directory does not shadow the
/// catalog's `rk4` (a method file is a path with a separator or `.toml`, or a bare name
/// the catalog does not know).
#[test]
fn a_stray_file_does_not_shadow_a_catalog_method() {
    let dir = workdir("bad-input", "stray-file");
    std::fs::write(dir.join("rk4"), "not a method\n").unwrap();
    let out = stormer_ok(
        &dir,
        &["run", "harmonic", "--method", "rk4", "--t-end", "0.1", "--out", "h.csv"],
    );
    assert!(
        binary::stderr(&out).contains("rk4 on harmonic: 100 steps"),
        "{}",
        binary::stderr(&out)
    );
    let out = stormer_ok(&dir, &["verify", "rk4"]);
    assert!(binary::stdout(&out).contains("source          catalog"));
    // the file is still read when asked for as a path
    let stderr = refusal(&dir, &["verify", "./rk4"], "./rk4");
    assert!(stderr.contains("invalid method ./rk4"), "{stderr}");
    // and a bare name the catalog does not know reads the file of that name
    std::fs::write(dir.join("my_verlet"), VERLET).unwrap();
    let out = stormer_ok(&dir, &["verify", "my_verlet"]);
    assert!(binary::stdout(&out).contains("source          my_verlet"));
}

/// Issue #30, item 8: `verify` on a composition whose weights are `[0, 1]` (the base
/// method itself: `S(0)` is no step) passed its checks but exited 1 saying "the
/// coefficients say symmetric = no"; and the method-file keys the guide promises
/// (`word`, `quadratic_kinetic`, the macro's names) are read.
#[test]
fn verify_agrees_with_the_guide_on_method_files() {
    let dir = workdir("bad-input", "verify-guide");
    std::fs::write(
        dir.join("c01.toml"),
        "name = \"c01\"\norder = 2\ngamma = [\"0\", \"1\"]\n",
    )
    .unwrap();
    let out = stormer_ok(&dir, &["verify", "c01.toml"]);
    assert!(
        binary::stdout(&out).contains("symmetric       yes"),
        "{}",
        binary::stdout(&out)
    );
    // McLachlan's two-stage method written as a word, as define-your-own-scheme.md shows
    let word = "name = \"my_mclachlan2\"\norder = 2\nquadratic_kinetic = false\nword = [\"kick(0.1931833275037836)\", \
                \"drift(1/2)\", \"kick(1 - 2 * 0.1931833275037836)\", \"drift(1/2)\", \"kick(0.1931833275037836)\"]\n";
    std::fs::write(dir.join("word.toml"), word).unwrap();
    let out = stormer_ok(&dir, &["verify", "word.toml"]);
    let text = binary::stdout(&out);
    assert!(
        text.contains("family          splitting") && text.contains("FSAL            yes"),
        "{text}"
    );
    let out = stormer_ok(
        &dir,
        &[
            "run",
            "harmonic",
            "--method",
            "word.toml",
            "--t-end",
            "1",
            "--out",
            "w.csv",
        ],
    );
    assert!(binary::stderr(&out).contains("my_mclachlan2 on harmonic"));
}

/// Issue #30, item 14: `--save-at` counts its times before making them, and refuses too
/// many at once, before the scene is even read (it built 1e8 times, 2.35 GB, first).
#[test]
fn too_many_output_times_are_refused_before_anything_else() {
    let dir = workdir("bad-input", "save-at-count");
    let start = std::time::Instant::now();
    let stderr = refusal(
        &dir,
        &["run", "no-such-scene", "--save-at", "0:1.0000001e-7:10"],
        "save-at",
    );
    assert!(
        stderr.contains("'0:1.0000001e-7:10' gives 99999991 output times, more than the 10000000 a run writes"),
        "{stderr}"
    );
    assert!(start.elapsed().as_secs() < 10, "took {:?}", start.elapsed());
}

/// Issue #30, item 14: a run whose CSV will be huge says so, with its size and how to
/// write less, before its first row (`run harmonic --dt 1.0000001e-7` wrote 7.4 GB
/// without a word). The run is stopped once the note is read.
#[test]
fn a_huge_run_says_so_before_it_starts() {
    use std::io::BufRead;
    let dir = workdir("bad-input", "huge-run");
    let mut child = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(["run", "harmonic", "--dt", "1.0000001e-7", "--out", "/dev/null"])
        .current_dir(&dir)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let stderr = child.stderr.take().unwrap();
    let (send, receive) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in std::io::BufReader::new(stderr).lines() {
            let _ = send.send(line.unwrap_or_default());
        }
    });
    let first = receive.recv_timeout(std::time::Duration::from_secs(60));
    child.kill().unwrap();
    child.wait().unwrap();
    let first = first.expect("a line on stderr within a minute");
    assert_eq!(
        first,
        "note: this run will write up to 99999993 rows (about 7.7 GB) to /dev/null; --every N writes one row in N \
         steps (--every 100 about 77 MB)"
    );
}

/// Issue #30, item 19: the README counts the methods `stormer methods` lists, family by
/// family, and docs/library.md the catalog's.
#[test]
fn the_readme_counts_the_methods_that_stormer_methods_lists() {
    let out = stormer_ok(Path::new("."), &["methods", "--json"]);
    let methods: Vec<serde_json::Value> = serde_json::from_slice(&out.stdout).unwrap();
    let count = |family: &str| methods.iter().filter(|m| m["family"] == family).count();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let readme = std::fs::read_to_string(root.join("README.md"))
        .unwrap()
        .replace('\n', " ");
    let listed = format!(
        "lists the {} methods: {} Butcher tableaus",
        methods.len(),
        count("butcher")
    );
    assert!(readme.contains(&listed), "README.md does not say {listed:?}");
    for (n, what) in [
        (count("splitting"), "splittings"),
        (count("composition"), "compositions"),
        (count("charged-particle"), "charged-particle pushers"),
        (count("relativistic-particle"), "relativistic pushers"),
    ] {
        assert!(
            readme.contains(&format!("{n} {what}")),
            "README.md does not say {n} {what}"
        );
    }
    let catalog = count("butcher") + count("splitting") + count("composition");
    let library = std::fs::read_to_string(root.join("docs/library.md"))
        .unwrap()
        .replace('\n', " ");
    let says = format!("(the {catalog} Butcher tableaus, splittings and compositions as data)");
    assert!(library.contains(&says), "docs/library.md does not say {says:?}");
}

/// The text files of the repository that cite pages: code, tests, benches, scene files,
/// docs (not the build output).
fn repository_texts() -> Vec<std::path::PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = vec![root.join("README.md")];
    let mut dirs: Vec<_> = [
        "src",
        "tests",
        "benches",
        "docs",
        "scenes",
        "order",
        "macros",
        "app/src",
        "app/tests",
    ]
    .iter()
    .map(|d| root.join(d))
    .collect();
    dirs.extend(["app/benches", "app/examples"].iter().map(|d| root.join(d)));
    while let Some(dir) = dirs.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else { continue };
        for entry in entries {
            let path = entry.unwrap().path();
            if path.is_dir() && !path.ends_with("target") {
                dirs.push(path);
            } else if path
                .extension()
                .is_some_and(|e| ["rs", "md", "toml", "py"].contains(&e.to_str().unwrap()))
            {
                files.push(path);
            }
        }
    }
    files
}

/// Issue #30, item 19: the code cited the users' scene page and the design page outside the
/// repository, 99 times; it cites the project's own docs/scenes.md and docs/design.md, and
/// every `docs/PAGE.md` the texts name exists.
#[test]
fn every_page_cited_is_in_the_repository() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let foreign = [["SCENES", ".md"].concat(), ["DESIGN", ".md"].concat()];
    let mut missing = Vec::new();
    for file in repository_texts() {
        let text = std::fs::read_to_string(&file).unwrap_or_default();
        for name in &foreign {
            if text.contains(name.as_str()) {
                missing.push(format!("{} cites {name}", file.display()));
            }
        }
        for (i, _) in text.match_indices("docs/") {
            let page: String = text[i + 5..]
                .chars()
                .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '-')
                .collect();
            if text[i + 5 + page.len()..].starts_with(".md") && !root.join("docs").join(format!("{page}.md")).is_file()
            {
                missing.push(format!("{} cites docs/{page}.md", file.display()));
            }
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Arbitrary text to every parser: a value or an error, never a panic.
    #[test]
    fn parsers_never_panic_on_arbitrary_text(text in "\\PC{0,200}") {
        let _ = scenes::parse(&text, "arbitrary.toml", "arbitrary");
        let _ = Tableau::from_toml_str(&text, "arbitrary.toml");
        let _ = Splitting::from_toml_str(&text, "arbitrary.toml");
    }

    /// Well-formed TOML with arbitrary numbers (NaN, infinities, huge, negative) in every
    /// field of a scene and of a method file.
    #[test]
    fn parsers_never_panic_on_arbitrary_numbers(x in any::<f64>(), y in any::<f64>(), n in any::<i64>()) {
        let fmt = |v: f64| if v.is_nan() { "nan".to_string() } else if v.is_infinite() { if v > 0.0 { "inf".into() } else { "-inf".into() } } else { format!("{v:e}") };
        let scene = format!(
            "model = \"pendulum\"\n[initial]\ntheta = {}\nomega = {}\n[run]\ndt = {}\nt_end = {}\nevery = {n}\n",
            fmt(x), fmt(y), fmt(y), fmt(x)
        );
        let _ = scenes::parse(&scene, "numbers.toml", "numbers");
        let nbody = format!(
            "model = \"n-body\"\n[parameters]\nG = {}\n[[bodies]]\nname = \"a\"\nmass = {}\nposition = [{}, 0.0, 0.0]\nvelocity = [0.0, {}, 0.0]\n[[bodies]]\nname = \"b\"\nmass = 1.0\nposition = [0.0, 0.0, 0.0]\nvelocity = [0.0, 0.0, 0.0]\n",
            fmt(x), fmt(y), fmt(x), fmt(y)
        );
        let _ = scenes::parse(&nbody, "nbody.toml", "nbody");
        let method = format!("name = \"m\"\norder = {}\na = [[{}]]\nb = [{}]\n", n.rem_euclid(20), fmt(x), fmt(y));
        let _ = Tableau::from_toml_str(&method, "method.toml");
        let split = format!("name = \"s\"\nfamily = \"splitting\"\norder = {}\ndrift = [{}]\nkick = [{}]\n", n.rem_euclid(20), fmt(x), fmt(y));
        let _ = Splitting::from_toml_str(&split, "split.toml");
    }
}
