//! Second derivatives of a run's final state (src/chaos/second_order.rs): on second-order
//! dual numbers, with respect to a mass, along a direction of the initial state, and mixed,
//! they agree with central differences of the first derivatives for an explicit
//! Runge-Kutta method, splittings, an implicit method and the Kepler split; and Newton's
//! method with the exact Hessian converges quadratically where Gauss-Newton does not.

use num_dual::{Dual2SVec64, Dual2_64, Dual64};
use stormer::chaos::{final_state_derivative, final_state_second_derivative, SecondOrderScalar};
use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};
use stormer::real::lit;
use stormer::{Method, Real, SecondOrder};

use crate::support::outer_solar_system as oss;

/// Steps of 10 days: 1000 days, a quarter of Jupiter's period.
const STEPS: u64 = 100;

/// A method, on the n-body problem or in the Kepler split (Jacobi coordinates, where
/// velocity Verlet is Wisdom-Holman).
struct Case {
    method: &'static str,
    split: bool,
}

const CASES: [Case; 5] = [
    Case {
        method: "rk4",
        split: false,
    },
    Case {
        method: "velocity_verlet_kdk",
        split: false,
    },
    Case {
        method: "triple_jump4",
        split: false,
    },
    Case {
        method: "gauss_legendre4",
        split: false,
    },
    Case {
        method: "velocity_verlet_kdk",
        split: true,
    },
];

/// The outer solar system with the mass `m` of body `body` (0 the Sun, 1 Jupiter) and the
/// x component `vx` of Jupiter's initial velocity (the momenta are `m v`, so they depend on
/// both), `offset` added to the state.
fn system<T: Real>(body: usize, m: T, vx: T, offset: &[T; 24]) -> (NBody<T, [T; 24]>, [T; 24]) {
    let mut masses = oss::MASSES.map(lit::<T>);
    masses[body] = m;
    let bodies = NBody::<T, [T; 24]>::new(lit(oss::G), &masses, 3).unwrap();
    let mut v = oss::V.map(lit::<T>);
    v[3] = vx;
    let mut y = [T::zero(); 24];
    bodies.set_state(&oss::Q.map(lit), &v, &mut y).unwrap();
    for (y, &o) in y.iter_mut().zip(offset) {
        *y += o;
    }
    (bodies, y)
}

/// The end of `STEPS` steps of `case` from [`system`] (Jupiter's mass, or `$body`'s), by
/// `$final` (the first- or the second-order final state), in the split's coordinates for
/// the Kepler split.
macro_rules! run {
    ($final:ident, $case:expr, $m:expr, $vx:expr, $offset:expr) => {
        run!($final, $case, 1, $m, $vx, $offset)
    };
    ($final:ident, $case:expr, $body:expr, $m:expr, $vx:expr, $offset:expr) => {{
        let (bodies, y) = system($body, $m, $vx, $offset);
        let method = Method::named($case.method).unwrap();
        macro_rules! on {
            ($problem:expr, $y:expr) => {{
                let mut stepper = method.stepper_for(&$problem, &$y, &Default::default()).unwrap();
                $final(&$problem, &mut stepper, 0.0, &$y, 10.0, STEPS).unwrap()
            }};
        }
        if $case.split {
            let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap();
            let y = split.from_scene(&y);
            on!(split, y)
        } else {
            on!(bodies, y)
        }
    }};
}

/// The final state's derivative along the seeds of `m`, `vx` and `offset`.
fn first_order(case: &Case, m: Dual64, vx: Dual64, offset: &[Dual64; 24]) -> Vec<f64> {
    run!(final_state_derivative, case, m, vx, offset).derivative
}

/// Central differences in `s` of `first(s)`, extrapolated from the steps `e` and `e / 2`
/// (Richardson: the error `O(e^4)`).
fn differences(first: impl Fn(f64) -> Vec<f64>, e: f64) -> Vec<f64> {
    let central = |e: f64| -> Vec<f64> {
        let (plus, minus) = (first(e), first(-e));
        plus.iter().zip(&minus).map(|(p, m)| (p - m) / (2.0 * e)).collect()
    };
    let (coarse, fine) = (central(e), central(e / 2.0));
    fine.iter().zip(&coarse).map(|(f, c)| (4.0 * f - c) / 3.0).collect()
}

/// The largest difference between `exact` and `differences`, relative to the largest entry.
fn relative_difference(exact: &[f64], differences: &[f64]) -> f64 {
    let scale = exact.iter().fold(0.0_f64, |s, x| s.max(x.abs()));
    let worst = exact
        .iter()
        .zip(differences)
        .fold(0.0_f64, |w, (x, d)| w.max((x - d).abs()));
    worst / scale
}

