//! Extreme field strengths and masses, through the scene files: a charged particle in a
//! magnetic field of strength 0, 1e-12 and one turning by 1000 radians per step; N bodies
//! with masses of 1e30 and 1e-30.

use std::ops::Range;

use nalgebra::DVector;
use stormer::models::NBody;
use stormer::{Driver, Error, Method, Real, State, Stepper};
use stormer_app::scenes::{self, AnyScene, ChargedScene, Setup};

/// The cyclotron scene with field `b` along z: the helix of radius `1/b` (a line at b = 0)
/// through (0, 1, 0) with velocity (1, 0, 0.1).
fn field_scene(b: f64) -> Setup<ChargedScene> {
    let text = format!(
        r#"
model = "charged-particles"
[parameters]
B = [0.0, 0.0, {b:e}]
[[particles]]
ratio = 1.0
position = [0.0, 1.0, 0.0]
velocity = [1.0, 0.0, 0.1]
[run]
method = "boris"
dt = 0.1
t_end = 100.0
"#
    );
    match scenes::parse(&text, "test", "field").unwrap() {
        AnyScene::ChargedParticles(s) => s,
        other => panic!("{}", other.model()),
    }
}

fn charged_stepper(s: &Setup<ChargedScene>, name: &str) -> Box<dyn Stepper<ChargedScene>> {
    let method = Method::resolve(name).unwrap();
    method.stepper_for(&s.model, &s.y0, &Default::default()).unwrap()
}

/// max over the records of `| |v| - |v0| | / |v0|` and of `|y - exact|` (max norm).
fn speed_and_exact(s: &Setup<ChargedScene>, t: &[f64], y: &[DVector<f64>]) -> (f64, f64) {
    let speed = |y: &DVector<f64>| y.rows(3, 3).norm();
    let v0 = speed(&s.y0);
    let dv = y.iter().map(|y| (speed(y) - v0).abs() / v0).fold(0.0, f64::max);
    let dx = t
        .iter()
        .zip(y)
        .map(|(&t, y)| (y - s.exact(t).unwrap()).amax())
        .fold(0.0, f64::max);
    (dv, dx)
}

/// The kepler scene (two bodies, m = 1 and 0.1, G = 4 pi^2) with every mass multiplied by
/// `scale` and G divided by it: the same orbits, momenta `scale` times larger.
fn kepler(scale: f64) -> Setup<NBody<f64, DVector<f64>>> {
    let g = 4.0 * std::f64::consts::PI.powi(2) / scale;
    let text = format!(
        r#"
model = "n-body"
[parameters]
G = {g:e}
[[bodies]]
name = "star"
mass = {m1:e}
position = [0.0, 0.0]
velocity = [0.0, -0.3]
[[bodies]]
name = "planet"
mass = {m2:e}
position = [2.5, 0.0]
velocity = [0.0, 3.0]
[run]
method = "velocity_verlet_kdk"
dt = 0.01
t_end = 10.0
"#,
        m1 = scale,
        m2 = 0.1 * scale
    );
    match scenes::parse(&text, "test", "kepler-scaled").unwrap() {
        AnyScene::NBody(s) => s,
        other => panic!("{}", other.model()),
    }
}

fn nbody_stepper(s: &Setup<NBody<f64, DVector<f64>>>, name: &str) -> Box<dyn Stepper<NBody<f64, DVector<f64>>>> {
    let method = Method::named(name).unwrap();
    method.stepper_for(&s.model, &s.y0, &Default::default()).unwrap()
}

