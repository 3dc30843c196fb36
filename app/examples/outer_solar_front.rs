//! Our side of the REBOUND comparison (`benches/peers/rebound.py`): the outer solar system
//! (docs/scenes.md 4: Sun, Jupiter, Saturn, Uranus in 3-D, G = 2.95912208286e-4, AU and days),
//! integrated by generated splitting steppers through `Stepper::step_in_place` (the
//! fixed-step driver's path). Prints one JSON object on stdout.
//!
//! ```sh
//! cargo run --release --example outer_solar_front -- time [--span DAYS] [--dt DAYS] [--reps N] [--methods LIST]
//! cargo run --release --example outer_solar_front -- front [--span DAYS] [--dts LIST] [--cadence DAYS] [--methods LIST]
//!     [--kepler-dts LIST] [--comp-dts LIST]
//! cargo run --release --example outer_solar_front -- plot FRONT.json OUT.svg
//! ```
//!
//! Our methods: splittings and compositions over the N-body problem's `T + V` split, and
//! (`kepler/...`) over the Kepler split in Jacobi coordinates (`KeplerSplit`: the drift every
//! planet's exact Kepler motion, the kick the planets' mutual pull; `kepler/wisdom_holman` is
//! Wisdom-Holman, drift-kick-drift as REBOUND's WHFast, uncorrected; `kepler+comp/...` the
//! same with compensated summation, `Stepper::set_compensated`). `--methods a,b,...` picks
//! some (default: all).
//!
//! - `time`: ns per step of each method at one `dt` (default 10 days) over `span` (default
//!   360000 days), best of `reps` runs (default 3). One call is one round: the script calls
//!   it between REBOUND's rounds so that the two are interleaved.
//! - `front`: for each method and each `dt` (default 100, 50, 20, 10, 5, 2, 1 days; the
//!   `kepler/` methods also at the steps of `--kepler-dts`, which may exceed the cadence; the
//!   `kepler+comp/` ones only at `--comp-dts`, default 300, 200, 150, 100, 50): max
//!   |dE/E| sampled every `cadence` days (default 100), the positions at `span` and their
//!   error against a reference run of ours (Kahan-Li 8 at dt = 10 days; the script measures
//!   every run, ours and REBOUND's, against REBOUND's IAS15 instead, which has the smaller
//!   round-off), and the run's wall time (best of 3, no sampling). Then our adaptive
//!   `dop853` and `verner9` at tolerances `--tols` (default 1e-8, 1e-10, 1e-12, 1e-14;
//!   energy checked at every accepted step). Also `compensation_check` (a compensated run
//!   against the same run uncompensated at a coarse step; asserted below 1e-9 AU) and
//!   `candidates`, compensated runs at short steps for the script's check of the reference.
//! - `plot`: reads the combined front written by the script and draws the work-precision
//!   diagrams (error against seconds) with plotters.

use std::hint::black_box;
use std::time::Instant;

use stormer::catalog::{
    Aba1064, Aba864, Abah864, BlanesMoanSrkn11b, BlanesMoanSrkn6b, Dop853, KahanLi6, KahanLi8, Saba4, Sbab4,
    StormerVerletDkd, TripleJump4, VelocityVerletKdk, Verner9,
};
use stormer::driver::Recorder;
use stormer::method::{ExplicitMethod, SplittingMethod};
use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};
use stormer::stepper::{ExplicitRk, SplittingStepper, Tolerances};
use stormer::{Driver, Problem, Stepper};

type Nb = NBody<f64, [f64; 24]>;
type Split = KeplerSplit<f64, [f64; 24]>;

/// docs/scenes.md 4, as REBOUND gets them too.
#[path = "../../tests/support/outer_solar_system.rs"]
mod outer_solar_system;
use outer_solar_system::{G, MASSES};

fn problem() -> (Nb, [f64; 24]) {
    outer_solar_system::outer_solar_system(1.0)
}
/// One of our methods: its name, order, force evaluations per step, and its runs.
struct Method {
    name: &'static str,
    order: usize,
    evals: usize,
    run: fn(&Nb, &[f64; 24], f64, usize) -> [f64; 24],
    sampled: Sampled,
}

