//! Runs paused and resumed (`Driver::pause_at`, `Driver::run_resumable`, `Stepper::save` /
//! `restore`, docs/reproducibility.md): a run cut into pieces, its state carried between
//! them through JSON and a new stepper each time, makes bit for bit the records, events and
//! statistics of the run that was not cut, for every loop of the driver (fixed steps in
//! place and not, adaptive, reversible) and every stepper that keeps a state (a FSAL
//! derivative, an implicit starting guess, a compensated carry, output and event
//! bookkeeping).
// the error of a run carries its solution, by design
#![allow(clippy::result_large_err)]

use stormer::driver::{Crossing, RunState, Solution, Stats};
use stormer::models::CentralForce;
use stormer::stepper::{ImplicitOptions, Tolerances};
use stormer::{Driver, Error, Method, Stepper};

type Kepler = CentralForce<f64, [f64; 4]>;

const Y0: [f64; 4] = [0.5, 0.0, 0.0, 1.7320508075688772]; // e = 0.5, a = 1, at pericentre

fn stepper(name: &str, implicit: &ImplicitOptions) -> Box<dyn Stepper<Kepler>> {
    Method::named(name)
        .unwrap()
        .stepper_for(&Kepler::new(1.0), &Y0, implicit)
        .unwrap()
}

/// Everything a run produced, as bits: record times, states, energies, events, stats.
#[derive(Debug, PartialEq)]
struct Bits {
    records: Vec<u64>,
    events: Vec<u64>,
    stats: Stats,
}

fn bits_of(s: &Solution<f64, [f64; 4]>) -> Vec<u64> {
    let mut out = Vec::new();
    for (i, t) in s.t.iter().enumerate() {
        out.push(t.to_bits());
        out.extend(s.y[i].iter().map(|x| x.to_bits()));
        out.extend(s.energy.get(i).map(|e| e.to_bits()));
    }
    out
}

fn event_bits(s: &Solution<f64, [f64; 4]>) -> Vec<u64> {
    let mut out = Vec::new();
    for hit in &s.events {
        out.push(hit.index as u64);
        out.push(hit.t.to_bits());
        out.extend(hit.y.iter().map(|x| x.to_bits()));
    }
    out
}

/// The run of `driver` with `method` to `t_end`: whole, then cut before each step of
/// `pauses`, each piece with a new stepper and the state read back from JSON. Both must
/// be bitwise equal; returns the pieces' stats of the whole run.
fn whole_and_cut<'a>(
    method: &str,
    implicit: &ImplicitOptions,
    driver: impl Fn() -> Driver<'a, f64, [f64; 4]>,
    t_end: f64,
    pauses: &[u64],
) -> Stats {
    let p = Kepler::new(1.0);
    let mut whole = Solution::default();
    let done = driver().run_resumable(&p, &mut stepper(method, implicit), 0.0, &Y0, t_end, &mut whole, None);
    let (stats, _) = done.outcome.unwrap_or_else(|(_, e)| panic!("{method}: {e}"));
    let whole = Bits {
        records: bits_of(&whole),
        events: event_bits(&whole),
        stats,
    };
    let mut cut = Solution::default();
    let mut from: Option<RunState> = None;
    let mut last = None;
    for pause in pauses.iter().copied().chain([u64::MAX]) {
        let mut fresh = stepper(method, implicit);
        let run = driver()
            .pause_at(pause)
            .run_resumable(&p, &mut fresh, 0.0, &Y0, t_end, &mut cut, from.as_ref());
        match run.outcome {
            Ok((stats, _)) => {
                last = Some(stats);
                break;
            }
            Err((_, Error::Cancelled { step, .. })) => {
                assert_eq!(step, pause, "{method}: paused elsewhere");
                let text = serde_json::to_string(&run.paused.expect("a paused run hands back its state")).unwrap();
                from = Some(serde_json::from_str(&text).unwrap());
            }
            Err((_, e)) => panic!("{method} paused at {pause}: {e}"),
        }
    }
    let cut = Bits {
        records: bits_of(&cut),
        events: event_bits(&cut),
        stats: last.expect("the last piece ends the run"),
    };
    assert_eq!(cut, whole, "{method}: the cut run differs from the whole one");
    whole.stats
}

#[test]
fn fixed_steps_in_place_and_not_resume_bitwise() {
    let fixed = || Driver::fixed(0.01).every(7);
    // a splitting steps in place (its FSAL force kept across the cut), rk4 does not
    for method in ["velocity_verlet_kdk", "triple_jump4", "rk4", "dop853"] {
        let stats = whole_and_cut(method, &Default::default(), fixed, 3.0, &[1, 50, 51, 177, 299]);
        assert_eq!(stats.steps, 300);
    }
}