/// Field 0 and 1e-12 (the gyration's `sin(w h)/w` and `(1 - cos(w h))/w^2` at and near
/// `w = 0`, where a naive formula divides by zero or cancels), 1000 steps of 0.1: every
/// method keeps `|v|` exactly (measured 0) and follows the exact straight line / helix
/// (x reaches 100) to 1.4e-12 (Kahan-Li 6 7.0e-12, Euler-Cromer 5.0e-12 at 1e-12).
#[test]
fn zero_and_tiny_fields_are_straight_lines_to_round_off() {
    // (method, bound on the distance to the exact solution)
    let methods = [
        ("velocity_verlet_kdk", 5e-12),
        ("kahan_li6", 3e-11),
        ("boris", 5e-12),
        ("boris_exact_phase", 5e-12),
        ("euler_cromer", 2e-11),
        ("rk4", 5e-12),
    ];
    for b in [0.0, 1e-12] {
        let s = field_scene(b);
        for (name, bound) in methods {
            let mut st = charged_stepper(&s, name);
            let sol = Driver::fixed(0.1).run(&s.model, &mut st, 0.0, &s.y0, 100.0).unwrap();
            let (dv, dx) = speed_and_exact(&s, &sol.t, &sol.y);
            assert!(
                dv <= 4.0 * f64::EPSILON && dx <= bound,
                "B = {b:e}, {name}: |v| {dv:e}, exact {dx:e}"
            );
        }
    }
}

/// Field 1e4 at h = 0.1: the particle turns by `w h` = 1000 radians per step, on a circle
/// of radius 1e-4. The magnetic Verlet's drift is the exact gyration: it keeps `|v|` to
/// 479 eps and the exact helix to 1.2e-10 after 1000 steps (Kahan-Li 6: 1323 eps, 7.7e-11).
/// Boris keeps `|v|` (1997 eps) but turns by `2 atan(w h / 2)` instead of `w h`; its
/// positions move by `h (v_n + v_{n+1}) / 2` (drift-kick-drift), which keeps the guiding
/// centre where it is, so they circle on the exact Larmor radius `|v| / w` = 1e-4 (the
/// leapfrog positions, moved by the half-step velocity of length `|v| sqrt(1 + (w h/2)^2)`,
/// would circle on `h |v| (1 + s^2) / (2 s)`, `s = w h/2`, = 25.0). Boris with
/// the exact phase refuses the step (`|omega| h < pi`); Euler-Cromer and RK4 blow up, and
/// the run stops at the step where the state becomes non-finite (51 and 28), keeping
/// every record before it.
#[test]
fn a_field_turning_1000_radians_per_step() {
    let (b, h, steps) = (1e4, 0.1, 1000);
    let s = field_scene(b);
    let t_end = h * steps as f64;
    let eps = f64::EPSILON;
    for (name, speed_bound, exact_bound) in [
        ("velocity_verlet_kdk", 2000.0 * eps, 5e-10),
        ("kahan_li6", 5000.0 * eps, 3e-10),
    ] {
        let mut st = charged_stepper(&s, name);
        let sol = Driver::fixed(h).run(&s.model, &mut st, 0.0, &s.y0, t_end).unwrap();
        let (dv, dx) = speed_and_exact(&s, &sol.t, &sol.y);
        assert!(
            dv <= speed_bound && dx <= exact_bound,
            "{name}: |v| {dv:e}, exact {dx:e}"
        );
    }
    let mut boris = charged_stepper(&s, "boris");
    let sol = Driver::fixed(h).run(&s.model, &mut boris, 0.0, &s.y0, t_end).unwrap();
    let (dv, _) = speed_and_exact(&s, &sol.t, &sol.y);
    assert!(dv <= 8000.0 * eps, "boris: |v| {dv:e}");
    let radius = 1.0 / b; // |v_perp| / w
    let widest = sol
        .y
        .iter()
        .map(|y| (y[0] - s.y0[0]).hypot(y[1] - s.y0[1]))
        .fold(0.0, f64::max);
    assert!(
        (widest / (2.0 * radius) - 1.0).abs() < 1e-3,
        "boris: diameter {widest} vs {}",
        2.0 * radius
    );

    let mut exact_phase = charged_stepper(&s, "boris_exact_phase");
    let refused = Driver::fixed(h)
        .run(&s.model, &mut exact_phase, 0.0, &s.y0, t_end)
        .unwrap_err();
    assert!(
        matches!(refused.error, Error::InvalidArgument { .. }),
        "{}",
        refused.error
    );
    assert!(refused.error.to_string().contains("< pi"), "{}", refused.error);
    assert_eq!(refused.solution.t, [0.0]);

    for (name, at) in [("euler_cromer", 51), ("rk4", 28)] {
        let mut st = charged_stepper(&s, name);
        let blown = Driver::fixed(h).run(&s.model, &mut st, 0.0, &s.y0, t_end).unwrap_err();
        let Error::NonFinite { step, t } = blown.error else {
            panic!("{name}: {}", blown.error)
        };
        assert_eq!(step, at, "{name}");
        assert_eq!(t, at as f64 * h, "{name}");
        assert_eq!(
            blown.solution.t.len() as u64,
            step + 1,
            "{name}: every record before the blow-up"
        );
        assert!(blown.solution.y.iter().all(|y| y.iter().all(|x| x.is_finite())));
    }
}