/// A run sampling the energy: `(problem, y0, h, steps, every)` to the end state and max |dE/E|.
type Sampled = fn(&Nb, &[f64; 24], f64, usize, usize) -> ([f64; 24], f64);

/// A series of the plot: its label and its points (seconds, position error, max |dE/E|).
type Series = (String, Vec<(f64, f64, f64)>);

/// One step of `h` on `y`: in place (the fixed-step driver's path), or with compensated
/// summation (`COMP`) through `step` and `accept`, which keep Kahan's carry from one step to
/// the next (a compensated splitting stepper does not step in place).
#[inline(always)]
fn advance<P, St, const COMP: bool>(st: &mut St, p: &P, t: f64, h: f64, y: &mut [f64; 24]) -> Result<(), stormer::Error>
where
    P: Problem<Scalar = f64, State = [f64; 24]>,
    St: Stepper<P>,
{
    if COMP {
        let from = *y;
        st.step(p, t, h, &from, y)?;
        st.accept();
        Ok(())
    } else {
        st.step_in_place(p, t, h, y)
    }
}

/// A splitting stepper for `problem` from `y0`, compensated if `COMP`.
fn stepper<M: SplittingMethod, P: Problem<Scalar = f64, State = [f64; 24]>, const COMP: bool>(
    y0: &[f64; 24],
) -> SplittingStepper<M, [f64; 24]>
where
    SplittingStepper<M, [f64; 24]>: Stepper<P>,
{
    let mut st = SplittingStepper::<M, [f64; 24]>::new(y0).expect("a splitting stepper");
    Stepper::<P>::set_compensated(&mut st, COMP).expect("a compensated form");
    assert!(COMP || Stepper::<P>::steps_in_place(&st));
    st
}

/// The coordinates a method steps in: the scene's (the N-body problem's T + V split), or
/// Jacobi coordinates over the Kepler split; the state changed to them before the loop and
/// back after it.
trait Space: Problem<Scalar = f64, State = [f64; 24]> + Sized {
    /// The problem in these coordinates.
    fn of(nb: &Nb) -> Self;
    /// A scene state in these coordinates, and back.
    fn enter(&self, y: &[f64; 24]) -> [f64; 24];
    fn leave(&self, y: &[f64; 24]) -> [f64; 24];
}

impl Space for Nb {
    fn of(nb: &Nb) -> Self {
        nb.clone()
    }
    fn enter(&self, y: &[f64; 24]) -> [f64; 24] {
        *y
    }
    fn leave(&self, y: &[f64; 24]) -> [f64; 24] {
        *y
    }
}

/// The Kepler split in Jacobi coordinates (`KeplerSplit`, the drift every planet's exact
/// Kepler motion).
impl Space for Split {
    fn of(nb: &Nb) -> Self {
        Split::new(nb.clone(), KeplerCoordinates::Jacobi).expect("one dominant body")
    }
    fn enter(&self, y: &[f64; 24]) -> [f64; 24] {
        KeplerSplit::from_scene(self, y)
    }
    fn leave(&self, y: &[f64; 24]) -> [f64; 24] {
        KeplerSplit::to_scene(self, y)
    }
}

/// `steps` steps of `h` in `Sp`, the fixed-step driver's loop without records.
fn run<M: SplittingMethod, Sp: Space, const COMP: bool>(nb: &Nb, y0: &[f64; 24], h: f64, steps: usize) -> [f64; 24]
where
    SplittingStepper<M, [f64; 24]>: Stepper<Sp>,
{
    let space = Sp::of(nb);
    let mut y = space.enter(y0);
    let mut st = stepper::<M, Sp, COMP>(&y);
    for i in 0..steps {
        let r = advance::<_, _, COMP>(&mut st, &space, i as f64 * h, h, &mut y);
        debug_assert!(r.is_ok());
    }
    space.leave(&y)
}

