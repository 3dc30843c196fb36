//! The users' magnetic Verlet of docs/scenes.md 5, written out by hand: the reference that the
//! catalog's velocity Verlet with the exact gyration drift is checked against, in the
//! library's tests and through the binary.

/// The users' magnetic Verlet of docs/scenes.md 5 written out with its matrices exp(Omega h)
/// and F(h) (closed forms, field along axis 3 of strength `w`, `grad V = q/|q|^3`): the
/// positions and velocities after each of `steps` steps of `h` from `q0`, `v0 = 0`.
pub fn users_magnetic_verlet(w: f64, h: f64, q0: [f64; 3], steps: usize) -> Vec<[f64; 6]> {
    let om = [[0.0, -w, 0.0], [w, 0.0, 0.0], [0.0, 0.0, 0.0]];
    let mut om2 = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            om2[i][j] = (0..3).map(|k| om[i][k] * om[k][j]).sum();
        }
    }
    let (s, c) = ((w * h).sin(), (w * h).cos());
    let id = |i: usize, j: usize| if i == j { 1.0 } else { 0.0 };
    let e: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| id(i, j) + s / w * om[i][j] + 2.0 * ((w * h / 2.0).sin() / w).powi(2) * om2[i][j])
    });
    let f: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| id(i, j) * h + (1.0 - c) / (w * w) * om[i][j] - (s - w * h) / (w * w * w) * om2[i][j])
    });
    let grad = |q: [f64; 3]| {
        let r3 = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).powf(1.5);
        q.map(|x| x / r3)
    };
    let (mut q, mut v) = (q0, [0.0; 3]);
    let mut states = vec![[q[0], q[1], q[2], 0.0, 0.0, 0.0]];
    for _ in 0..steps {
        let g = grad(q);
        let half: [f64; 3] = std::array::from_fn(|i| v[i] - h / 2.0 * g[i]);
        q = std::array::from_fn(|i| q[i] + (0..3).map(|j| f[i][j] * half[j]).sum::<f64>());
        let g = grad(q);
        v = std::array::from_fn(|i| (0..3).map(|j| e[i][j] * half[j]).sum::<f64>() - h / 2.0 * g[i]);
        states.push([q[0], q[1], q[2], v[0], v[1], v[2]]);
    }
    states
}
