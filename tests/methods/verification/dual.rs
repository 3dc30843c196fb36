//! Dual numbers through the implicit solvers: the iteration must converge the derivative
//! part too. Comparisons of dual numbers see the real part only, so a stopping rule on
//! `|update|` alone stops a fixed-point iteration at an equilibrium after one sweep (the
//! value's first update is exactly zero) with the derivative unconverged: the Jacobian of
//! implicit midpoint at the pendulum's rest state then had a defect of 4e-2 at h = 0.2.
//! The solvers measure updates with every part of the scalar (`real::magnitude`).

use num_dual::Dual64;
use stormer::real::lit;
use stormer::stepper::ImplicitOptions;
use stormer::verify::problems::Pendulum;
use stormer::verify::{defect_bound, jacobian_dual, symplectic_defect, Canonical, SYMPLECTIC_FACTOR};
use stormer::Method;
use stormer::Stepper;

#[test]
fn implicit_solvers_converge_the_derivative_at_and_near_equilibria() {
    let p = Pendulum::<Dual64>::new();
    for options in [ImplicitOptions::fixed_point(), ImplicitOptions::newton()] {
        for name in ["implicit_midpoint", "gauss_legendre4", "gauss_legendre6"] {
            for y in [[0.0, 0.0], [1e-9, 0.0], [1e-5, 1e-5], [1.0, 0.5]] {
                for h in [0.01, 0.2, 0.8] {
                    let yd: [Dual64; 2] = y.map(lit);
                    let method = Method::named(name).unwrap();
                    let mut stepper: Box<dyn Stepper<Pendulum<Dual64>>> =
                        method.stepper_for(&p, &yd, &options).unwrap();
                    let j = jacobian_dual(&mut stepper, &p, 0.0, h, &yd).unwrap();
                    let mut y1 = yd;
                    stepper.reset();
                    stepper.step(&p, lit(0.0), lit(h), &yd, &mut y1).unwrap();
                    let defect = symplectic_defect(&j, &Canonical, &y, &y1.map(|x| x.re));
                    assert!(
                        defect <= defect_bound(&j, SYMPLECTIC_FACTOR),
                        "{name} ({:?}) at y = {y:?}, h = {h}: defect {defect:e}",
                        options.solver
                    );
                }
            }
        }
    }
}
