//! Escapes: an n-body run ends when a body gets `[run] escape_distance` from the centre of
//! mass of all the bodies (REBOUND's `exit_max_distance`), located within the step like
//! every stop condition, with a sentence saying which body and when. A stability map's
//! escaped orbits are then a record, not a NaN or an endless run (docs/chaos.md).

use nalgebra::DVector;
use stormer::models::NBody;

use super::{Scene, Stop};

/// The body farthest from the centre of mass of the bodies whose positions `y` begins
/// with (momenta may follow), its index and its distance.
pub fn farthest(bodies: &NBody<f64, DVector<f64>>, y: &[f64]) -> (usize, f64) {
    let (d, masses) = (bodies.dim(), bodies.masses());
    let total: f64 = masses.iter().sum();
    let mut centre = [0.0; 3];
    for (c, centre) in centre[..d].iter_mut().enumerate() {
        let moment: f64 = masses.iter().enumerate().map(|(k, &m)| m * y[k * d + c]).sum();
        *centre = moment / total;
    }
    // the largest squared distance, its root taken once (the root is monotonic: the same
    // body, the same bits)
    let mut out = (0, 0.0);
    for (k, q) in y[..masses.len() * d].chunks_exact(d).enumerate() {
        let r2: f64 = q.iter().zip(&centre).map(|(x, c)| (x - c) * (x - c)).sum();
        // a body that is no longer finite is the farthest
        if r2 > out.1 || r2.is_nan() {
            out = (k, r2);
        }
    }
    (out.0, out.1.sqrt())
}

/// The stop of an n-body scene whose runs end at `distance` from the centre of mass: `g`
/// is minus the farthest body's distance, crossing `-distance` outwards.
pub fn stop<S: Scene>(distance: f64) -> Stop<S> {
    Stop {
        event: "escape",
        g: |model, _, y| farthest_in(model, y).map_or(0.0, |(_, r)| -r),
        // the bound's rounding is a few units of the last place: a margin far above it
        g_at_least: Some(|model, y| {
            model
                .distance_bound(y)
                .map_or(f64::NEG_INFINITY, |r| -r * (1.0 + 1e-12))
        }),
        level: -distance,
        report: |model, t, y| match escaped(model, y) {
            Some((name, r)) => format!(
                "{name} escapes: {} from the centre of mass at t = {}",
                stormer::text::number(r).significant(6),
                stormer::text::number(t).significant(9)
            ),
            None => format!("the run stopped at t = {t}"),
        },
    }
}

/// The farthest body of the scene state of `y` (the model's own state, in the scene's
/// coordinates first), its name and distance; `None` for a model without bodies.
fn escaped<S: Scene>(model: &S, y: &S::State) -> Option<(String, f64)> {
    let (k, r) = farthest_in(model, y)?;
    let names = model.bodies()?.names();
    Some((names.get(k).cloned().unwrap_or_else(|| format!("body {k}")), r))
}

/// [`farthest`] of the scene state of `y`, with no allocation for up to 16 bodies in 3-D.
fn farthest_in<S: Scene>(model: &S, y: &S::State) -> Option<(usize, f64)> {
    let bodies = model.bodies()?;
    Some(super::stack_buffer::with_zeros(
        bodies.masses().len() * bodies.dim(),
        |q| {
            model.scene_positions(y, q);
            farthest(bodies, q)
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_farthest_body_is_measured_from_the_centre_of_mass() {
        let bodies = NBody::<f64, DVector<f64>>::new(1.0, &[3.0, 1.0], 1).unwrap();
        // centre of mass at 1: the light body at 4 is 3 away, the heavy one at 0 is 1
        let y = [0.0, 4.0, 0.0, 0.0];
        assert_eq!(farthest(&bodies, &y), (1, 3.0));
        assert_eq!(farthest(&bodies, &[0.0, f64::NAN, 0.0, 0.0]).0, 1);
    }

    #[test]
    fn the_split_bound_is_never_below_the_farthest_body_in_either_coordinates() {
        use crate::scenes::{load, AnyScene};
        use stormer::models::{KeplerCoordinates, SplitMix64};
        for coordinates in [KeplerCoordinates::Jacobi, KeplerCoordinates::DemocraticHeliocentric] {
            let AnyScene::KeplerSplit(setup) = load("outer-solar-system").unwrap().with_split(coordinates).unwrap()
            else {
                panic!("not split");
            };
            let mut draws = SplitMix64::new(11);
            for scale in [0.1, 1.0, 30.0] {
                let y = setup.y0.map(|x| x + scale * draws.next().unwrap());
                let (_, r) = farthest_in(&setup.model, &y).unwrap();
                let bound = setup.model.distance_bound(&y).unwrap();
                assert!(bound >= r && bound <= 5.0 * r, "{coordinates:?} {scale}: {bound} {r}");
            }
        }
    }
}