#[test]
fn adaptive_steps_with_events_and_a_stop_resume_bitwise() {
    let adaptive = || {
        Driver::adaptive(Tolerances::new(1e-8, 1e-8))
            .every(3)
            .event(|_t, y: &[f64; 4]| y[1], Crossing::Either, false)
            .stop_when(|t, _y: &[f64; 4]| t - 9.5)
    };
    for method in ["dormand_prince5", "dop853", "bogacki_shampine3"] {
        let stats = whole_and_cut(method, &Default::default(), adaptive, 20.0, &[2, 3, 40, 41, 90]);
        assert!(stats.rejected > 0 || method != "bogacki_shampine3", "{stats:?}");
    }
}

#[test]
fn output_times_on_the_hermite_interpolants_resume_bitwise() {
    // rk4 (order 4): the quintic Hermite, its slope and second derivative at a step's end
    // reused by the next; velocity Verlet: the cubic, its end slope reused
    let times: Vec<f64> = (0..=100).map(|k| 0.0299 * k as f64).collect();
    for method in ["rk4", "velocity_verlet_kdk"] {
        let times = times.clone();
        let at = move || {
            Driver::fixed(0.01)
                .save_at(times.clone())
                .event(|_t, y: &[f64; 4]| y[0], Crossing::Rising, false)
        };
        whole_and_cut(method, &Default::default(), at, 3.0, &[5, 6, 150, 299]);
    }
}

#[test]
fn implicit_steps_resume_with_their_starting_guess() {
    let newton = ImplicitOptions::newton();
    let fixed = || Driver::fixed(0.02).every(4);
    for (method, implicit) in [("gauss_legendre4", Default::default()), ("radau_iia5", newton)] {
        let stats = whole_and_cut(method, &implicit, fixed, 2.0, &[1, 2, 33, 99]);
        assert!(stats.solver_iterations > 0);
    }
    let adaptive = || Driver::adaptive(Tolerances::new(1e-7, 1e-7));
    whole_and_cut("lobatto_iiia4", &newton, adaptive, 5.0, &[3, 10, 11]);
}

#[test]
fn compensated_runs_resume_with_their_carry() {
    let compensated = || Driver::fixed(0.001).every(50).compensated();
    for method in ["triple_jump4", "rk4", "gauss_legendre4"] {
        whole_and_cut(method, &Default::default(), compensated, 1.0, &[1, 250, 251, 999]);
    }
}

#[test]
fn reversible_steps_resume_bitwise() {
    let kepler = Kepler::new(1.0);
    let density = move || kepler.step_density(1.5);
    let reversible = move || Driver::reversible(0.02, density()).every(2);
    whole_and_cut(
        "velocity_verlet_kdk",
        &Default::default(),
        reversible,
        6.0,
        &[1, 17, 18, 100],
    );
}

#[test]
fn a_state_of_another_run_is_refused() {
    let p = Kepler::new(1.0);
    let mut s = stepper("dormand_prince5", &Default::default());
    let adaptive = Driver::adaptive(Tolerances::new(1e-8, 1e-8)).pause_at(5);
    let run = adaptive.run_resumable(&p, &mut s, 0.0, &Y0, 5.0, &mut Solution::default(), None);
    let state = run.paused.unwrap();
    // fixed steps from an adaptive run's state
    let mut s = stepper("dormand_prince5", &Default::default());
    let fixed = Driver::fixed(0.01).run_resumable(&p, &mut s, 0.0, &Y0, 5.0, &mut Solution::default(), Some(&state));
    let Err((_, e)) = fixed.outcome else { panic!("accepted") };
    assert!(e.to_string().contains("is not of this run"), "{e}");
    // another method's stepper
    let mut s = stepper("tsitouras5", &Default::default());
    let other = Driver::adaptive(Tolerances::new(1e-8, 1e-8));
    let run = other.run_resumable(&p, &mut s, 0.0, &Y0, 5.0, &mut Solution::default(), Some(&state));
    let Err((_, e)) = run.outcome else { panic!("accepted") };
    assert!(e.to_string().contains("dormand_prince5"), "{e}");
}

