//! Total momentum and angular momentum are conserved to round-off in the N-body scenes
//! (the scene files as loaded, `DVector` states), by splittings and compositions; RK4
//! keeps the momentum (a linear invariant) but not the angular momentum (quadratic): the
//! negative control.
//!
//! The bounds, worst case (every rounding of the same sign), per component:
//! - momentum `P = sum p_k`: a kick `p_k += tau f_k` rounds each `p_k` once (`eps/2` of
//!   `|p_k|`), and the forces sum to zero up to the rounding of their accumulation
//!   (`tau |f_k|` is far below `|p_k|`); a drift leaves `p` alone. So after `K` kicks
//!   `|P - P_0| <= K eps sum_k max|p_k|`.
//! - angular momentum `L = sum q_k x p_k`: a drift `q_k += tau p_k / m_k` changes
//!   `q_k x p_k` by the rounding of `q_k` only, a kick `p_k += tau f_k` by the rounding of
//!   `p_k` (the torques `q_k x f_k` of central pair forces cancel up to rounding). Each
//!   sub-flow moves `L` by at most about `2 eps sum_k |q_k| |p_k|` (two products per
//!   component), so after `K` sub-flows `|L - L_0| <= 2 K eps sum_k max(|q_k| |p_k|)`.
//!
//! A method that does not conserve `L` (RK4) exceeds that bound by orders of magnitude.

use nalgebra::DVector;
use stormer::models::NBody;
use stormer::stepper::ImplicitOptions;
use stormer::{Driver, Method, Stepper};
use stormer_app::scenes::{self, AnyScene, Setup};

type Scene = Setup<NBody<f64, DVector<f64>>>;

/// The outer solar system file as a user extends it: Neptune and Pluto added from
/// Hairer, Lubich, Wanner, GNI section I.2.4.
pub fn with_neptune_and_pluto() -> String {
    let text = scenes::builtin("outer-solar-system").unwrap().text;
    let bodies = "[[bodies]]\nname = \"Neptune\"\nmass = 0.0000517759138449\n\
                  position = [11.4707666, -25.7294829, -10.8169456]\n\
                  velocity = [0.00288930, 0.00114527, 0.00039677]\n\n\
                  [[bodies]]\nname = \"Pluto\"\nmass = 7.692307692307693e-9  # 1 / 1.3e8\n\
                  position = [-15.5387357, -25.2225594, -3.1902382]\n\
                  velocity = [0.00276725, -0.00170702, -0.00136504]\n\n[run]";
    text.replacen("[run]", bodies, 1)
}

fn nbody(scene: AnyScene) -> Scene {
    match scene {
        AnyScene::NBody(s) => s,
        other => panic!("{} is not an n-body scene", other.name()),
    }
}

/// Worst drifts of total momentum and angular momentum over a run, each divided by its
/// round-off bound (`<= 1` means conserved to round-off), and the sub-flow count.
struct Drift {
    momentum: f64,
    angular: f64,
}