/// The same, with max |dE/E| of the N-body energy sampled every `every` steps (and at the
/// end).
fn sampled<M: SplittingMethod, Sp: Space, const COMP: bool>(
    nb: &Nb,
    y0: &[f64; 24],
    h: f64,
    steps: usize,
    every: usize,
) -> ([f64; 24], f64)
where
    SplittingStepper<M, [f64; 24]>: Stepper<Sp>,
{
    let space = Sp::of(nb);
    let e0 = nb.energy(0.0, y0).expect("an energy");
    let mut y = space.enter(y0);
    let mut st = stepper::<M, Sp, COMP>(&y);
    let mut worst: f64 = 0.0;
    for i in 0..steps {
        advance::<_, _, COMP>(&mut st, &space, i as f64 * h, h, &mut y).expect("a finite step");
        if (i + 1) % every == 0 || i + 1 == steps {
            let e = space.energy((i + 1) as f64 * h, &y).expect("an energy");
            worst = worst.max(((e - e0) / e0).abs());
        }
    }
    (space.leave(&y), worst)
}

/// A method stepping in `Sp` (the scene's coordinates `Nb`, or the Kepler split `Split`),
/// `true` for Kahan's summation of each step's increment (the Kepler drift's increment form).
fn method<M: SplittingMethod, Sp: Space, const COMP: bool>(name: &'static str, order: usize, evals: usize) -> Method
where
    SplittingStepper<M, [f64; 24]>: Stepper<Sp>,
{
    Method {
        name,
        order,
        evals,
        run: run::<M, Sp, COMP>,
        sampled: sampled::<M, Sp, COMP>,
    }
}

fn methods() -> Vec<Method> {
    vec![
        method::<VelocityVerletKdk, Nb, false>("velocity_verlet_kdk", 2, 1),
        method::<TripleJump4, Nb, false>("triple_jump4", 4, 3),
        method::<BlanesMoanSrkn6b, Nb, false>("blanes_moan_srkn6b", 4, 6),
        method::<KahanLi6, Nb, false>("kahan_li6", 6, 9),
        method::<BlanesMoanSrkn11b, Nb, false>("blanes_moan_srkn11b", 6, 11),
        method::<KahanLi8, Nb, false>("kahan_li8", 8, 17),
        // over the Kepler split: `order` is the order in h, `evals` the kicks per step
        method::<StormerVerletDkd, Split, false>("kepler/wisdom_holman", 2, 1),
        method::<VelocityVerletKdk, Split, false>("kepler/velocity_verlet_kdk", 2, 1),
        method::<Sbab4, Split, false>("kepler/sbab4", 2, 4),
        method::<Saba4, Split, false>("kepler/saba4", 2, 4),
        method::<Abah864, Split, false>("kepler/abah864", 4, 7),
        method::<Aba864, Split, false>("kepler/aba864", 4, 7),
        method::<Aba1064, Split, false>("kepler/aba1064", 4, 9),
        // the same with compensated summation (`kepler+comp/`, at `--comp-dts` only): the
        // round-off of 1e4 uncompensated steps is the floor of the runs above (~3e-11 AU)
        method::<Aba864, Split, true>("kepler+comp/aba864", 4, 7),
        method::<Aba1064, Split, true>("kepler+comp/aba1064", 4, 9),
    ]
}

/// The methods named in `--methods a,b,...` (all when absent).
fn selected(args: &[String]) -> Vec<Method> {
    let all = methods();
    match arg(args, "--methods") {
        None => all,
        Some(list) => {
            let names: Vec<&str> = list.split(',').map(str::trim).collect();
            for name in &names {
                assert!(all.iter().any(|m| m.name == *name), "unknown method {name}");
            }
            all.into_iter().filter(|m| names.contains(&m.name)).collect()
        }
    }
}

/// Keeps the last state and the largest |dE/E| of the records.
struct Watch {
    e0: f64,
    worst: f64,
    last: [f64; 24],
}

impl Recorder<f64, [f64; 24]> for Watch {
    fn record(&mut self, _t: f64, y: &[f64; 24], energy: Option<f64>) -> Result<(), stormer::Error> {
        if let Some(e) = energy {
            self.worst = self.worst.max(((e - self.e0) / self.e0).abs());
        }
        self.last = *y;
        Ok(())
    }
}

/// An adaptive embedded Runge-Kutta run of ours (the non-symplectic high-order competitor):
/// `every` = 1 records (and checks the energy) at every accepted step, `u64::MAX` only at
/// the ends. Returns the end state, max |dE/E|, steps and evaluations.
fn adaptive<M: ExplicitMethod>(nb: &Nb, y0: &[f64; 24], tol: f64, span: f64, every: u64) -> ([f64; 24], f64, u64, u64) {
    let mut st = ExplicitRk::<M, [f64; 24]>::new(y0);
    let e0 = nb.energy(0.0, y0).expect("an energy");
    let mut watch = Watch {
        e0,
        worst: 0.0,
        last: *y0,
    };
    let (stats, _) = Driver::adaptive(Tolerances::new(tol, tol))
        .every(every)
        .run_into(nb, &mut st, 0.0, y0, span, &mut watch)
        .unwrap_or_else(|(_, e)| panic!("{e}"));
    (watch.last, watch.worst, stats.steps, stats.evaluations)
}

fn arg(args: &[String], name: &str) -> Option<String> {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1).cloned())
}