/// The kepler scene with masses 1e30 and 1e-30 times the users' (G divided by the same):
/// the same orbits. Over 1000 steps the positions agree with the unscaled run to 1.1e-12
/// (on |q| ~ 2.5), the momenta divided by the scale to 4.8e-13, the relative energy error
/// is the unscaled run's (to 3 digits), and the total momentum stays at zero to 1.1 eps of
/// the momenta's size (exactly 0 at 1e-30), for velocity Verlet, RK4, Kahan-Li 6 and
/// Gauss-Legendre 4.
#[test]
fn masses_of_1e30_and_1e_30_give_the_same_orbits() {
    for name in ["velocity_verlet_kdk", "rk4", "kahan_li6", "gauss_legendre4"] {
        let run = |scale: f64| {
            let s = kepler(scale);
            let mut st = nbody_stepper(&s, name);
            let sol = Driver::fixed(0.01).run(&s.model, &mut st, 0.0, &s.y0, 10.0).unwrap();
            let momentum = sol
                .y
                .iter()
                .map(|y| {
                    let total = s.model.total_momentum(y);
                    let size: f64 = y.rows(4, 4).iter().map(|x| x.abs()).sum();
                    total.iter().map(|x| x.abs()).fold(0.0, f64::max) / size
                })
                .fold(0.0, f64::max);
            let de = max_energy_error(&sol.energy);
            (sol, momentum, de)
        };
        let (base, _, base_de) = run(1.0);
        for scale in [1e30, 1e-30] {
            let (sol, momentum, de) = run(scale);
            let dq = max_deviation(&sol.y, &base.y, 0..4, 1.0);
            let dp = max_deviation(&sol.y, &base.y, 4..8, scale);
            let what =
                format!("{name} x {scale:e}: momentum {momentum:e}, dE {de:e} vs {base_de:e}, dq {dq:e}, dp {dp:e}");
            assert!(momentum <= 4.0 * f64::EPSILON, "{what}");
            assert!((de / base_de - 1.0).abs() < 0.01, "{what}");
            assert!(dq <= 5e-12 && dp <= 2e-12, "{what}");
        }
    }
}

/// The largest relative energy error of a run's records against the first.
fn max_energy_error<T: Real>(energy: &[T]) -> T {
    let e0 = energy[0];
    energy
        .iter()
        .map(|&e| ((e - e0) / e0).abs())
        .fold(T::zero(), |m, d| m.max(d))
}

/// The largest `|a_i / scale - b_i|` over the records of two runs, for the components
/// `range` of their states.
fn max_deviation<T: Real, S: State<Scalar = T>>(a: &[S], b: &[S], range: Range<usize>, scale: T) -> T {
    a.iter()
        .zip(b)
        .flat_map(|(x, y)| {
            let range = range.clone();
            range.map(move |i| (x.as_slice()[i] / scale - y.as_slice()[i]).abs())
        })
        .fold(T::zero(), |m, d| m.max(d))
}