fn run(scene: &Scene, method: &str, steps: u64) -> Drift {
    let y0 = &scene.y0;
    let model = &scene.model;
    let resolved = Method::named(method).unwrap();
    let stepper = resolved.stepper_for(model, y0, &ImplicitOptions::default());
    let (mut stepper, kicks, subflows): (Box<dyn Stepper<_>>, u64, u64) = match resolved {
        Method::Splitting(d) => {
            let kicks = d
                .word()
                .iter()
                .filter(|op| op.flow == stormer::verify::conditions::splitting::Flow::Kick)
                .count();
            (stepper.unwrap(), kicks as u64, d.word().len() as u64)
        }
        Method::Tableau(d) => (stepper.unwrap(), d.stages as u64, d.stages as u64),
        other => panic!("{} is not a catalog method", other.name()),
    };
    let sol = Driver::fixed(scene.run.dt)
        .run(model, &mut stepper, 0.0, y0, scene.run.dt * steps as f64)
        .unwrap();
    let (p0, l0) = (model.total_momentum(y0), model.angular_momentum(y0));
    let d = model.dim();
    let (mut p_scale, mut l_scale) = (0.0f64, 0.0f64);
    let (mut dp, mut dl) = (0.0f64, 0.0f64);
    for y in &sol.y {
        let (q, p) = y.as_slice().split_at(y.len() / 2);
        let sum_p: f64 = p.iter().map(|x| x.abs()).sum();
        let sum_qp: f64 = q
            .chunks(d)
            .zip(p.chunks(d))
            .map(|(q, p)| q.iter().map(|x| x * x).sum::<f64>().sqrt() * p.iter().map(|x| x * x).sum::<f64>().sqrt())
            .sum();
        p_scale = p_scale.max(sum_p);
        l_scale = l_scale.max(sum_qp);
        for (a, b) in model.total_momentum(y).iter().zip(&p0) {
            dp = dp.max((a - b).abs());
        }
        for (a, b) in model.angular_momentum(y).iter().zip(&l0) {
            dl = dl.max((a - b).abs());
        }
    }
    let eps = f64::EPSILON;
    let momentum_bound = (steps * kicks) as f64 * eps * p_scale;
    let angular_bound = 2.0 * (steps * subflows) as f64 * eps * l_scale;
    eprintln!(
        "{:<20} {method:<20} {steps} steps: |dP| {dp:.2e} ({:.1e} of bound), |dL| {dl:.2e} ({:.1e} of bound)",
        scene.name,
        dp / momentum_bound,
        dl / angular_bound
    );
    Drift {
        momentum: dp / momentum_bound,
        angular: dl / angular_bound,
    }
}

/// Each of `methods` conserves both to round-off over `steps` steps of the scene.
fn assert_conserved(scene: &Scene, methods: &[&str], steps: u64) {
    for method in methods {
        let drift = run(scene, method, steps);
        assert!(drift.momentum <= 1.0 && drift.angular <= 1.0, "{method}");
    }
}

#[test]
fn splittings_conserve_momentum_and_angular_momentum_in_the_outer_solar_system() {
    let scene = nbody(scenes::load("outer-solar-system").unwrap());
    // 10 000 steps of 10 days: 100 000 days, about 8 Saturn orbits
    assert_conserved(
        &scene,
        &[
            "velocity_verlet_kdk",
            "stormer_verlet_dkd",
            "triple_jump4",
            "blanes_moan_srkn11b",
        ],
        10_000,
    );
}

#[test]
fn neptune_and_pluto_added_by_editing_the_file() {
    let text = with_neptune_and_pluto();
    let scene = nbody(scenes::parse(&text, "outer-solar-system-6.toml", "outer-solar-system-6").unwrap());
    assert_eq!(
        scene.model.names(),
        ["Sun", "Jupiter", "Saturn", "Uranus", "Neptune", "Pluto"]
    );
    assert_eq!(scene.y0.len(), 36);
    assert_conserved(&scene, &["velocity_verlet_kdk", "triple_jump4"], 5_000);
}

#[test]
fn the_kepler_scene_conserves_them_too() {
    let scene = nbody(scenes::load("kepler").unwrap());
    // 10 000 steps of 0.01 years: 43 orbits
    assert_conserved(&scene, &["velocity_verlet_kdk", "kahan_li6"], 10_000);
}

#[test]
fn rk4_keeps_the_momentum_but_not_the_angular_momentum() {
    // negative control: the bound is tight enough to see a method that does not conserve L
    let scene = nbody(scenes::load("kepler").unwrap());
    let drift = run(&scene, "rk4", 10_000);
    assert!(
        drift.momentum <= 1.0,
        "a linear invariant: every Runge-Kutta method keeps it"
    );
    assert!(
        drift.angular > 100.0,
        "RK4 does not conserve angular momentum: {}",
        drift.angular
    );
}
