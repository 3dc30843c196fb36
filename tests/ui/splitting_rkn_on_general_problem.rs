// A method built for quadratic kinetic energies does not step a problem that is not
// `QuadraticKinetic`: the type system refuses it.
use stormer::Stepper;
use stormer::hamiltonian::Hamiltonian;
use stormer::stepper::SplittingStepper;

stormer::splitting! {
    pub struct RknOnly {
        name: "rkn_only",
        order: 2,
        drift: [0, 1],
        kick: [1/2, 1/2],
        quadratic_kinetic: true,
    }
}

struct Relativistic;
impl Hamiltonian for Relativistic {
    type Scalar = f64;
    type State = [f64; 2];
    fn kinetic_gradient(&self, p: &[f64], v: &mut [f64]) {
        v[0] = p[0] / (1.0 + p[0] * p[0]).sqrt();
    }
    fn force(&self, _t: f64, q: &[f64], f: &mut [f64]) {
        f[0] = -q[0];
    }
}

fn main() {
    let mut s = SplittingStepper::<RknOnly, [f64; 2]>::new(&[1.0, 0.0]).unwrap();
    let mut y = [0.0; 2];
    s.step(&Relativistic, 0.0, 0.1, &[1.0, 0.0], &mut y).unwrap();
}
