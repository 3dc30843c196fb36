//! Our adaptive Dormand-Prince methods against the `ode_solvers` crate on the free kick
//! (docs/scenes.md 7: a spinning ball with gravity, quadratic drag and the Magnus force).
//!
//! The problem is defined here (the scene is built elsewhere), once for each library:
//! state `(x, z, vx, vz)` in the vertical launch plane, `R = 0.11` m, `m = 0.42` kg,
//! `Cx = 0.4`, `rho = 1.3` kg/m^3, `mu = 2 pi`, `g = 9.81`, launched at 20 m/s, 30 degrees
//! above the horizontal, spin `omega = 4 pi` rad/s about `+y` (the horizontal axis
//! perpendicular to the launch plane; with `x` forward and `z` up this is topspin: the
//! Magnus force `rho mu R^3 omega x v` turns the velocity clockwise at
//! `Omega = -mu R^3 rho |omega| / m`, as docs/scenes.md 7 states). The ball lands at
//! t = 1.239 s; every run goes from t = 0 to `T_END = 1.2` s, just before landing (so no
//! event location is involved: `ode_solvers` has none).
//!
//! Solvers: `ode_solvers::Dopri5` and `ode_solvers::Dop853` (sparse output: the state of
//! every accepted step is pushed to a `Vec`, their cheapest output), and ours,
//! `ExplicitRk<DormandPrince5>` and `ExplicitRk<Dop853>` under `Driver::adaptive` (records at
//! the start and the end only). Same `rtol = atol` for all; each library keeps its own
//! controller (ours: Hairer's PI rules; theirs: its defaults), so equal tolerances do not mean
//! equal work or error: the printed tables compare at equal error and at equal evaluations by
//! interpolating each method's front in log-log.
//!
//! Error: the largest component of `|y(T) - y_ref(T)|` (metres and m/s), with `y_ref` our
//! `dop853` at `rtol = atol = 1e-14`, checked against `ode_solvers`' Dop853 at the same.
//!
//! Run: `cargo bench --bench free_kick_peers` (criterion at rtol 1e-6 and 1e-10, then the
//! work-precision table and the interleaved timing, 31 rounds, min and median).

#![allow(missing_docs)] // criterion_group! generates an undocumented function

use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Instant;

use criterion::{criterion_group, Criterion};
use ode_solvers::dop_shared::{IntegrationError, SolverResult, Stats};
use ode_solvers::{OutputType, System, Vector4};
use stormer::catalog::{Dop853, DormandPrince5};
use stormer::driver::Recorder;
use stormer::method::ExplicitMethod;
use stormer::stepper::{ExplicitRk, Tolerances};
use stormer::{Driver, Problem};

const T_END: f64 = 1.2;
const R: f64 = 0.11;
const MASS: f64 = 0.42;
const CX: f64 = 0.4;
const RHO: f64 = 1.3;
const MU: f64 = 2.0 * PI;
const SPIN: f64 = 4.0 * PI;
const G: f64 = 9.81;

/// Drag and Magnus coefficients per unit mass.
#[derive(Clone, Copy)]
struct FreeKick {
    drag: f64,
    magnus: f64,
}

impl FreeKick {
    fn new() -> Self {
        FreeKick {
            drag: 0.5 * RHO * CX * PI * R * R / MASS,
            magnus: RHO * MU * R * R * R * SPIN / MASS,
        }
    }

    #[inline(always)]
    fn accel(&self, vx: f64, vz: f64) -> (f64, f64) {
        let speed = (vx * vx + vz * vz).sqrt();
        (
            -self.drag * speed * vx + self.magnus * vz,
            -G - self.drag * speed * vz - self.magnus * vx,
        )
    }
}

fn y0() -> [f64; 4] {
    let (s, c) = (PI / 6.0).sin_cos();
    [0.0, 0.0, 20.0 * c, 20.0 * s]
}

/// Ours: a `Problem`.
impl Problem for FreeKick {
    type Scalar = f64;
    type State = [f64; 4];
    fn rhs(&self, _t: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
        let (ax, az) = self.accel(y[2], y[3]);
        *dy = [y[2], y[3], ax, az];
    }
}

/// Theirs: a `System`.
impl System<f64, Vector4<f64>> for FreeKick {
    fn system(&self, _t: f64, y: &Vector4<f64>, dy: &mut Vector4<f64>) {
        let (ax, az) = self.accel(y[2], y[3]);
        dy[0] = y[2];
        dy[1] = y[3];
        dy[2] = ax;
        dy[3] = az;
    }
}

/// The end state and the right-hand-side evaluations of one run.
type Run = ([f64; 4], u64);