fn assert_agrees(exact: &[f64], differences: &[f64], what: &str) {
    let relative = relative_difference(exact, differences);
    println!("{what}: relative difference {relative:.1e}");
    assert!(
        relative < 1e-6,
        "{what}: {relative:e}\n exact {exact:?}\n differences {differences:?}"
    );
}

/// The direction of the initial state the tests vary: Jupiter's x, Saturn's y and
/// Jupiter's y momentum (momenta are `m v`, some 1e-6 of the positions).
fn direction() -> [f64; 24] {
    let mut v = [0.0; 24];
    (v[3], v[7], v[16]) = (1.0, 0.5, 2e-6);
    v
}

/// The step of the differences in Jupiter's mass, relative to it, for `d2 y / d m2`: the
/// first derivatives in the mass carry rounding noise that steps of 1e-3 m magnify to
/// 2e-6 of the result (measured; 1e-4 m: 2e-5), so the steps are large and Richardson's
/// extrapolation keeps their error `O(step^4)` (measured: 1e-8 to 3e-8 at 0.1 m). The
/// mixed entry has no such noise: steps of 1e-3 m agree to 4e-13 ([`MIXED_STEP`]).
const MASS_STEP: f64 = 0.1;

/// The step of the differences in Jupiter's mass, relative to it, for the mixed entry.
const MIXED_STEP: f64 = 1e-3;

fn m0() -> f64 {
    oss::MASSES[1]
}

fn sun() -> f64 {
    oss::MASSES[0]
}

fn vx0() -> f64 {
    oss::V[3]
}

/// Second-order dual numbers seeded along `v` (one of the scalar's directions `k`).
fn seeded_offset<S: SecondOrderScalar<Re = f64>>(v: &[f64; 24], k: usize) -> [S; 24] {
    let mut first = [0.0; 4];
    v.map(|v| {
        first[k] = v;
        S::seeded(0.0, &first[..=k])
    })
}

#[test]
fn second_derivatives_with_respect_to_a_mass_agree_with_differences_of_first_derivatives() {
    let zero = [Dual2_64::from(0.0); 24];
    for case in &CASES {
        let (m, vx) = (Dual2_64::seeded(m0(), &[1.0]), Dual2_64::from(vx0()));
        let end = run!(final_state_second_derivative, case, m, vx, &zero);
        let second: Vec<f64> = end.second.iter().map(|h| h[(0, 0)]).collect();
        let first: Vec<f64> = end.first.iter().map(|d| d[0]).collect();
        let on_dual64 = |dm: f64| {
            first_order(
                case,
                Dual64::new(m0() + dm, 1.0),
                Dual64::from(vx0()),
                &[Dual64::from(0.0); 24],
            )
        };
        // the first derivative is the first-order one
        let what = format!("d y / d m, {} (split: {})", case.method, case.split);
        assert!(relative_difference(&first, &on_dual64(0.0)) < 1e-12, "{what}");
        let what = format!("d2 y / d m2, {} (split: {})", case.method, case.split);
        assert_agrees(&second, &differences(on_dual64, MASS_STEP * m0()), &what);
    }
}

#[test]
fn second_derivatives_along_an_initial_direction_agree_with_differences_of_first_derivatives() {
    let v = direction();
    let offset = seeded_offset::<Dual2_64>(&v, 0);
    for case in &CASES {
        let (m, vx) = (Dual2_64::from(m0()), Dual2_64::from(vx0()));
        let end = run!(final_state_second_derivative, case, m, vx, &offset);
        let second: Vec<f64> = end.second.iter().map(|h| h[(0, 0)]).collect();
        let along = |s: f64| {
            let offset = v.map(|v| Dual64::new(s * v, v));
            first_order(case, Dual64::from(m0()), Dual64::from(vx0()), &offset)
        };
        let what = format!("v^T H v, {} (split: {})", case.method, case.split);
        assert_agrees(&second, &differences(along, 1e-3), &what);
    }
}

#[test]
fn a_mixed_second_derivative_of_a_mass_and_an_initial_direction_agrees_with_differences() {
    type Two = Dual2SVec64<2>;
    let v = direction();
    // direction 0: Jupiter's mass; direction 1: v in the initial state
    let offset = seeded_offset::<Two>(&v, 1);
    for case in [&CASES[2], &CASES[3], &CASES[4]] {
        let (m, vx) = (Two::seeded(m0(), &[1.0]), Two::from(vx0()));
        let end = run!(final_state_second_derivative, case, m, vx, &offset);
        let mixed: Vec<f64> = end.second.iter().map(|h| h[(0, 1)]).collect();
        let what = format!("d2 y / dm dv, {} (split: {})", case.method, case.split);
        let asymmetry: Vec<f64> = end.second.iter().map(|h| h[(1, 0)]).collect();
        assert!(relative_difference(&mixed, &asymmetry) < 1e-12, "{what}: not symmetric");
        // d/dm of the derivative along v
        let along_v = |dm: f64| {
            let offset = v.map(|v| Dual64::new(0.0, v));
            first_order(case, Dual64::from(m0() + dm), Dual64::from(vx0()), &offset)
        };
        assert_agrees(&mixed, &differences(along_v, MIXED_STEP * m0()), &what);
    }
}

