//! Charged particles at speeds close to light, in external fields, not interacting: the
//! model of the relativistic particle-in-cell pushers (`boris_relativistic`, `vay`,
//! `higuera_cary`).

use super::charged_particles::write_particles;
use super::{ChargedParticles, ExternalFields, MagneticField};
use crate::hamiltonian::{halves, halves_mut};
use crate::magnetic::{cross, Gyration};
use crate::method::Families;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::to_f64;
use crate::{Error, Problem, Real, State};

/// `N` charged particles moving at relativistic speeds in a uniform electric field `E` and
/// a magnetic field `B` ([`MagneticField`]: uniform, a bottle, a dipole), with the speed
/// of light `c`.
///
/// The state is `(x, u)`: the `3N` positions, particle after particle, then the `3N`
/// momenta per unit mass `u = gamma v`, `gamma = sqrt(1 + |u|^2/c^2)`:
///
/// ```text
/// x' = u / gamma,     u' = r (E + u/gamma x B)       (r = charge / mass)
/// ```
///
/// It runs with the relativistic pushers ([`crate::stepper::RelativisticMethod`]) and with
/// every Runge-Kutta method; the non-relativistic pushers and the splittings are refused
/// ([`Families::relativistic_particles`]). The energy `sum m_k c^2 (gamma_k - 1) - c_k E . x_k` is
/// conserved (the magnetic force does no work).
///
/// ```
/// use stormer::models::{MagneticField, RelativisticParticles};
/// use stormer::{Driver, Method, Problem};
/// // an electron-like particle (r = -1) at gamma = 5 in B = (0, 0, 1), c = 1
/// let model = RelativisticParticles::<f64, [f64; 6]>::new(&[1.0], &[-1.0], 1.0)?
///     .with_field(MagneticField::uniform_b([0.0, 0.0, 1.0]));
/// let u = 24f64.sqrt(); // gamma = sqrt(1 + u^2) = 5
/// let y0 = [0.0, 0.0, 0.0, u, 0.0, 0.0];
/// let period = 2.0 * std::f64::consts::PI * 5.0; // 2 pi gamma / (r B)
/// let mut vay = Method::resolve("vay")?.stepper_for(&model, &y0, &Default::default())?;
/// let run = Driver::fixed(period / 1000.0).run(&model, &mut vay, 0.0, &y0, period)?;
/// let end = run.y.last().unwrap();
/// assert!(end[0].abs() < 1e-3 && end[1].abs() < 1e-3); // back after one slow turn (radius 4.9)
/// # Ok::<(), stormer::Error>(())
/// ```
pub struct RelativisticParticles<T, S> {
    /// The particles and fields, as in the non-relativistic model (with no centre, no
    /// quadrupole, no interaction): its checks, names and builders serve both.
    particles: ChargedParticles<T, S>,
    c: T,
}

impl<T: Real, S> Clone for RelativisticParticles<T, S> {
    fn clone(&self) -> Self {
        RelativisticParticles {
            particles: self.particles.clone(),
            c: self.c,
        }
    }
}

impl<T: Real, S: State<Scalar = T>> core::fmt::Debug for RelativisticParticles<T, S> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("RelativisticParticles")
            .field("particles", &self.particles.masses().len())
            .field("c", &self.c)
            .field("field", &self.particles.field())
            .field("electric", &self.particles.electric_field())
            .finish_non_exhaustive()
    }
}

/// `|x|^2` for a 3-vector.
#[inline(always)]
fn norm2<T: Real>(x: &[T]) -> T {
    x[0] * x[0] + x[1] * x[1] + x[2] * x[2]
}

impl<T: Real, S: State<Scalar = T>> RelativisticParticles<T, S> {
    /// Particles of the given masses (finite, `> 0`) and charges (finite), named `p0`,
    /// `p1`, ..., with the speed of light `c` (finite, `> 0`), in no field.
    pub fn new(masses: &[T], charges: &[T], c: T) -> Result<Self, Error> {
        if !(c.is_finite() && c > T::zero()) {
            return Err(Error::invalid(
                "speed of light c",
                format!("must be a finite number > 0, got {}", to_f64(c)),
            ));
        }
        let particles = ChargedParticles::new(masses, charges)?;
        Ok(RelativisticParticles { particles, c })
    }

    /// The same particles with names (one per particle; they name the CSV columns).
    pub fn with_names(self, names: Vec<String>) -> Result<Self, Error> {
        let particles = self.particles.with_names(names)?;
        Ok(RelativisticParticles { particles, ..self })
    }

    /// In the magnetic field `field`.
    pub fn with_field(self, field: MagneticField<T>) -> Self {
        let particles = self.particles.with_field(field);
        RelativisticParticles { particles, ..self }
    }

