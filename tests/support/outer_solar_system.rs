//! The outer solar system of the scene `outer-solar-system` (Sun, Jupiter, Saturn, Uranus;
//! GNI I.2.4), AU and days, shared by the tests, benches and examples that need it in
//! `[f64; 24]`.

use stormer::models::NBody;

/// Positions then velocities of the bodies, as `[f64; 24]`.
pub type Outer = [f64; 24];

/// `G` in AU^3 / (solar mass day^2).
pub const G: f64 = 2.95912208286e-4;
/// The Sun's mass (with the inner planets') and the planets', in solar masses.
pub const MASSES: [f64; 4] = [1.00000597682, 0.000954786104043, 0.000285583733151, 0.0000437273164546];
/// Positions, AU.
pub const Q: [f64; 12] = [
    0.0,
    0.0,
    0.0,
    -3.5023653,
    -3.8169847,
    -1.5507963,
    9.0755314,
    -3.0458353,
    -1.6483708,
    8.3101420,
    -16.2901086,
    -7.2521278,
];
/// Velocities, AU per day.
pub const V: [f64; 12] = [
    0.0,
    0.0,
    0.0,
    0.00565429,
    -0.00412490,
    -0.00190589,
    0.00168318,
    0.00483525,
    0.00192462,
    0.00354178,
    0.00137102,
    0.00055029,
];

/// The system with the planets' masses times `scale`, and its initial state.
pub fn outer_solar_system(scale: f64) -> (NBody<f64, Outer>, Outer) {
    let mut masses = MASSES;
    for m in &mut masses[1..] {
        *m *= scale;
    }
    let bodies = NBody::new(G, &masses, 3).expect("four bodies in 3-D");
    let mut y = [0.0; 24];
    bodies
        .set_state(&Q, &V, &mut y)
        .expect("12 positions and 12 velocities");
    (bodies, y)
}
