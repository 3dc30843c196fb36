//! Regular or chaotic? The mean MEGNO of the Henon-Heiles orbits of the section picture at
//! E = 1/6, from one variation carried through velocity Verlet's steps on dual numbers
//! (docs/chaos.md): about 2 on the islands, growing in the chaotic sea.

use super::picture::{picture, Figure};
use crate::cli::plot::{Chart, Scale, Series};
use crate::cli::tour_page::Section;
use std::path::Path;
use stormer::chaos::Tangent;
use stormer::text::number;
use stormer::verify::problems::HenonHeiles;
use stormer::verify::Dual64;
use stormer::Method;

/// The mean MEGNO against time.
const MEGNO: Figure = Figure {
    file: "henon-heiles-megno.svg",
    caption: "The running mean of MEGNO against time, log scale, for the orbits of the section at \
        E = 1/6: the ones that trace curves on the section settle near 2 (quasi-periodic), the \
        ones that scatter grow like lambda t / 2 (chaotic). REBOUND's stability maps call an \
        orbit chaotic above 2.5.",
};

/// The section's starting points `(y, py = 0)` (those of the section picture).
const YS: [f64; 7] = [-0.25, -0.15, -0.05, 0.05, 0.15, 0.35, 0.42];

/// Velocity Verlet's step and the span.
const H: f64 = 0.05;
const T_END: f64 = 2000.0;

/// One orbit from `(x, y, py) = (0, y, 0)` at E = 1/6: its mean MEGNO every 20 steps, and
/// the Lyapunov estimate at the end.
fn orbit(y: f64) -> anyhow::Result<(Vec<(f64, f64)>, f64)> {
    let problem = HenonHeiles::<Dual64>::new();
    let px = (1.0 / 3.0 - y * y + 2.0 * y * y * y / 3.0).sqrt();
    let y0 = [0.0, y, px, 0.0].map(Dual64::from);
    let mut stepper = Method::named("velocity_verlet_kdk")?.stepper_for(&problem, &y0, &Default::default())?;
    let mut tangent = Tangent::new(0.0, &y0, &[1.0, 0.5, 0.25, 0.125])?;
    let mut megno = Vec::new();
    for _ in 0..(T_END / H / 20.0) as usize {
        tangent.steps(&problem, &mut stepper, H, 20)?;
        megno.push((tangent.t(), tangent.indicators().mean_megno().max(1e-3)));
    }
    Ok((megno, tangent.indicators().lyapunov()))
}

/// Henon-Heiles at E = 1/6: regular or chaotic, orbit by orbit.
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let orbits = YS.iter().map(|&y| orbit(y)).collect::<anyhow::Result<Vec<_>>>()?;
    let series: Vec<Series> = YS
        .iter()
        .zip(&orbits)
        .map(|(y, (megno, _))| Series::line(format!("y0 = {}", number(*y)), megno.clone()))
        .collect();
    let chart = Chart::new("Henon-Heiles, E = 1/6: mean MEGNO against time", "t", "mean MEGNO")
        .scales(Scale::Linear, Scale::Log);
    let megno = picture(out, &MEGNO, &chart, &series)?;
    let mut table = vec![vec![
        "y0 (x0 = py0 = 0)".to_string(),
        "mean MEGNO at t = 2000".into(),
        "Lyapunov estimate".into(),
        "verdict".into(),
    ]];
    let (mut chaotic, mut lyapunovs, mut off_two) = (0, Vec::new(), 0.0_f64);
    for (y, (megno, lyapunov)) in YS.iter().zip(&orbits) {
        let last = megno.last().map_or(f64::NAN, |m| m.1);
        let verdict = if last > 2.5 {
            chaotic += 1;
            lyapunovs.push(*lyapunov);
            "chaotic"
        } else {
            off_two = off_two.max((last - 2.0).abs());
            "regular"
        };
        table.push(vec![
            number(*y).to_string(),
            number(last).significant(4).to_string(),
            number(*lyapunov).significant(3).to_string(),
            verdict.into(),
        ]);
    }
    let range = |xs: &[f64]| {
        let (lo, hi) = xs.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(x), hi.max(x))
        });
        format!("{} to {}", number(lo).significant(2), number(hi).significant(2))
    };
    let verdict = format!(
        "{chaotic} of the {} orbits are chaotic (mean MEGNO above 2.5, Lyapunov estimates {}), {} regular \
         (mean MEGNO within {} of 2 at t = 2000).",
        YS.len(),
        range(&lyapunovs),
        YS.len() - chaotic,
        number(off_two).significant(2)
    );
    Ok(Section {
        title: "Regular or chaotic? MEGNO on Henon-Heiles at E = 1/6".into(),
        verdict,
        table,
        pictures: vec![megno],
    })
}