/// A saved state is not trusted (it may come from a file): one whose time, step or state
/// would make the loop run forever or step outside the run is refused, within a second.
#[test]
fn states_that_would_hang_or_leave_the_run_are_refused() {
    use stormer::driver::ControlState;
    use stormer::stepper::snapshot::Bits;
    let p = Kepler::new(1.0);
    let adaptive = || Driver::adaptive(Tolerances::new(1e-8, 1e-8));
    let mut s = stepper("dormand_prince5", &Default::default());
    let run = adaptive()
        .pause_at(5)
        .run_resumable(&p, &mut s, 0.0, &Y0, 5.0, &mut Solution::default(), None);
    let good = run.paused.unwrap();
    let ControlState::Adaptive { err_old, .. } = good.control else {
        panic!("{:?}", good.control)
    };
    let with_h = |h: f64| RunState {
        control: ControlState::Adaptive {
            h: Bits::of(h),
            err_old,
            last_rejected: false,
        },
        ..good.clone()
    };
    let mut bad = vec![
        ("a step that is NaN", with_h(f64::NAN)),
        ("a step of 0", with_h(0.0)),
        ("a step backwards", with_h(-0.01)),
        ("a step longer than the span", with_h(100.0)),
    ];
    bad.push((
        "a time that is NaN",
        RunState {
            t: Bits::of(f64::NAN),
            ..good.clone()
        },
    ));
    bad.push((
        "a time after the end",
        RunState {
            t: Bits::of(7.0),
            ..good.clone()
        },
    ));
    let mut y = good.y.clone();
    y[2] = Bits::of(f64::INFINITY);
    bad.push(("a state that is not finite", RunState { y, ..good.clone() }));
    for (what, state) in bad {
        let (send, receive) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let (p, mut s) = (Kepler::new(1.0), stepper("dormand_prince5", &Default::default()));
            let run = adaptive().run_resumable(&p, &mut s, 0.0, &Y0, 5.0, &mut Solution::default(), Some(&state));
            let _ = send.send(run.outcome.map(|_| ()).map_err(|(_, e)| e.to_string()));
        });
        let outcome = receive
            .recv_timeout(std::time::Duration::from_secs(10))
            .unwrap_or_else(|_| panic!("{what}: the resumed run did not end"));
        let message = outcome.expect_err(what);
        assert!(message.contains("is not of this run"), "{what}: {message}");
    }
}

/// The state is written exactly by any serde format: JSON (the checkpoint's) and TOML, whose
/// integers are signed (an `f64`'s bits as an integer would not fit) and whose readers in
/// other languages may read numbers as `f64`: the bits are hex strings.
#[test]
fn a_run_state_round_trips_exactly_through_json_and_toml() {
    let p = Kepler::new(1.0);
    // compensated (a carry), FSAL (a slope), events (their bookkeeping), a negative state
    let driver = || {
        Driver::adaptive(Tolerances::new(1e-8, 1e-8)).compensated().event(
            |_t, y: &[f64; 4]| y[1],
            Crossing::Either,
            false,
        )
    };
    let mut s = stepper("dormand_prince5", &Default::default());
    let run = driver()
        .pause_at(30)
        .run_resumable(&p, &mut s, 0.0, &Y0, 5.0, &mut Solution::default(), None);
    let state = run.paused.unwrap();
    assert!(!state.stepper.is_empty());
    let json: RunState = serde_json::from_str(&serde_json::to_string(&state).unwrap()).unwrap();
    assert_eq!(json, state);
    let text = toml::to_string(&state).unwrap();
    let read: RunState = toml::from_str(&text).unwrap();
    assert_eq!(read, state, "{text}");
    // and the bits are hex digits, not numbers
    assert!(text.contains(&format!("\"{:016x}\"", state.y[0].0)), "{text}");
}

/// docs/reproducibility.md: Rust never fuses `a * b + c` into one rounding unless the code
/// asks, and the integration code (the crate's `src/`) never asks: a fused multiply-add
/// would give other bits on a CPU without it (REBOUND checks the same of its C code).
#[test]
fn the_integration_code_never_fuses_a_multiply_add() {
    fn visit(dir: &std::path::Path, found: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                visit(&path, found);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                for (i, line) in text.lines().enumerate() {
                    let code = line.split("//").next().unwrap_or("");
                    if code.contains("mul_add") || code.contains("fmaf") || code.contains("fma(") {
                        found.push(format!("{}:{}: {line}", path.display(), i + 1));
                    }
                }
            }
        }
    }
    let mut found = Vec::new();
    visit(
        &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src"),
        &mut found,
    );
    assert!(found.is_empty(), "fused multiply-adds: {found:#?}");
    // the check sees one where there is one
    let mut probe = Vec::new();
    visit(
        &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("order/src"),
        &mut probe,
    );
    assert!(
        !probe.is_empty(),
        "the order crate's double-double arithmetic uses mul_add"
    );
}
