//! A weighted Euclidean norm after a linear change of coordinates, `|W T x|`, as the
//! quadratic form `sqrt(x^T G x)` with `G = T^T W^2 T` kept by its non-zero entries: the
//! measure of a variation in the scene's coordinates while it is carried in the split's
//! (Jacobi coordinates and momenta: `G` couples only the same component of the bodies,
//! 6 N(N+1)/2 entries in 3-D where the change itself costs a pass over the state and a
//! copy). The indicators take it at every step (docs/chaos.md).

/// `G`'s entries on and above the diagonal, those off it doubled: `(i, j, g)`.
#[derive(Debug, Clone)]
pub struct QuadraticNorm {
    entries: Vec<(usize, usize, f64)>,
}

impl QuadraticNorm {
    /// The norm `|W T x|` on vectors of length `n`, where `change(x)` applies `T` in place
    /// (linear; exact zeros where no component feeds another, as the changes of
    /// coordinates of the crate give) and `weights[i]` is `W`'s `i`-th diagonal entry.
    pub fn new(n: usize, change: impl Fn(&mut [f64]), weights: &[f64]) -> Self {
        // T's columns, weighted
        let columns: Vec<Vec<f64>> = (0..n)
            .map(|j| {
                let mut column = vec![0.0; n];
                column[j] = 1.0;
                change(&mut column);
                column.iter().zip(weights).map(|(t, w)| t * w).collect()
            })
            .collect();
        let mut entries = Vec::new();
        for i in 0..n {
            for j in i..n {
                let g: f64 = columns[i].iter().zip(&columns[j]).map(|(a, b)| a * b).sum();
                if g != 0.0 {
                    entries.push((i, j, if i == j { g } else { 2.0 * g }));
                }
            }
        }
        QuadraticNorm { entries }
    }

    /// `|W T x|`, with `x_i = part(&y[i])` (read in place: no copy of the state).
    #[inline]
    pub fn of<Y>(&self, y: &[Y], part: impl Fn(&Y) -> f64) -> f64 {
        let square: f64 = self
            .entries
            .iter()
            .map(|&(i, j, g)| g * part(&y[i]) * part(&y[j]))
            .sum();
        // rounding may leave a tiny negative for a zero vector's neighbours
        square.max(0.0).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};

    #[test]
    fn the_form_is_the_norm_after_the_change_for_both_splits_to_round_off() {
        let masses = [1.0, 1e-3, 3e-4];
        let bodies = NBody::<f64, nalgebra::DVector<f64>>::new(1.0, &masses, 3).unwrap();
        let weights: Vec<f64> = (0..18)
            .map(|i| if i < 9 { 1.0 } else { 1.0 / masses[(i - 9) / 3] })
            .collect();
        for coordinates in [KeplerCoordinates::Jacobi, KeplerCoordinates::DemocraticHeliocentric] {
            let split = KeplerSplit::new(bodies.clone(), coordinates).unwrap();
            let norm = QuadraticNorm::new(18, |x| split.split_to_scene(x), &weights);
            // the same component of the bodies only: 2 blocks x 3 components x 6 entries
            assert!(norm.entries.len() <= 36, "{}", norm.entries.len());
            let x: Vec<f64> = stormer::models::SplitMix64::new(7).take(18).collect();
            let mut scene = x.clone();
            split.split_to_scene(&mut scene);
            let direct = scene
                .iter()
                .zip(&weights)
                .map(|(s, w)| (s * w) * (s * w))
                .sum::<f64>()
                .sqrt();
            let form = norm.of(&x, |x| *x);
            assert!((form - direct).abs() <= 1e-14 * direct, "{form} {direct}");
        }
    }
}
