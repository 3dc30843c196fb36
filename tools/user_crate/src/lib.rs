//! Problems of a newcomer's crate, for the build-time measurements of docs/build-shape.md.
use stormer::SecondOrder;
use stormer::hamiltonian::Hamiltonian;

macro_rules! second_order {
    ($name:ident, $k:expr) => {
        pub struct $name;
        impl SecondOrder for $name {
            type Scalar = f64;
            type State = [f64; 2];
            fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
                a[0] = -$k * q[0].sin();
            }
        }
    };
}
second_order!(Pendulum, 1.0);
second_order!(Pendulum2, 2.0);
second_order!(Pendulum3, 3.0);
second_order!(Pendulum4, 4.0);

/// Henon-Heiles as a separable Hamiltonian.
pub struct HenonHeiles;
impl Hamiltonian for HenonHeiles {
    type Scalar = f64;
    type State = [f64; 4];
    fn force(&self, _t: f64, q: &[f64], f: &mut [f64]) {
        f[0] = -q[0] - 2.0 * q[0] * q[1];
        f[1] = -q[1] - q[0] * q[0] + q[1] * q[1];
    }
}