struct Last([f64; 4]);

impl Recorder<f64, [f64; 4]> for Last {
    fn record(&mut self, _t: f64, y: &[f64; 4], _energy: Option<f64>) -> Result<(), stormer::Error> {
        self.0 = *y;
        Ok(())
    }
}

fn ours<M: ExplicitMethod>(tol: f64) -> Run {
    let p = FreeKick::new();
    let y0 = y0();
    let mut st = ExplicitRk::<M, [f64; 4]>::new(&y0);
    let mut last = Last(y0);
    let (stats, _) = Driver::adaptive(Tolerances::new(tol, tol))
        .every(u64::MAX)
        .max_steps(10_000_000)
        .run_into(&p, &mut st, 0.0, &y0, T_END, &mut last)
        .unwrap_or_else(|(_, e)| panic!("{e}"));
    (last.0, stats.evaluations)
}

fn theirs_dopri5(tol: f64) -> Run {
    let mut s = ode_solvers::Dopri5::new(FreeKick::new(), 0.0, T_END, T_END, Vector4::from(y0()), tol, tol);
    s.set_output(OutputType::Sparse);
    let stats = s.integrate();
    their_run(stats, s.results())
}

fn theirs_dop853(tol: f64) -> Run {
    let mut s = ode_solvers::Dop853::new(FreeKick::new(), 0.0, T_END, T_END, Vector4::from(y0()), tol, tol);
    s.set_output(OutputType::Sparse);
    let stats = s.integrate();
    their_run(stats, s.results())
}

/// One run of theirs, once integrated: the last state of the sparse output and the
/// evaluations (`Dopri5` and `Dop853` share these types, not a trait).
fn their_run(stats: Result<Stats, IntegrationError>, out: &SolverResult<f64, Vector4<f64>>) -> Run {
    let stats = stats.unwrap_or_else(|e| panic!("{e}"));
    let end = out.get().1.last().expect("an end state");
    ([end[0], end[1], end[2], end[3]], u64::from(stats.num_eval))
}

struct Solver {
    name: &'static str,
    run: fn(f64) -> Run,
}

fn solvers() -> [Solver; 4] {
    [
        Solver {
            name: "ode_solvers Dopri5",
            run: theirs_dopri5,
        },
        Solver {
            name: "stormer dormand_prince5",
            run: ours::<DormandPrince5>,
        },
        Solver {
            name: "ode_solvers Dop853",
            run: theirs_dop853,
        },
        Solver {
            name: "stormer dop853",
            run: ours::<Dop853>,
        },
    ]
}

fn error(y: &[f64; 4], reference: &[f64; 4]) -> f64 {
    y.iter().zip(reference).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
}

fn bench(c: &mut Criterion) {
    for tol in [1e-6, 1e-10] {
        let mut group = c.benchmark_group(format!("free_kick_rtol_{tol:e}"));
        for s in solvers() {
            group.bench_function(s.name, |b| b.iter(|| (s.run)(black_box(tol))));
        }
        group.finish();
    }
}

criterion_group!(benches, bench);

/// Best-of-`reps` time of one run, in microseconds.
fn time_once(run: fn(f64) -> Run, tol: f64, reps: usize) -> f64 {
    let start = Instant::now();
    for _ in 0..reps {
        black_box(run(black_box(tol)));
    }
    start.elapsed().as_secs_f64() * 1e6 / reps as f64
}

fn min_median(v: &mut [f64]) -> (f64, f64) {
    v.sort_by(f64::total_cmp);
    (v[0], v[v.len() / 2])
}

/// Log-log interpolation of `y` at `x` on a front given as (x, y) points sorted by x.
fn interpolate(points: &[(f64, f64)], x: f64) -> Option<f64> {
    points.windows(2).find_map(|w| {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        let (lo, hi) = (x0.min(x1), x0.max(x1));
        if x < lo || x > hi || (x1 - x0).abs() <= f64::EPSILON * hi {
            return None;
        }
        let f = (x.ln() - x0.ln()) / (x1.ln() - x0.ln());
        Some((y0.ln() + f * (y1.ln() - y0.ln())).exp())
    })
}

/// The machine's load average (1, 5, 15 minutes), as the kernel reports it.
fn load() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "?".into())
}

