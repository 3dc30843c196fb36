//! What each problem class admits, decided once per class by `Problem::families`, and the
//! sentence a refused method gets: the same in the library as on the command line.

use crate::support::problems;

use problems::{Decay, Oscillator};
use stormer::hamiltonian::Hamiltonian;
use stormer::magnetic::Charged;
use stormer::models::{ChargedParticles, MagneticField};
use stormer::stepper::ImplicitOptions;
use stormer::{Method, Problem};

/// `H = p^4/4 + q^2/2`: separable, but the kinetic energy is not quadratic.
struct QuarticKinetic;
impl Hamiltonian for QuarticKinetic {
    type Scalar = f64;
    type State = [f64; 2];
    fn kinetic_gradient(&self, p: &[f64], v: &mut [f64]) {
        v[0] = p[0] * p[0] * p[0];
    }
    fn force(&self, _t: f64, q: &[f64], f: &mut [f64]) {
        f[0] = -q[0];
    }
}

fn refusal<P: Problem + 'static>(problem: &P, y0: &P::State, method: &str) -> String {
    let method = Method::resolve(method).unwrap();
    match method.stepper_for(problem, y0, &ImplicitOptions::fixed_point()) {
        Ok(_) => panic!("{} was admitted", method.name()),
        Err(e) => e.to_string(),
    }
}

fn admitted<P: Problem + 'static>(problem: &P, y0: &P::State, method: &str) {
    let method = Method::resolve(method).unwrap();
    if let Err(e) = method.stepper_for(problem, y0, &ImplicitOptions::fixed_point()) {
        panic!("{} refused: {e}", method.name());
    }
}

#[test]
fn a_problem_that_declares_nothing_admits_runge_kutta_only() {
    admitted(&Decay, &[1.0], "rk4");
    admitted(&Decay, &[1.0], "gauss_legendre4");
    let message = refusal(&Decay, &[1.0], "velocity_verlet_kdk");
    assert!(message.contains("use a Runge-Kutta method instead"), "{message}");
    let message = refusal(&Decay, &[1.0], "boris");
    assert!(message.contains("it is a charged-particle method"), "{message}");
}

#[test]
fn a_second_order_problem_admits_every_splitting() {
    for name in ["velocity_verlet_kdk", "kahan_li6", "blanes_moan_srkn11b", "rk4"] {
        admitted(&Oscillator, &[1.0, 0.0], name);
    }
    assert!(refusal(&Oscillator, &[1.0, 0.0], "euler_cromer").contains("charged-particle"));
}

#[test]
fn a_non_quadratic_kinetic_energy_refuses_runge_kutta_nystrom_methods() {
    admitted(&QuarticKinetic, &[1.0, 0.0], "triple_jump4");
    let message = refusal(&QuarticKinetic, &[1.0, 0.0], "blanes_moan_srkn11b");
    assert!(message.contains("kinetic energy is quadratic in p"), "{message}");
    assert!(message.contains("use a general splitting or composition"), "{message}");
}

#[test]
fn a_non_uniform_magnetic_field_refuses_splittings_in_the_library_too() {
    // splittings used to run here at first order (magnetic moment off by 13%)
    let particle = |field| {
        Charged(
            ChargedParticles::<f64, [f64; 6]>::new(&[1.0], &[1.0])
                .unwrap()
                .with_field(field),
        )
    };
    let y0 = [0.1, 0.0, 0.0, 0.0, 1.0, 0.3];
    let bottle = particle(MagneticField::Bottle { b0: 1.0, length: 2.0 });
    let message = refusal(&bottle, &y0, "velocity_verlet_kdk");
    assert!(
        message.contains("the magnetic field of this problem is not uniform"),
        "{message}"
    );
    assert!(message.contains("use boris"), "{message}");
    admitted(&bottle, &y0, "boris");
    admitted(&bottle, &y0, "rk4");
    // in a uniform field the drift is the exact gyration: every general splitting runs
    let uniform = particle(MagneticField::Uniform([0.0, 0.0, 1.0]));
    for name in [
        "velocity_verlet_kdk",
        "kahan_li6",
        "boris",
        "boris_exact_phase",
        "dop853",
    ] {
        admitted(&uniform, &y0, name);
    }
    let message = refusal(&uniform, &y0, "blanes_moan_srkn11b");
    assert!(
        message.contains("quadratic in p and the drift a free flight"),
        "{message}"
    );
}
