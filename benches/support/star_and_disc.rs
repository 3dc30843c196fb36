//! A star and `n - 1` light bodies on near-circular orbits, `G = 1`: the many-body scene of
//! the scaling benches, the thread tests and the REBOUND comparison (the same numbers in
//! every one of them, from a formula rather than a random generator).

#![allow(dead_code)] // each user takes its part

/// Positions and velocities (3-D, body by body) and masses of `n` bodies: body 0 of mass 1 at
/// rest at the origin, body `k` of mass `1e-3 / n` at radius 1 to 5 and angle spread by
/// quasi-random sequences, a small height, on the circular speed.
pub fn star_and_disc(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let frac = |x: f64| x - x.floor();
    let (mut q, mut v, mut m) = (vec![0.0; 3 * n], vec![0.0; 3 * n], vec![1.0; n]);
    for k in 1..n {
        let kf = k as f64;
        let r = 1.0 + 4.0 * frac(kf * 0.618_033_988_749_894_9);
        let theta = 2.0 * core::f64::consts::PI * frac(kf * 0.754_877_666_246_692_7);
        let z = 0.01 * (frac(kf * 0.569_840_290_998_053_2) - 0.5);
        let speed = (1.0 / r).sqrt();
        q[3 * k..3 * k + 3].copy_from_slice(&[r * theta.cos(), r * theta.sin(), z]);
        v[3 * k..3 * k + 3].copy_from_slice(&[-speed * theta.sin(), speed * theta.cos(), 0.0]);
        m[k] = 1e-3 / n as f64;
    }
    (q, v, m)
}

/// Unordered pairs computed per force evaluation: `M (M - 1) / 2` among the `M` active bodies
/// and `M (N - M)` between them and the test particles.
pub fn pairs(n: usize, active: usize) -> usize {
    active * active.saturating_sub(1) / 2 + active * (n - active)
}
