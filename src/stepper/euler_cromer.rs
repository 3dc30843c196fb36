//! Euler-Cromer for charged particles: each velocity component is updated with the
//! components already updated, then the positions with the new velocities.

use super::particle_chunks::check_particles_in_3d;
use super::{Counters, ParticleMethod, Stepper};
use crate::hamiltonian::halves_mut;
use crate::magnetic::{Charged, Lorentz};
use crate::method::MethodInfo;
use crate::{Error, Real, State};

/// Euler-Cromer (semi-implicit Euler of the users' E x B study, docs/scenes.md 6):
///
/// ```text
/// for each particle and component i = 1, 2, 3:
///     v_i <- v_i + h (a_i(t_n, q_n) + (omega x v)_i)    (v already holds the new v_1 .. v_{i-1})
/// q_{n+1} = q_n + h v_{n+1}
/// ```
///
/// First order, explicit, one force evaluation per step. With the field along axis 3 it is
/// the textbook "update one velocity component, then use the new value for the other".
///
/// ```
/// use stormer::magnetic::{Charged, Lorentz};
/// use stormer::stepper::EulerCromer;
/// use stormer::Stepper;
/// struct Field;
/// impl Lorentz for Field {
///     type Scalar = f64;
///     type State = [f64; 6];
///     fn omega(&self, _k: usize, _q: &[f64]) -> [f64; 3] { [0.0, 0.0, 1.0] }
///     fn acceleration(&self, _t: f64, _q: &[f64], a: &mut [f64]) { a.fill(0.0); }
/// }
/// let y0 = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0];
/// let mut s = EulerCromer::new(&y0).unwrap();
/// let mut y = [0.0; 6];
/// s.step(&Charged(Field), 0.0, 0.1, &y0, &mut y).unwrap();
/// // v_x is unchanged (omega x v has no x part while v_y = 0), then v_y uses the new v_x
/// assert_eq!(&y[3..5], &[1.0, 0.1]);
/// ```
#[derive(Debug, Clone)]
pub struct EulerCromer<S> {
    work: S,
    counters: Counters,
}

impl<S: State> EulerCromer<S> {
    /// A stepper with buffers shaped like `y0 = (q, v)`, of length `6N`.
    pub fn new(y0: &S) -> Result<Self, Error> {
        check_particles_in_3d(ParticleMethod::EulerCromer.name(), "(q, v)", y0.dim())?;
        Ok(EulerCromer {
            work: y0.zeros_like(),
            counters: Counters::default(),
        })
    }
}

impl<T: Real, L: Lorentz<Scalar = T>> Stepper<Charged<L>> for EulerCromer<L::State> {
    fn info(&self) -> MethodInfo {
        ParticleMethod::EulerCromer.info()
    }

    fn step(&mut self, p: &Charged<L>, t: T, h: T, y: &L::State, y_new: &mut L::State) -> Result<(), Error> {
        y_new.copy_from(y);
        let (q, v) = halves_mut(y_new.as_mut_slice());
        let (_, a) = halves_mut(self.work.as_mut_slice());
        p.0.acceleration(t, q, a);
        self.counters.evaluations += 1;
        for k in 0..q.len() / 3 {
            let w = p.0.omega(k, q);
            let v = &mut v[3 * k..3 * k + 3];
            let a = &a[3 * k..3 * k + 3];
            v[0] += h * (a[0] + (w[1] * v[2] - w[2] * v[1]));
            v[1] += h * (a[1] + (w[2] * v[0] - w[0] * v[2]));
            v[2] += h * (a[2] + (w[0] * v[1] - w[1] * v[0]));
        }
        for (q, &v) in q.iter_mut().zip(v.iter()) {
            *q += h * v;
        }
        Ok(())
    }

    fn accept(&mut self) {}

    fn reset(&mut self) {}

    fn counters(&self) -> Counters {
        self.counters
    }
}
