//! Charged particles in electric and magnetic fields (docs/scenes.md 5-6): the model behind the
//! `charged-particles` scenes (`coulomb-magnetic`, `cyclotron`, `exb-drift`,
//! `penning-trap`, `magnetic-bottle`).

use super::{ExternalFields, MagneticField};
use crate::hamiltonian::{halves, halves_mut};
use crate::magnetic::{cross, Gyration, Lorentz};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::verify::Structure;
use crate::{Error, Real, State};
use core::marker::PhantomData;
use nalgebra::{DMatrix, DVector};

/// Charged particles in 3-D (docs/scenes.md 5-6), each with its mass `m_k` and charge `c_k`
/// (ratio `r_k = c_k / m_k`), in a magnetic field ([`MagneticField`]) and optionally:
///
/// - a uniform electric field `E`: acceleration `r_k E`, potential energy `-c_k E . q_k`;
/// - an attracting Coulomb centre at the origin: potential energy `-mu c_k / |q_k|`
///   (docs/scenes.md 5's `V = -1/|q|` for `mu = 1` and a unit charge);
/// - a quadrupole electric potential (the Penning trap's, axis 3):
///   `phi = (k/2) (z^2 - (x^2 + y^2)/2)`, potential energy `c_k phi(q_k)`, which confines
///   along the axis (frequency `sqrt(r k)`) and pushes outwards across it, where the
///   magnetic field confines when `(r B)^2 > 2 r k`;
/// - Coulomb interaction between the particles, each pair once: potential energy
///   `kappa c_k c_l / |q_k - q_l|` (repulsion between like charges).
///
/// States are `(q, v)`: the `3N` positions, particle after particle, then the `3N`
/// velocities. The model is a [`Lorentz`] model: wrapped in [`crate::magnetic::Charged`]
/// it runs with every Runge-Kutta method (first-order form), every general splitting and
/// composition (the drift is the exact gyration, so velocity Verlet is the magnetic Verlet)
/// and the charged-particle steppers ([`crate::stepper::ParticleMethod`]). The energy
/// `sum m_k |v_k|^2/2 + potential` is conserved (the magnetic force does no work).
///
/// Generic over the scalar and the state: `[f64; 6]` for one particle in a benchmark,
/// `DVector<f64>` for a scene file, dual numbers for the verification's Jacobians.
///
/// ```
/// use stormer::magnetic::Charged;
/// use stormer::models::{ChargedParticles, MagneticField};
/// use stormer::{Driver, Method, Problem};
/// // docs/scenes.md 5: unit charge and mass, Coulomb centre, field along axis 3 of strength 1
/// let model = ChargedParticles::<f64, [f64; 6]>::new(&[1.0], &[1.0])
///     .unwrap()
///     .with_field(MagneticField::Uniform([0.0, 0.0, 1.0]))
///     .with_centre(1.0);
/// let y0 = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0];
/// let problem = Charged(model);
/// assert_eq!(problem.energy(0.0, &y0), Some(-1.0 / 3f64.sqrt()));
/// let mut verlet = Method::named("velocity_verlet_kdk")?.stepper_for(&problem, &y0, &Default::default())?;
/// let sol = Driver::fixed(0.01).every(10).run(&problem, &mut verlet, 0.0, &y0, 10.0)?;
/// let worst = sol.energy.iter().map(|e| (e - sol.energy[0]).abs()).fold(0.0, f64::max);
/// assert!(worst < 2e-4);
/// # Ok::<(), stormer::Error>(())
/// ```
pub struct ChargedParticles<T, S> {
    names: Vec<String>,
    masses: Vec<T>,
    charges: Vec<T>,
    ratios: Vec<T>,
    field: MagneticField<T>,
    /// The uniform electric field (zero when there is none).
    electric: [T; 3],
    centre: Option<T>,
    quadrupole: Option<T>,
    interaction: Option<T>,
    state: PhantomData<fn() -> S>,
}