/// The same in f32, where 1e30 squared overflows and 1e-30 squared underflows: masses
/// 1e30 and 1e-30 (G scaled) give the unscaled run's energy (E0 / scale equal to 8 eps),
/// its relative energy error (6.74e-4 against 6.74e-4, to 3.4e-4 of it) and its orbits
/// (positions within 4.8e-5 after 1000 steps, `n eps |q|` = 3e-4). The N-body energy used
/// to compute `|p|^2 / m`, which gave E0 = inf at 1e30 and dropped the kinetic energy at
/// 1e-30; it now computes `(p / m) p`.
#[test]
fn masses_of_1e30_and_1e_30_in_f32() {
    type Two = NBody<f32, [f32; 8]>;
    let run = |scale: f32| {
        let g = 4.0 * std::f32::consts::PI.powi(2) / scale;
        let model = Two::new(g, &[scale, 0.1 * scale], 2).unwrap();
        let mut y0 = [0.0f32; 8];
        model
            .set_state(&[0.0, 0.0, 2.5, 0.0], &[0.0, -0.3, 0.0, 3.0], &mut y0)
            .unwrap();
        let verlet = Method::named("velocity_verlet_kdk").unwrap();
        let mut verlet = verlet.stepper_for(&model, &y0, &Default::default()).unwrap();
        let sol = Driver::fixed(0.01f32).run(&model, &mut verlet, 0.0, &y0, 10.0).unwrap();
        let (e0, de) = (sol.energy[0], max_energy_error(&sol.energy));
        (sol, e0 / scale, de)
    };
    let (base, base_e0, base_de) = run(1.0);
    for scale in [1e30f32, 1e-30] {
        let (sol, e0, de) = run(scale);
        let dq = max_deviation(&sol.y, &base.y, 0..4, 1.0);
        let what = format!("x {scale:e}: E0 / scale {e0} vs {base_e0}, dE {de:e} vs {base_de:e}, dq {dq:e}");
        assert!(e0.is_finite() && (e0 / base_e0 - 1.0).abs() < 1e-6, "{what}");
        assert!((de / base_de - 1.0).abs() < 3e-3, "{what}");
        assert!(dq < 2e-4, "{what}");
    }
}

/// The stability limits of the charged-particle methods (not catalog data, so not in
/// tests/methods/stability.rs), in the field of strength 1 at 0.99 and 1.01 times the limit:
/// Euler-Cromer's map `[[1, a], [-a, 1 - a^2]]` (`a = w h`) is bounded for `a <= 2`
/// (measured max |v| 10.0 at a = 1.98, from |v0| = 1.005: the map is far from a rotation
/// there) and grows at its eigenvalue's rate above; Boris keeps `|v|` at any step (w h = 100
/// here); Boris with the exact phase works up to `w h < pi` and refuses larger steps.
#[test]
fn charged_particle_methods_at_their_stability_limits() {
    let s = field_scene(1.0);
    let speed = |y: &DVector<f64>| y.rows(3, 3).norm();
    let v0 = speed(&s.y0);
    let largest = |name: &str, h: f64, steps: f64| {
        let mut st = charged_stepper(&s, name);
        let sol = Driver::fixed(h).run(&s.model, &mut st, 0.0, &s.y0, h * steps).unwrap();
        sol.y.iter().map(speed).fold(0.0, f64::max)
    };
    assert!(largest("euler_cromer", 0.99 * 2.0, 2000.0) < 30.0 * v0);
    let a: f64 = 1.01 * 2.0;
    let half_trace = (2.0 - a * a).abs() / 2.0;
    let rate = (half_trace + (half_trace * half_trace - 1.0).sqrt()).ln();
    let measured = (largest("euler_cromer", a, 200.0) / v0).ln() / 200.0;
    assert!((measured / rate - 1.0).abs() < 0.05, "rate {measured} vs {rate}");
    // |v| kept to round-off over the 2000 steps: measured 1.2e-13 for both
    let round_off = 2.0 * 2000.0 * f64::EPSILON;
    let boris = largest("boris", 100.0, 2000.0);
    assert!((boris - v0).abs() <= round_off, "{boris}");
    let pi = std::f64::consts::PI;
    let exact_phase = largest("boris_exact_phase", 0.99 * pi, 2000.0);
    assert!((exact_phase - v0).abs() <= round_off, "{exact_phase}");
    let mut st = charged_stepper(&s, "boris_exact_phase");
    let refused = Driver::fixed(1.01 * pi)
        .run(&s.model, &mut st, 0.0, &s.y0, 10.0)
        .unwrap_err();
    assert!(
        matches!(refused.error, Error::InvalidArgument { .. }),
        "{}",
        refused.error
    );
}