    /// In the uniform electric field `e`.
    pub fn with_electric_field(self, e: [T; 3]) -> Self {
        let particles = self.particles.with_electric_field(e);
        RelativisticParticles { particles, ..self }
    }

    /// Number of particles.
    pub fn particles(&self) -> usize {
        self.particles.particles()
    }

    /// The names of the particles.
    pub fn names(&self) -> &[String] {
        self.particles.names()
    }

    /// The masses.
    pub fn masses(&self) -> &[T] {
        self.particles.masses()
    }

    /// The charge-to-mass ratios.
    pub fn ratios(&self) -> &[T] {
        self.particles.ratios()
    }

    /// The speed of light.
    pub fn c(&self) -> T {
        self.c
    }

    /// The magnetic field.
    pub fn field(&self) -> MagneticField<T> {
        self.particles.field()
    }

    /// The uniform electric field (zero when there is none).
    pub fn electric_field(&self) -> [T; 3] {
        self.particles.electric_field()
    }

    /// The fields and ratios, as the pushers read them.
    pub fn fields(&self) -> ExternalFields<'_, T> {
        let p = &self.particles;
        ExternalFields::new(p.ratios(), p.electric_field(), p.field())
    }

    /// `gamma = sqrt(1 + |u|^2/c^2)` of a momentum per unit mass `u` (3 components).
    #[inline(always)]
    pub fn gamma(&self, u: &[T]) -> T {
        (T::one() + norm2(u) / (self.c * self.c)).sqrt()
    }

    /// Writes the particles at `positions` with momenta per unit mass `momenta`
    /// (`u = gamma v`; `3N` values each, particle by particle) into `y`.
    pub fn set_state(&self, positions: &[T], momenta: &[T], y: &mut S) -> Result<(), Error> {
        write_particles(self.particles(), positions, (momenta, "momenta"), y)
    }

    /// The state at time `t` after `y0` in a uniform magnetic field and no electric field:
    /// each particle keeps its `gamma` and gyrates with the angular frequency
    /// `r |B| / gamma` (the non-relativistic gyration of `(x, u/gamma)` with `omega / gamma`);
    /// `None` in any other field.
    pub fn exact_state(&self, y0: &S, t: T) -> Option<S> {
        if !self.field().is_uniform() || self.electric_field().iter().any(|&e| e != T::zero()) {
            return None;
        }
        let mut y = y0.clone();
        let (x, u) = halves_mut(y.as_mut_slice());
        for (k, (xk, uk)) in x.chunks_exact_mut(3).zip(u.chunks_exact_mut(3)).enumerate() {
            let g = self.gamma(uk);
            let omega = self.fields().omega(k, xk).map(|w| w / g);
            let mut v = [uk[0] / g, uk[1] / g, uk[2] / g];
            Gyration::new(omega, t).apply(xk, &mut v);
            for i in 0..3 {
                uk[i] = g * v[i];
            }
        }
        Some(y)
    }
}

impl<T: Real, S: State<Scalar = T>> Problem for RelativisticParticles<T, S> {
    type Scalar = T;
    type State = S;

    fn rhs(&self, _t: T, y: &S, dy: &mut S) {
        let (x, u) = halves(y.as_slice());
        let (dx, du) = halves_mut(dy.as_mut_slice());
        let fields = self.fields();
        for (k, (xk, uk)) in x.chunks_exact(3).zip(u.chunks_exact(3)).enumerate() {
            let g = self.gamma(uk);
            let v = [uk[0] / g, uk[1] / g, uk[2] / g];
            let r = fields.ratio(k);
            let force = cross(&v, &self.field().b(xk));
            let electric = self.electric_field();
            for i in 0..3 {
                dx[3 * k + i] = v[i];
                du[3 * k + i] = r * (electric[i] + force[i]);
            }
        }
    }

    /// `sum m_k c^2 (gamma_k - 1) - c_k E . x_k`.
    fn energy(&self, _t: T, y: &S) -> Option<T> {
        let (x, u) = halves(y.as_slice());
        let (masses, charges, electric) = (self.masses(), self.particles.charges(), self.electric_field());
        let mut e = T::zero();
        for (k, (xk, uk)) in x.chunks_exact(3).zip(u.chunks_exact(3)).enumerate() {
            // c^2 (gamma - 1) = |u|^2 / (gamma + 1), without cancellation at low speed
            let g = self.gamma(uk);
            let kinetic = masses[k] * norm2(uk) / (g + T::one());
            let potential = charges[k] * (electric[0] * xk[0] + electric[1] * xk[1] + electric[2] * xk[2]);
            e += kinetic - potential;
        }
        Some(e)
    }

    /// The relativistic pushers and the Runge-Kutta methods.
    fn families(&self) -> Families<Self>
    where
        Self: 'static,
    {
        Families::relativistic_particles()
    }
}