impl<T: Real, S> Clone for ChargedParticles<T, S> {
    fn clone(&self) -> Self {
        ChargedParticles {
            names: self.names.clone(),
            masses: self.masses.clone(),
            charges: self.charges.clone(),
            ratios: self.ratios.clone(),
            field: self.field,
            electric: self.electric,
            centre: self.centre,
            quadrupole: self.quadrupole,
            interaction: self.interaction,
            state: PhantomData,
        }
    }
}

impl<T: Real, S> core::fmt::Debug for ChargedParticles<T, S> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("ChargedParticles")
            .field("names", &self.names)
            .field("masses", &self.masses)
            .field("charges", &self.charges)
            .field("field", &self.field)
            .field("electric", &self.electric)
            .field("centre", &self.centre)
            .field("quadrupole", &self.quadrupole)
            .field("interaction", &self.interaction)
            .finish()
    }
}

#[inline(always)]
fn norm2<T: Real>(x: &[T]) -> T {
    x[0] * x[0] + x[1] * x[1] + x[2] * x[2]
}

/// `q_k - q_l`, the separation of particles `k` and `l` in 3-D.
#[inline(always)]
fn separation<T: Real>(q: &[T], k: usize, l: usize) -> [T; 3] {
    [
        q[3 * k] - q[3 * l],
        q[3 * k + 1] - q[3 * l + 1],
        q[3 * k + 2] - q[3 * l + 2],
    ]
}

/// Writes `particles` particles in 3-D at `positions` into the first half of `y` and the
/// `rates` (velocities or momenta, `name` in the error) into the second half, `3N` values
/// each: the states of both charged-particle models.
pub(super) fn write_particles<T: Real, S: State<Scalar = T>>(
    particles: usize,
    positions: &[T],
    (rates, name): (&[T], &str),
    y: &mut S,
) -> Result<(), Error> {
    let len = 3 * particles;
    if positions.len() != len || rates.len() != len || y.dim() != 2 * len {
        return Err(Error::invalid(
            "state",
            format!(
                "{particles} particles need {len} positions, {len} {name} and a state of {}, got {}, {} and {}",
                2 * len,
                positions.len(),
                rates.len(),
                y.dim()
            ),
        ));
    }
    let (q, v) = y.as_mut_slice().split_at_mut(len);
    q.copy_from_slice(positions);
    v.copy_from_slice(rates);
    Ok(())
}

#[inline(always)]
fn dot<T: Real>(x: &[T], y: &[T]) -> T {
    x[0] * y[0] + x[1] * y[1] + x[2] * y[2]
}

impl<T: Real, S: State<Scalar = T>> ChargedParticles<T, S> {
    /// Particles of the given masses (finite, `> 0`) and charges (finite), named `p0`,
    /// `p1`, ..., in no field.
    pub fn new(masses: &[T], charges: &[T]) -> Result<Self, Error> {
        if masses.is_empty() || masses.len() != charges.len() {
            return Err(Error::invalid(
                "particles",
                format!(
                    "there must be at least one particle and one charge per mass, got {} masses and {} charges",
                    masses.len(),
                    charges.len()
                ),
            ));
        }
        if let Some(k) = masses.iter().position(|&m| !(m.is_finite() && m > T::zero())) {
            return Err(Error::invalid(
                format!("mass of particle {k}"),
                format!("must be a finite number > 0, got {}", to_f64(masses[k])),
            ));
        }
        if let Some(k) = charges.iter().position(|&c| !c.is_finite()) {
            return Err(Error::invalid(
                format!("charge of particle {k}"),
                format!("must be a finite number, got {}", to_f64(charges[k])),
            ));
        }
        Ok(ChargedParticles {
            names: (0..masses.len()).map(|k| format!("p{k}")).collect(),
            masses: masses.to_vec(),
            charges: charges.to_vec(),
            ratios: masses.iter().zip(charges).map(|(&m, &c)| c / m).collect(),
            field: MagneticField::None,
            electric: [T::zero(); 3],
            centre: None,
            quadrupole: None,
            interaction: None,
            state: PhantomData,
        })
    }