fn num(args: &[String], name: &str, default: f64) -> f64 {
    arg(args, name).map_or(default, |s| {
        s.parse().unwrap_or_else(|_| panic!("{name}: not a number: {s}"))
    })
}

/// The comma-separated step sizes of option `name` (`default` when absent; "" for none).
fn list(args: &[String], name: &str, default: &str) -> Vec<f64> {
    arg(args, name)
        .unwrap_or_else(|| default.into())
        .split(',')
        .filter(|s| !s.trim().is_empty())
        .map(|s| {
            s.trim()
                .parse()
                .unwrap_or_else(|_| panic!("{name}: not a list of step sizes: {s}"))
        })
        .collect()
}

fn steps_for(span: f64, h: f64) -> usize {
    let n = (span / h).round();
    assert!(
        (n * h - span).abs() < 1e-9 * span,
        "dt = {h} must divide the span {span}"
    );
    n as usize
}

/// Best of `reps` wall times of `f`, in seconds.
fn best_of(reps: usize, mut f: impl FnMut() -> [f64; 24]) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..reps {
        let start = Instant::now();
        black_box(f());
        best = best.min(start.elapsed().as_secs_f64());
    }
    best
}

fn position_error(y: &[f64; 24], reference: &[f64; 24]) -> f64 {
    (0..4)
        .map(|k| {
            (0..3)
                .map(|c| (y[3 * k + c] - reference[3 * k + c]).powi(2))
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0, f64::max)
}

fn json_list(v: &[f64]) -> String {
    let items: Vec<String> = v.iter().map(|x| format!("{x:e}")).collect();
    format!("[{}]", items.join(", "))
}

fn time(args: &[String]) {
    let (nb, y0) = problem();
    let span = num(args, "--span", 360000.0);
    let h = num(args, "--dt", 10.0);
    let reps = num(args, "--reps", 3.0) as usize;
    let steps = steps_for(span, h);
    let rows: Vec<String> = selected(args)
        .iter()
        .map(|m| {
            let secs = best_of(reps, || (m.run)(&nb, black_box(&y0), black_box(h), steps));
            format!(
                "{{\"method\": \"{}\", \"order\": {}, \"evals\": {}, \"ns_per_step\": {:e}}}",
                m.name,
                m.order,
                m.evals,
                secs * 1e9 / steps as f64
            )
        })
        .collect();
    println!(
        "{{\"dt\": {h:e}, \"span\": {span:e}, \"steps\": {steps}, \"rows\": [{}]}}",
        rows.join(", ")
    );
}

fn front(args: &[String]) {
    let (nb, y0) = problem();
    let span = num(args, "--span", 360000.0);
    let cadence = num(args, "--cadence", 100.0);
    let kepler_dts = list(args, "--kepler-dts", "");
    let dts = list(args, "--dts", "100,50,20,10,5,2,1");
    let comp_dts = list(args, "--comp-dts", "300,200,150,100,50");
    let all = selected(args);
    let catalogue = methods();
    let reference_method = catalogue.iter().find(|m| m.name == "kahan_li8").expect("kahan_li8");
    // Few steps keep the reference's round-off small: Kahan-Li 8's truncation error at
    // dt = 10 days is below the round-off of a run at dt = 0.25 (both about 1e-9 AU).
    let h_ref = 10.0;
    let start = Instant::now();
    let reference = (reference_method.run)(&nb, &y0, h_ref, steps_for(span, h_ref));
    let ref_secs = start.elapsed().as_secs_f64();
    // How far the reference is from the same method at half the step.
    let coarse = (reference_method.run)(&nb, &y0, 0.5 * h_ref, steps_for(span, 0.5 * h_ref));
    let mut rows = Vec::new();
    for m in &all {
        // the Kepler split's methods also at longer steps (`--kepler-dts`, default none);
        // the compensated ones at `--comp-dts` only
        let (longer, usual) = if m.name.starts_with("kepler+comp/") {
            (&comp_dts[..], &[][..])
        } else if m.name.starts_with("kepler/") {
            (&kepler_dts[..], &dts[..])
        } else {
            (&[][..], &dts[..])
        };
        for &h in longer.iter().chain(usual) {
            let steps = steps_for(span, h);
            let every = steps_for(cadence.max(h), h);
            let (y, de) = (m.sampled)(&nb, &y0, h, steps, every);
            let secs = best_of(3, || (m.run)(&nb, black_box(&y0), black_box(h), steps));
            rows.push(format!(
                "{{\"who\": \"stormer\", \"method\": \"{}\", \"order\": {}, \"evals_per_step\": {}, \"dt\": {h:e}, \
                 \"steps\": {steps}, \"evaluations\": {}, \"seconds\": {secs:e}, \"max_dE\": {de:e}, \"pos_err\": {:e}, \"q_end\": {}}}",
                m.name,
                m.order,
                m.evals,
                steps * m.evals,
                position_error(&y, &reference),
                json_list(&y[..12]),
            ));
        }
    }
    type Adaptive = fn(&Nb, &[f64; 24], f64, f64, u64) -> ([f64; 24], f64, u64, u64);
    let adaptives: [(&str, usize, Adaptive); 2] =
        [("dop853", 8, adaptive::<Dop853>), ("verner9", 9, adaptive::<Verner9>)];
    let tols: Vec<f64> = arg(args, "--tols")
        .unwrap_or_else(|| "1e-8,1e-10,1e-12,1e-14".into())
        .split(',')
        .map(|s| s.trim().parse().expect("a list of tolerances"))
        .collect();
    for (name, order, run) in adaptives {
        for &tol in &tols {
            let (y, de, steps, evals) = run(&nb, &y0, tol, span, 1);
            let mut best = f64::INFINITY;
            for _ in 0..3 {
                let start = Instant::now();
                black_box(run(&nb, black_box(&y0), tol, span, u64::MAX));
                best = best.min(start.elapsed().as_secs_f64());
            }
            rows.push(format!(
                "{{\"who\": \"stormer\", \"method\": \"{name}\", \"order\": {order}, \"tol\": {tol:e}, \
                 \"steps\": {steps}, \"evaluations\": {evals}, \"seconds\": {best:e}, \"max_dE\": {de:e}, \
                 \"pos_err\": {:e}, \"q_end\": {}}}",
                position_error(&y, &reference),
                json_list(&y[..12]),
            ));
        }
    }
    let y0_json = json_list(&y0);
    println!(
        "{{\"span\": {span:e}, \"cadence\": {cadence:e}, \"G\": {G:e}, \"masses\": {}, \"y0\": {y0_json}, \
         \"reference\": {{\"method\": \"kahan_li8\", \"dt\": {h_ref:e}, \"seconds\": {ref_secs:e}, \
         \"positions\": {}, \"self_check\": {:e}}}, \"compensation_check\": {:e}, \"candidates\": [{}], \"rows\": [\n{}\n]}}",
        json_list(&MASSES),
        json_list(&reference[..12]),
        position_error(&coarse, &reference),
        compensation_check(&nb, &y0, span),
        candidates(&nb, &y0, span).join(", "),
        rows.join(",\n")
    );
}

/// How far a compensated Kepler-split run is from the same run uncompensated, where the
/// truncation error (3e-7 AU for ABA(10,6,4) at 600 days) dwarfs the round-off that
/// compensation removes: the two must agree to round-off (~1e-10 AU), or the compensated
/// form is not the same method.
fn compensation_check(nb: &Nb, y0: &[f64; 24], span: f64) -> f64 {
    let (h, steps) = (600.0, steps_for(span, 600.0));
    let plain = run::<Aba1064, Split, false>(nb, y0, h, steps);
    let compensated = run::<Aba1064, Split, true>(nb, y0, h, steps);
    let gap = position_error(&compensated, &plain);
    assert!(
        gap < 1e-9,
        "compensated aba1064 is {gap:e} AU from the uncompensated run at dt 600"
    );
    gap
}

/// Candidates for a reference better than IAS15's round-off: compensated runs at short
/// steps, where the truncation error is far below 1e-12 AU, by two methods of different
/// kinds (the Kepler split's ABA(10,6,4) and ABA(8,6,4), and Kahan-Li 8 over `T + V`, no
/// Kepler solver and no coordinate change), so that errors they share are unlikely. The
/// script measures them against each other and against IAS15.
fn candidates(nb: &Nb, y0: &[f64; 24], span: f64) -> Vec<String> {
    type Run = fn(&Nb, &[f64; 24], f64, usize) -> [f64; 24];
    let runs: [(&str, f64, Run); 5] = [
        ("kepler+comp/aba1064", 20.0, run::<Aba1064, Split, true>),
        ("kepler+comp/aba1064", 10.0, run::<Aba1064, Split, true>),
        ("kepler+comp/aba864", 10.0, run::<Aba864, Split, true>),
        ("kahan_li8+comp", 2.0, run::<KahanLi8, Nb, true>),
        ("kahan_li8+comp", 1.0, run::<KahanLi8, Nb, true>),
    ];
    runs.iter()
        .map(|&(name, h, run)| {
            let y = run(nb, y0, h, steps_for(span, h));
            format!(
                "{{\"method\": \"{name}\", \"dt\": {h:e}, \"positions\": {}}}",
                json_list(&y[..12])
            )
        })
        .collect()
}

fn plot(args: &[String]) {
    use plotters::prelude::*;
    let input = args.get(1).expect("plot FRONT.json OUT.svg");
    let output = args.get(2).expect("plot FRONT.json OUT.svg");
    let text = std::fs::read_to_string(input).expect("the combined front");
    let data: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let rows = data["rows"].as_array().expect("rows");
    // One series per (who, method).
    let mut series: Vec<Series> = Vec::new();
    for r in rows {
        let label = format!(
            "{} {}",
            r["who"].as_str().unwrap_or("?"),
            r["method"].as_str().unwrap_or("?")
        );
        let point = (
            r["seconds"].as_f64().unwrap_or(f64::NAN),
            r["pos_err"].as_f64().unwrap_or(f64::NAN),
            r["max_dE"].as_f64().unwrap_or(f64::NAN),
        );
        match series.iter_mut().find(|(l, _)| *l == label) {
            Some((_, pts)) => pts.push(point),
            None => series.push((label, vec![point])),
        }
    }
    let floor = 1e-17;
    let ok = |x: f64| x.is_finite() && x > 0.0;
    let (mut t_lo, mut t_hi) = (f64::INFINITY, 0.0f64);
    for (_, pts) in &series {
        for &(t, _, _) in pts {
            if ok(t) {
                t_lo = t_lo.min(t);
                t_hi = t_hi.max(t);
            }
        }
    }
    let root = SVGBackend::new(output, (1500, 700)).into_drawing_area();
    root.fill(&WHITE).expect("draw");
    let (plots, legend) = root.split_horizontally(1260);
    let panels = plots.split_evenly((1, 2));
    let titles = ["position error at t_end (AU) vs seconds", "max |dE/E| vs seconds"];
    for (panel, (which, title)) in panels.iter().zip(titles.iter().enumerate()) {
        let (mut e_lo, mut e_hi) = (f64::INFINITY, 0.0f64);
        for (_, pts) in &series {
            for &(_, pe, de) in pts {
                let e = if which == 0 { pe } else { de };
                if ok(e) {
                    e_lo = e_lo.min(e.max(floor));
                    e_hi = e_hi.max(e);
                }
            }
        }
        let mut chart = ChartBuilder::on(panel)
            .caption(*title, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(
                (t_lo * 0.7..t_hi * 1.4).log_scale(),
                (e_lo * 0.3..e_hi * 3.0).log_scale(),
            )
            .expect("axes");
        chart
            .configure_mesh()
            .x_desc("wall time of the run (s)")
            .y_desc(if which == 0 {
                "max position error (AU)"
            } else {
                "max |dE/E|"
            })
            .x_label_formatter(&|x| format!("{x:.0e}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .draw()
            .expect("mesh");
        for (i, (label, pts)) in series.iter().enumerate() {
            let colour = colour_of(label, i);
            let dashed = label.starts_with("rebound");
            let mut line: Vec<(f64, f64)> = pts
                .iter()
                .map(|&(t, pe, de)| (t, if which == 0 { pe } else { de }))
                .filter(|&(t, e)| ok(t) && ok(e))
                .map(|(t, e)| (t, e.max(floor)))
                .collect();
            line.sort_by(|a, b| a.0.total_cmp(&b.0));
            let style = ShapeStyle::from(&colour).stroke_width(if dashed { 1 } else { 2 });
            chart.draw_series(LineSeries::new(line.clone(), style)).expect("line");
            if dashed {
                chart
                    .draw_series(line.iter().map(|&p| Cross::new(p, 4, style)))
                    .expect("points");
            } else {
                chart
                    .draw_series(line.iter().map(|&p| Circle::new(p, 3, style.filled())))
                    .expect("points");
            }
        }
    }
    // One legend for both panels, beside them: ours solid with dots, REBOUND thin with
    // crosses, the same colour at the same order.
    for (i, (label, _)) in series.iter().enumerate() {
        let colour = colour_of(label, i);
        let y = 40 + 24 * i as i32;
        let rebound = label.starts_with("rebound");
        let style = ShapeStyle::from(&colour).stroke_width(if rebound { 1 } else { 2 });
        legend
            .draw(&PathElement::new(vec![(10, y), (40, y)], style))
            .expect("legend");
        if rebound {
            legend.draw(&Cross::new((25, y), 4, style)).expect("legend");
        } else {
            legend.draw(&Circle::new((25, y), 3, style.filled())).expect("legend");
        }
        legend
            .draw(&Text::new(label.clone(), (48, y - 7), ("sans-serif", 13)))
            .expect("legend");
    }
    root.present().expect("write the SVG");
    eprintln!("wrote {output}");
}

/// Colours by order, shared by our method and REBOUND's of the same order.
fn colour_of(label: &str, i: usize) -> plotters::style::RGBAColor {
    use plotters::style::{Color, Palette, Palette99, RGBColor};
    let method = label.split_whitespace().nth(1).unwrap_or("");
    let rgb = match method {
        "velocity_verlet_kdk" | "leapfrog2" => RGBColor(200, 30, 30),
        "triple_jump4" | "leapfrog4" => RGBColor(30, 140, 30),
        "kahan_li6" | "leapfrog6" => RGBColor(20, 60, 200),
        "kahan_li8" | "leapfrog8" => RGBColor(130, 30, 160),
        "blanes_moan_srkn6b" => RGBColor(0, 150, 150),
        "blanes_moan_srkn11b" => RGBColor(230, 120, 0),
        "dop853" => RGBColor(110, 110, 110),
        "verner9" => RGBColor(0, 0, 0),
        "whfast" => RGBColor(150, 100, 40),
        "ias15" => RGBColor(230, 0, 180),
        _ => return Palette99::pick(i).to_rgba(),
    };
    rgb.to_rgba()
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("time") => time(&args),
        Some("front") => front(&args),
        Some("plot") => plot(&args),
        _ => {
            eprintln!("usage: outer_solar_front time|front|plot ... (see the file's header)");
            std::process::exit(2);
        }
    }
}
