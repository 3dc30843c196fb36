//! A star and two planets, the first falling straight onto the star (zero angular
//! momentum, r -> 0 within the first steps of 0.01): the collision course that every
//! Kepler-split run must end cleanly.

use stormer::models::NBody;

/// The bodies (`G = 1`, 2-D) and their state.
pub fn collision_course() -> (NBody<f64, [f64; 12]>, [f64; 12]) {
    let bodies = NBody::<f64, [f64; 12]>::new(1.0, &[1.0, 1e-3, 1e-3], 2).expect("three bodies in 2-D");
    let mut y = [0.0; 12];
    bodies
        .set_state(
            &[0.0, 0.0, 0.05, 0.0, 2.0, 0.0],
            &[0.0, 0.0, 0.0, 0.0, 0.0, 0.7],
            &mut y,
        )
        .expect("6 positions and 6 velocities");
    (bodies, y)
}