    /// The same particles with names (one per particle; they name the CSV columns).
    pub fn with_names(mut self, names: Vec<String>) -> Result<Self, Error> {
        self.names = super::one_name_each(names, self.masses.len(), "particles")?;
        Ok(self)
    }

    /// In the magnetic field `field`.
    pub fn with_field(mut self, field: MagneticField<T>) -> Self {
        self.field = field;
        self
    }

    /// In the uniform electric field `e`.
    pub fn with_electric_field(mut self, e: [T; 3]) -> Self {
        self.electric = e;
        self
    }

    /// Around an attracting Coulomb centre at the origin: potential energy `-mu c_k/|q_k|`.
    pub fn with_centre(mut self, mu: T) -> Self {
        self.centre = Some(mu);
        self
    }

    /// In the quadrupole potential `phi = (k/2) (z^2 - (x^2 + y^2)/2)` (a Penning trap).
    pub fn with_quadrupole(mut self, k: T) -> Self {
        self.quadrupole = Some(k);
        self
    }

    /// With Coulomb interaction between the particles: `kappa c_k c_l / |q_k - q_l|`.
    pub fn with_interaction(mut self, kappa: T) -> Self {
        self.interaction = Some(kappa);
        self
    }

    /// Number of particles.
    pub fn particles(&self) -> usize {
        self.masses.len()
    }

    /// The names of the particles.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The masses.
    pub fn masses(&self) -> &[T] {
        &self.masses
    }

    /// The charges.
    pub fn charges(&self) -> &[T] {
        &self.charges
    }

    /// The charge-to-mass ratios.
    pub fn ratios(&self) -> &[T] {
        &self.ratios
    }

    /// The magnetic field.
    pub fn field(&self) -> MagneticField<T> {
        self.field
    }

    /// The uniform electric field (zero when there is none).
    pub fn electric_field(&self) -> [T; 3] {
        self.electric
    }

    /// The Coulomb centre's `mu`, if there is one.
    pub fn centre(&self) -> Option<T> {
        self.centre
    }

    /// The quadrupole's `k`, if there is one.
    pub fn quadrupole(&self) -> Option<T> {
        self.quadrupole
    }

    /// The interaction constant `kappa`, if the particles interact.
    pub fn interaction(&self) -> Option<T> {
        self.interaction
    }

    /// The same model at another scalar and state type (values converted through `f64`):
    /// a scene file's model on a static state for speed, or on dual numbers for a Jacobian.
    pub fn converted<U: Real, S2: State<Scalar = U>>(&self) -> ChargedParticles<U, S2> {
        let c = |x: T| lit::<U>(to_f64(x));
        ChargedParticles {
            names: self.names.clone(),
            masses: self.masses.iter().map(|&x| c(x)).collect(),
            charges: self.charges.iter().map(|&x| c(x)).collect(),
            ratios: self.ratios.iter().map(|&x| c(x)).collect(),
            field: self.field.map(c),
            electric: self.electric.map(c),
            centre: self.centre.map(c),
            quadrupole: self.quadrupole.map(c),
            interaction: self.interaction.map(c),
            state: PhantomData,
        }
    }

    /// Writes the particles at `positions` moving at `velocities` (`3N` values each,
    /// particle by particle) into `y`.
    pub fn set_state(&self, positions: &[T], velocities: &[T], y: &mut S) -> Result<(), Error> {
        write_particles(self.masses.len(), positions, (velocities, "velocities"), y)
    }

    /// True when the particles move independently in uniform fields (no centre, no
    /// quadrupole, no interaction, no bottle): the motion is then known in closed form.
    pub fn has_exact_solution(&self) -> bool {
        self.field.is_uniform()
            && self.centre.is_none()
            && self.quadrupole.is_none()
            && (self.interaction.is_none() || self.masses.len() == 1)
    }

