//! The Rust side of the Python bench (`benches/peers/python_side.py`): the run behind
//! Python's `Simulation.integrate` (`stormer_app::cli::in_process::run`: the scene read, the
//! split built, the run with no records but the first and the last), timed from Rust. Prints
//! one JSON object: the best and median wall time of `--reps` runs, in seconds.
//!
//! ```sh
//! cargo run --release -p stormer-app --example in_process_run -- [--scene S] [--method M]
//!     [--split kepler-jacobi] [--t-end T] [--reps N]
//! ```

use std::time::Instant;
use stormer_app::cli::in_process::{run, RunRequest, SceneInput};

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1))
            .cloned()
    };
    let mut request = RunRequest::new(SceneInput::Named(
        value("--scene").unwrap_or("outer-solar-system".into()),
    ));
    request.method = Some(value("--method").unwrap_or("wisdom_holman".into()));
    request.split = Some(value("--split").unwrap_or("kepler-jacobi".into()));
    request.t_end = Some(value("--t-end").map_or(Ok(1e5), |t| t.parse())?);
    // the first and the last record only, as Simulation.integrate asks
    request.every = Some(1 << 62);
    let reps: usize = value("--reps").map_or(Ok(20), |n| n.parse())?;
    let mut seconds = Vec::with_capacity(reps);
    let mut steps = 0;
    for _ in 0..reps {
        let start = Instant::now();
        let records = run(&request, None)?;
        seconds.push(start.elapsed().as_secs_f64());
        steps = records.summary.steps;
        anyhow::ensure!(records.failure.is_none(), "{:?}", records.failure);
    }
    seconds.sort_by(f64::total_cmp);
    println!(
        "{{\"steps\": {steps}, \"min\": {:e}, \"median\": {:e}, \"reps\": {reps}}}",
        seconds[0],
        seconds[reps / 2]
    );
    Ok(())
}