/// A position, its gradient (`[component][parameter]`) and Hessians
/// (`[component][parameter][parameter]`) with respect to two parameters.
type WithDerivatives = ([f64; 3], [[f64; 2]; 3], [[[f64; 2]; 2]; 3]);

/// Jupiter's final position (velocity Verlet), its gradient and its Hessian with respect to
/// the Sun's mass `m` and Jupiter's initial `vx`.
fn jupiter(m: f64, vx: f64) -> WithDerivatives {
    type Two = Dual2SVec64<2>;
    let case = &CASES[1];
    let (m, vx) = (Two::seeded(m, &[1.0, 0.0]), Two::seeded(vx, &[0.0, 1.0]));
    let end = run!(final_state_second_derivative, case, 0, m, vx, &[Two::from(0.0); 24]);
    let q = |i: usize| end.state[3 + i];
    let dq = |i: usize| [end.first[3 + i][0], end.first[3 + i][1]];
    let ddq = |i: usize| {
        let h = &end.second[3 + i];
        [[h[(0, 0)], h[(0, 1)]], [h[(1, 0)], h[(1, 1)]]]
    };
    ([q(0), q(1), q(2)], [dq(0), dq(1), dq(2)], [ddq(0), ddq(1), ddq(2)])
}

/// Newton iterates for the `(m, vx)` closest to `target` (least `|q - target|^2 / 2`):
/// with the exact Hessian `J^T J + sum r_i H_i`, or Gauss-Newton's `J^T J` alone.
fn fit(target: [f64; 3], start: [f64; 2], exact_hessian: bool, iterations: usize) -> Vec<[f64; 2]> {
    let mut x = start;
    let mut iterates = vec![x];
    for _ in 0..iterations {
        let (q, dq, ddq) = jupiter(x[0], x[1]);
        let r: Vec<f64> = (0..3).map(|i| q[i] - target[i]).collect();
        let mut g = [0.0; 2];
        let mut h = [[0.0; 2]; 2];
        for i in 0..3 {
            for j in 0..2 {
                g[j] += r[i] * dq[i][j];
                for k in 0..2 {
                    h[j][k] += dq[i][j] * dq[i][k] + if exact_hessian { r[i] * ddq[i][j][k] } else { 0.0 };
                }
            }
        }
        let det = h[0][0] * h[1][1] - h[0][1] * h[1][0];
        x[0] -= (h[1][1] * g[0] - h[0][1] * g[1]) / det;
        x[1] -= (h[0][0] * g[1] - h[1][0] * g[0]) / det;
        iterates.push(x);
    }
    iterates
}

/// The largest relative error of each iterate against `best`.
fn errors(iterates: &[[f64; 2]], best: [f64; 2]) -> Vec<f64> {
    iterates
        .iter()
        .map(|x| {
            ((x[0] - best[0]) / best[0])
                .abs()
                .max(((x[1] - best[1]) / best[1]).abs())
        })
        .collect()
}