    /// The state at time `t` after `y0` when [`Self::has_exact_solution`]: each particle
    /// gyrates about a guiding centre that moves with the drift velocity
    /// `u = omega x a / |omega|^2` (`a = r E`: the E x B drift `E x B / |B|^2`) and
    /// accelerates with `a`'s component along `omega`:
    ///
    /// ```text
    /// v(t) = u + a_par t + exp(Omega t) (v0 - u)
    /// q(t) = q0 + u t + a_par t^2/2 + F(t) (v0 - u)
    /// ```
    ///
    /// with the exact gyration's `exp(Omega t)` and `F(t)` ([`Gyration`]).
    pub fn exact_state(&self, y0: &S, t: T) -> Option<S> {
        if !self.has_exact_solution() {
            return None;
        }
        let mut y = y0.clone();
        let (q, v) = halves_mut(y.as_mut_slice());
        let half = lit::<T>(0.5);
        for (k, (qk, vk)) in q.chunks_exact_mut(3).zip(v.chunks_exact_mut(3)).enumerate() {
            let r = self.ratios[k];
            let omega = match self.field {
                MagneticField::Uniform(w) => w.map(|x| r * x),
                _ => [T::zero(); 3],
            };
            let a = self.electric.map(|e| r * e);
            let w2 = norm2(&omega);
            let (parallel, u) = if w2 > T::zero() {
                let s = dot(&a, &omega) / w2;
                let u = cross(&omega, &a).map(|x| x / w2);
                (omega.map(|x| s * x), u)
            } else {
                (a, [T::zero(); 3])
            };
            let mut gyrating = [vk[0] - u[0], vk[1] - u[1], vk[2] - u[2]];
            Gyration::new(omega, t).apply(qk, &mut gyrating);
            for i in 0..3 {
                qk[i] += u[i] * t + half * parallel[i] * t * t;
                vk[i] = gyrating[i] + u[i] + parallel[i] * t;
            }
        }
        Some(y)
    }
}

impl<T: Real, S: State<Scalar = T>> Lorentz for ChargedParticles<T, S> {
    type Scalar = T;
    type State = S;

    /// `r_k` times the unit-ratio rotation vector; in a bottle or a dipole, `-r_k B(q_k)`.
    #[inline(always)]
    fn omega(&self, particle: usize, q: &[T]) -> [T; 3] {
        ExternalFields::new(&self.ratios, self.electric, self.field).omega(particle, &q[3 * particle..3 * particle + 3])
    }

    fn uniform(&self) -> bool {
        self.field.is_uniform()
    }

    /// The fields, when each particle feels only them (no centre, no quadrupole, no
    /// interaction): Boris then pushes the particles independently, in parallel.
    fn external_fields(&self) -> Option<ExternalFields<'_, T>> {
        let alone = self.centre.is_none() && self.quadrupole.is_none() && self.interaction.is_none();
        alone.then(|| ExternalFields::new(&self.ratios, self.electric, self.field))
    }

    #[inline]
    fn acceleration(&self, _t: T, q: &[T], a: &mut [T]) {
        let half = lit::<T>(0.5);
        for ((ak, qk), &r) in a.chunks_exact_mut(3).zip(q.chunks_exact(3)).zip(&self.ratios) {
            let mut f = self.electric;
            if let Some(mu) = self.centre {
                let r2 = norm2(qk);
                let s = mu / (r2 * r2.sqrt());
                for i in 0..3 {
                    f[i] -= s * qk[i];
                }
            }
            if let Some(k) = self.quadrupole {
                f[0] += k * half * qk[0];
                f[1] += k * half * qk[1];
                f[2] -= k * qk[2];
            }
            for i in 0..3 {
                ak[i] = r * f[i];
            }
        }
        if let Some(kappa) = self.interaction {
            let n = self.masses.len();
            for k in 0..n {
                for l in k + 1..n {
                    let d = separation(q, k, l);
                    let r2 = norm2(&d);
                    let s = kappa * self.charges[k] * self.charges[l] / (r2 * r2.sqrt());
                    let (sk, sl) = (s / self.masses[k], s / self.masses[l]);
                    for i in 0..3 {
                        a[3 * k + i] += sk * d[i];
                        a[3 * l + i] -= sl * d[i];
                    }
                }
            }
        }
    }

    fn energy(&self, _t: T, q: &[T], v: &[T]) -> Option<T> {
        let half = lit::<T>(0.5);
        let mut e = T::zero();
        for (k, (qk, vk)) in q.chunks_exact(3).zip(v.chunks_exact(3)).enumerate() {
            let c = self.charges[k];
            let mut phi = -dot(&self.electric, qk);
            if let Some(mu) = self.centre {
                phi -= mu / norm2(qk).sqrt();
            }
            if let Some(kq) = self.quadrupole {
                phi += half * kq * (qk[2] * qk[2] - half * (qk[0] * qk[0] + qk[1] * qk[1]));
            }
            e += half * self.masses[k] * norm2(vk) + c * phi;
        }
        if let Some(kappa) = self.interaction {
            let n = self.masses.len();
            for k in 0..n {
                for l in k + 1..n {
                    let d = separation(q, k, l);
                    e += kappa * self.charges[k] * self.charges[l] / norm2(&d).sqrt();
                }
            }
        }
        Some(e)
    }
}