fn tables() {
    println!("\nload average at the start of the tables: {} (2 cores)", load());
    let reference = ours::<Dop853>(1e-14).0;
    let check = theirs_dop853(1e-14).0;
    println!(
        "\nfree kick to t = {T_END} s: reference (stormer dop853, tol 1e-14) x = {:.12} m, z = {:.12} m; \
         ode_solvers Dop853 at 1e-14 differs by {:.1e}",
        reference[0],
        reference[1],
        error(&check, &reference)
    );
    let tols: Vec<f64> = (3..=13).map(|k| 10f64.powi(-k)).collect();
    // Work-precision table: evaluations, error, time (best of 20 runs, interleaved below).
    let all = solvers();
    let mut fronts: Vec<Vec<(f64, f64, f64)>> = vec![Vec::new(); all.len()]; // (err, evals, us)
    println!("\n| rtol = atol | solver | evaluations | error at T | us per run (min of 7 rounds) |");
    println!("|---:|---|---:|---:|---:|");
    for &tol in &tols {
        let mut times = vec![Vec::new(); all.len()];
        for _ in 0..7 {
            for (i, s) in all.iter().enumerate() {
                times[i].push(time_once(s.run, tol, 20));
            }
        }
        for (i, s) in all.iter().enumerate() {
            let (y, evals) = (s.run)(tol);
            let err = error(&y, &reference);
            let (t, _) = min_median(&mut times[i]);
            fronts[i].push((err, evals as f64, t));
            println!("| {tol:.0e} | {} | {evals} | {err:.2e} | {t:.2} |", s.name);
        }
    }
    // At equal error: evaluations and time each solver needs (log-log interpolation).
    println!("\nAt equal error (interpolated on each front):\n");
    println!("| error | solver | evaluations | us per run |");
    println!("|---:|---|---:|---:|");
    for target in [1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12] {
        for (i, s) in all.iter().enumerate() {
            let mut by_err: Vec<(f64, f64)> = fronts[i].iter().map(|&(e, n, _)| (e, n)).collect();
            let mut by_err_t: Vec<(f64, f64)> = fronts[i].iter().map(|&(e, _, t)| (e, t)).collect();
            by_err.sort_by(|a, b| a.0.total_cmp(&b.0));
            by_err_t.sort_by(|a, b| a.0.total_cmp(&b.0));
            let fmt = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.1}"));
            println!(
                "| {target:.0e} | {} | {} | {} |",
                s.name,
                fmt(interpolate(&by_err, target)),
                fmt(interpolate(&by_err_t, target))
            );
        }
    }
    // At equal evaluations: the error each solver reaches.
    println!("\nAt equal evaluations (interpolated on each front):\n");
    println!("| evaluations | solver | error at T |");
    println!("|---:|---|---:|");
    for target in [50.0, 75.0, 100.0, 150.0, 200.0, 300.0] {
        for (i, s) in all.iter().enumerate() {
            let mut by_n: Vec<(f64, f64)> = fronts[i].iter().map(|&(e, n, _)| (n, e)).collect();
            by_n.sort_by(|a, b| a.0.total_cmp(&b.0));
            let v = interpolate(&by_n, target).map_or("-".to_string(), |v| format!("{v:.2e}"));
            println!("| {target} | {} | {v} |", s.name);
        }
    }
}

/// Interleaved timing at three tolerances: 31 rounds, each solver 50 runs per round.
fn interleaved() {
    let all = solvers();
    println!("\nInterleaved timing, 31 rounds of 50 runs, us per run (min / median):\n");
    println!(
        "| rtol = atol | solver | evaluations | us per run (min) | us per run (median) | ns per evaluation (min) |"
    );
    println!("|---:|---|---:|---:|---:|---:|");
    for tol in [1e-4, 1e-7, 1e-10] {
        let mut times = vec![Vec::new(); all.len()];
        for _ in 0..31 {
            for (i, s) in all.iter().enumerate() {
                times[i].push(time_once(s.run, tol, 50));
            }
        }
        for (i, s) in all.iter().enumerate() {
            let evals = (s.run)(tol).1;
            let (lo, med) = min_median(&mut times[i]);
            println!(
                "| {tol:.0e} | {} | {evals} | {lo:.2} | {med:.2} | {:.1} |",
                s.name,
                lo * 1e3 / evals as f64
            );
        }
    }
    println!("\nload average at the end: {}", load());
}

fn main() {
    // Both libraries integrate the same equations: at a tight tolerance they agree.
    let a = ours::<Dop853>(1e-12).0;
    let b = theirs_dop853(1e-12).0;
    assert!(
        error(&a, &b) < 1e-8,
        "the two definitions of the free kick disagree: {a:?} vs {b:?}"
    );
    assert!(a[1] > 0.0, "still in the air at T_END");
    benches();
    Criterion::default().configure_from_args().final_summary();
    let args: Vec<String> = std::env::args().collect();
    // `cargo test --benches` runs this binary with --bench absent: keep that quick.
    if args.iter().any(|a| a == "--bench") {
        tables();
        interleaved();
    }
}