#[test]
fn newtons_method_with_the_exact_hessian_fits_the_suns_mass_and_a_velocity_quadratically() {
    // a target off the surface of reachable positions, along its normal `n` at the true
    // `(m, vx)` (the Sun's mass, Jupiter's velocity): the least squares fit is the truth, with a residual `alpha n` whose
    // curvature term `-alpha n.H_i` Gauss-Newton leaves out; alpha is set so that it
    // converges linearly, its error shrinking by a quarter at best at each step, while Newton with the whole Hessian
    // converges quadratically
    let (q, dq, ddq) = jupiter(sun(), vx0());
    let (a, b) = ([dq[0][0], dq[1][0], dq[2][0]], [dq[0][1], dq[1][1], dq[2][1]]);
    let cross = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let norm = cross.iter().map(|c| c * c).sum::<f64>().sqrt();
    let n = cross.map(|c| c / norm);
    let jtj = |j: usize, k: usize| (0..3).map(|i| dq[i][j] * dq[i][k]).sum::<f64>();
    let curvature = |j: usize, k: usize| (0..3).map(|i| n[i] * ddq[i][j][k]).sum::<f64>();
    // (J^T J)^-1 (n.H): Gauss-Newton's error shrinks by alpha times its spectral radius
    let det = jtj(0, 0) * jtj(1, 1) - jtj(0, 1) * jtj(1, 0);
    let inverse = [[jtj(1, 1) / det, -jtj(0, 1) / det], [-jtj(1, 0) / det, jtj(0, 0) / det]];
    let m = |j: usize, k: usize| inverse[j][0] * curvature(0, k) + inverse[j][1] * curvature(1, k);
    let (trace, determinant) = (m(0, 0) + m(1, 1), m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0));
    let radius = (trace.abs() + (trace * trace - 4.0 * determinant).abs().sqrt()) / 2.0;
    let alpha = 0.25 / radius;
    let target = [0, 1, 2].map(|i| q[i] + alpha * n[i]);
    let start = [1.001 * sun(), 1.01 * vx0()];
    let newton = fit(target, start, true, 8);
    let best = *newton.last().unwrap();
    let e = errors(&newton[..7], best);
    let show = |e: &[f64]| e.iter().map(|e| format!("{e:.1e}")).collect::<Vec<_>>().join(" ");
    println!("residual {alpha:.2e} AU; Newton with the Hessian: {}", show(&e));
    let gauss_newton = errors(&fit(target, start, false, 6), best);
    println!("Gauss-Newton:          {}", show(&gauss_newton));
    assert!(
        errors(&[best], [sun(), vx0()])[0] < 1e-12,
        "fitted {best:?}, true {:?}",
        [sun(), vx0()]
    );
    // quadratic: each error above round-off is the square of the one before, roughly
    let above_round_off: Vec<(f64, f64)> = e
        .windows(2)
        .map(|w| (w[0], w[1]))
        .filter(|&(_, next)| next > 1e-11)
        .collect();
    assert!(above_round_off.len() >= 2, "too few steps to judge: {e:?}");
    for &(error, next) in &above_round_off[above_round_off.len() - 2..] {
        let order = next.ln() / error.ln();
        assert!(order > 1.7, "not quadratic: {error:e} -> {next:e} (order {order:.2})");
    }
    assert!(e[6] < 1e-11, "not converged: {e:?}");
    // Gauss-Newton, linear: each step shrinks the error by a constant factor, and it is
    // still far off after as many steps
    let rate = gauss_newton[6] / gauss_newton[5];
    assert!(
        rate > 0.1 && gauss_newton[6] > 1e-8,
        "Gauss-Newton as fast: {gauss_newton:?}"
    );
}

/// `q'' = -(q - a)^2`: at `q = a`, `p = 0` an equilibrium whose force has zero first but
/// nonzero second derivatives, so an implicit solver's first sweep leaves the value and
/// the first derivatives unchanged and only the second derivatives move.
struct Pinned<T> {
    a: T,
}

impl<T: Real> SecondOrder for Pinned<T> {
    type Scalar = T;
    type State = [T; 2];
    fn acceleration(&self, _t: T, q: &[T], acc: &mut [T]) {
        let d = q[0] - self.a;
        acc[0] = -d * d;
    }
}

/// 10 steps of 0.1 of the implicit `gauss_legendre4` on [`Pinned`] from rest at 0.
fn pinned<T: Real, R>(a: T, end: impl FnOnce(&Pinned<T>, &mut dyn stormer::Stepper<Pinned<T>>, &[T; 2]) -> R) -> R {
    let problem = Pinned { a };
    let y0 = [T::zero(); 2];
    let mut stepper = Method::named("gauss_legendre4")
        .unwrap()
        .stepper_for(&problem, &y0, &Default::default())
        .unwrap();
    end(&problem, &mut *stepper, &y0)
}

#[test]
fn an_implicit_method_converges_the_second_derivatives_at_an_equilibrium() {
    let first = |da: f64| {
        pinned(Dual64::new(da, 1.0), |p, s, y| {
            final_state_derivative(p, s, 0.0, y, 0.1, 10).unwrap().derivative
        })
    };
    let differences = differences(first, 1e-3);
    let one = pinned(Dual2_64::seeded(0.0, &[1.0]), |p, s, y| {
        final_state_second_derivative(p, s, 0.0, y, 0.1, 10).unwrap()
    });
    let two = pinned(Dual2SVec64::<2>::seeded(0.0, &[1.0]), |p, s, y| {
        final_state_second_derivative(p, s, 0.0, y, 0.1, 10).unwrap()
    });
    for (end, what) in [(one, "Dual2_64"), (two, "Dual2SVec64<2>")] {
        let second: Vec<f64> = end.second.iter().map(|h| h[(0, 0)]).collect();
        assert_agrees(
            &second,
            &differences,
            &format!("d2 y / d a2 at an equilibrium, on {what}"),
        );
    }
}