/// The two-form of charged particles in `(q, v)` coordinates, which the exact flow
/// preserves: `sum_k m_k (dq_k ^ dv_k + (1/2) eps_ijl omega_kl dq_ki ^ dq_kj)`, i.e. per
/// particle the blocks `S = [[m K, m I], [-m I, 0]]` with `K_ij = eps_ijl omega_l`
/// (`omega` of the particle at `y`'s positions: constant for a uniform field).
///
/// For a uniform field, the magnetic Verlet and every composition over it preserve it
/// (`tests/methods/verification/structure.rs`); Boris preserves the phase-space volume but not
/// this form.
///
/// ```
/// use stormer::models::{ChargedParticles, MagneticField};
/// use stormer::verify::Structure;
/// let model = ChargedParticles::<f64, [f64; 6]>::new(&[2.0], &[1.0])
///     .unwrap()
///     .with_field(MagneticField::Uniform([0.0, 0.0, 1.0]));
/// let s = model.matrix(&[0.0f64; 6]);
/// // m K: K_01 = omega_z = 1, times r = 1/2, times m = 2
/// assert_eq!((s[(0, 1)], s[(1, 0)], s[(0, 3)], s[(3, 0)]), (1.0, -1.0, 2.0, -2.0));
/// ```
impl<T: Real, S: State<Scalar = T>> Structure for ChargedParticles<T, S> {
    fn matrix<U: Real>(&self, y: &[U]) -> DMatrix<U> {
        let model = self.converted::<U, DVector<U>>();
        let n = y.len() / 2;
        let (q, _) = halves(y);
        let mut s = DMatrix::from_element(2 * n, 2 * n, U::zero());
        for k in 0..n / 3 {
            let m = model.masses[k];
            let [w1, w2, w3] = model.omega(k, q);
            let kk = [[U::zero(), w3, -w2], [-w3, U::zero(), w1], [w2, -w1, U::zero()]];
            for i in 0..3 {
                for j in 0..3 {
                    s[(3 * k + i, 3 * k + j)] = m * kk[i][j];
                }
                s[(3 * k + i, n + 3 * k + i)] = m;
                s[(n + 3 * k + i, 3 * k + i)] = -m;
            }
        }
        s
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // exact values compared exactly
mod tests {
    use super::*;
    use crate::catalog::Dop853;
    use crate::magnetic::Charged;
    use crate::stepper::ExplicitRk;
    use crate::{Driver, Problem};

    /// Two ions in a Penning trap with interaction, plus a uniform E along the axis.
    fn trap() -> ChargedParticles<f64, [f64; 12]> {
        ChargedParticles::new(&[1.0, 2.0], &[1.0, 3.0])
            .unwrap()
            .with_field(MagneticField::uniform_b([0.0, 0.0, 4.0]))
            .with_quadrupole(1.5)
            .with_interaction(0.7)
            .with_centre(0.3)
            .with_electric_field([0.0, 0.0, 0.1])
    }

    /// The acceleration is minus the gradient of the potential energy divided by the mass
    /// (central differences), and the magnetic force does no work.
    #[test]
    fn forces_derive_from_the_energy() {
        let model = trap();
        let y = [0.3, -0.2, 0.5, -0.4, 0.1, -0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let mut a = [0.0; 6];
        model.acceleration(0.0, &y[..6], &mut a);
        for j in 0..6 {
            let (mut up, mut down) = (y, y);
            let d = 1e-6;
            up[j] += d;
            down[j] -= d;
            let grad = (model.energy(0.0, &up[..6], &up[6..]).unwrap()
                - model.energy(0.0, &down[..6], &down[6..]).unwrap())
                / (2.0 * d);
            let m = model.masses()[j / 3];
            assert!(
                (a[j] + grad / m).abs() < 1e-8,
                "component {j}: {} vs {}",
                a[j],
                -grad / m
            );
        }
        // omega x v . v = 0: the energy rate is the power of the electric forces only
        let p = Charged(model.clone());
        let y = [0.3, -0.2, 0.5, -0.4, 0.1, -0.3, 1.0, 2.0, -1.0, 0.5, 0.2, 0.1];
        let mut dy = [0.0; 12];
        p.rhs(0.0, &y, &mut dy);
        let d = 1e-5;
        let (mut ahead, mut behind) = (y, y);
        for i in 0..12 {
            ahead[i] += d * dy[i];
            behind[i] -= d * dy[i];
        }
        let rate = (p.energy(0.0, &ahead).unwrap() - p.energy(0.0, &behind).unwrap()) / (2.0 * d);
        assert!(rate.abs() < 1e-7, "dE/dt = {rate}");
    }

    /// The closed form in crossed fields (with a parallel part) follows DOP853.
    #[test]
    fn the_exact_solution_solves_the_equations() {
        let model = ChargedParticles::<f64, [f64; 12]>::new(&[1.0, 0.5], &[2.0, -1.0])
            .unwrap()
            .with_field(MagneticField::uniform_b([0.3, -0.4, 1.2]))
            .with_electric_field([0.5, 0.2, -0.1]);
        let y0 = [0.1, 0.2, 0.3, -1.0, 0.0, 2.0, 0.5, -0.5, 0.2, 0.0, 1.0, -0.3];
        let p = Charged(model.clone());
        let mut st = ExplicitRk::<Dop853, [f64; 12]>::new(&y0);
        let sol = Driver::fixed(1e-3).every(500).run(&p, &mut st, 0.0, &y0, 10.0).unwrap();
        let mut worst = 0.0f64;
        for (t, y) in sol.t.iter().zip(&sol.y) {
            let exact = model.exact_state(&y0, *t).unwrap();
            worst = y.iter().zip(&exact).fold(worst, |m, (a, b)| m.max((a - b).abs()));
        }
        assert!(worst < 1e-10, "{worst:e}");
        // and a neutral particle with no field falls freely
        let free = ChargedParticles::<f64, [f64; 6]>::new(&[1.0], &[0.0]).unwrap();
        assert_eq!(
            free.exact_state(&[0.0, 0.0, 0.0, 1.0, 2.0, 3.0], 2.0).unwrap(),
            [2.0, 4.0, 6.0, 1.0, 2.0, 3.0]
        );
        assert!(trap().exact_state(&[0.0; 12], 1.0).is_none());
    }

    #[test]
    fn bad_particles_are_refused() {
        type M = ChargedParticles<f64, [f64; 6]>;
        assert!(M::new(&[0.0], &[1.0])
            .unwrap_err()
            .to_string()
            .contains("mass of particle 0"));
        assert!(M::new(&[1.0], &[f64::NAN]).is_err());
        assert!(M::new(&[], &[]).is_err());
        assert!(M::new(&[1.0], &[1.0]).unwrap().with_names(vec![]).is_err());
    }
}
