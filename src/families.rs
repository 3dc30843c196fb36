//! Which families of methods a problem admits, declared once per problem class.
//!
//! Every problem runs the Runge-Kutta methods (they need only `rhs`). The other families
//! need structure: a splitting or composition needs drift and kick sub-flows
//! ([`Splittable`]), and reaches its order with a Runge-Kutta-Nystrom method only when the
//! kinetic energy is quadratic ([`QuadraticKinetic`]); a charged-particle pusher (Boris,
//! Euler-Cromer) needs a Lorentz-force problem ([`Charged`]), a relativistic pusher (Boris,
//! Vay, Higuera-Cary) relativistic particles ([`RelativisticParticles`]). A problem class says which
//! through [`Problem::families`](crate::Problem::families): every [`crate::SecondOrder`]
//! problem admits every splitting, every [`crate::hamiltonian::Hamiltonian`] the general ones, a
//! [`Charged`] problem the general ones and the pushers when its field is uniform and the
//! pushers only when it is not; any other problem only Runge-Kutta methods. The builder
//! ([`Method::stepper_for`](crate::Method::stepper_for)) reads the answer, so what a problem
//! admits is said in one place, with the sentence a user sees when a method is refused.

use crate::flows::{quadratic_kinetic_refused, QuadraticKinetic, Splittable};
use crate::magnetic::{Charged, Lorentz};
use crate::method::Splitting;
use crate::method::SplittingData;
use crate::models::RelativisticParticles;
use crate::stepper::RuntimeSplitting;
use crate::stepper::{ParticleMethod, RelativisticMethod};
use crate::{Error, Problem, Real, State, Stepper};

/// A splitting or composition to build: compiled into the crate (its generated stepper is
/// used) or held in memory (read from a file, or built with [`Splitting::splitting`]).
#[derive(Debug, Clone, Copy)]
pub enum SplittingSource<'a> {
    /// A catalog method.
    Compiled(&'static SplittingData),
    /// A method built at run time.
    Runtime(&'a Splitting),
}

impl SplittingSource<'_> {
    /// The method's name.
    pub fn name(&self) -> &str {
        match self {
            SplittingSource::Compiled(d) => d.name,
            SplittingSource::Runtime(s) => s.name(),
        }
    }

    /// True for a Runge-Kutta-Nystrom method, which needs a quadratic kinetic energy.
    pub fn requires_quadratic_kinetic(&self) -> bool {
        match self {
            SplittingSource::Compiled(d) => d.requires_quadratic_kinetic,
            SplittingSource::Runtime(s) => s.requires_quadratic_kinetic(),
        }
    }
}

/// Builds a splitting stepper for problem `P`.
type SplittingBuilder<P> = for<'a> fn(SplittingSource<'a>, &<P as Problem>::State) -> BuildResult<P>;
/// Builds a charged-particle pusher for problem `P`.
type ParticleBuilder<P> = fn(ParticleMethod, &<P as Problem>::State) -> BuildResult<P>;
/// Builds a relativistic pusher for problem `P`.
type RelativisticBuilder<P> = fn(RelativisticMethod, &<P as Problem>::State) -> BuildResult<P>;
type BuildResult<P> = Result<Box<dyn Stepper<P>>, Error>;

/// The families of methods a problem admits besides Runge-Kutta, and the reasons for the
/// ones it refuses.
///
/// ```
/// use stormer::{Method, Problem, SecondOrder};
/// use stormer::method::Families;
///
/// /// x'' = -x - 0.1 x': friction, so no drift and kick flows.
/// struct Damped;
/// impl Problem for Damped {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) { *dy = [y[1], -y[0] - 0.1 * y[1]]; }
///     fn families(&self) -> Families<Self> {
///         Families::runge_kutta_only("the oscillator has friction")
///     }
/// }
/// let y0 = [1.0, 0.0];
/// let verlet = Method::named("velocity_verlet_kdk").unwrap();
/// let refusal = verlet.stepper_for(&Damped, &y0, &Default::default()).err().unwrap();
/// assert!(refusal.to_string().contains("the oscillator has friction"));
/// assert!(Method::named("rk4").unwrap().stepper_for(&Damped, &y0, &Default::default()).is_ok());
/// ```
pub struct Families<P: Problem> {
    splitting: Result<SplittingBuilder<P>, String>,
    /// `Err(why)` when Runge-Kutta-Nystrom methods are refused (`None`: the problem does
    /// not declare a quadratic kinetic energy, [`quadratic_kinetic_refused`] says why).
    quadratic_kinetic: Result<(), Option<&'static str>>,
    particle: Result<ParticleBuilder<P>, String>,
    relativistic: Result<RelativisticBuilder<P>, String>,
}

impl<P: Problem> Families<P> {
    /// Runge-Kutta methods only; `why` says what the problem is that splittings do not
    /// apply (it ends the refusal's sentence: "...: `why`; use a Runge-Kutta method").
    pub fn runge_kutta_only(why: impl Into<String>) -> Self {
        Families {
            splitting: Err(why.into()),
            quadratic_kinetic: Err(None),
            particle: Err(NOT_CHARGED.into()),
            relativistic: Err(NOT_RELATIVISTIC.into()),
        }
    }

    /// What a problem that declares nothing admits: Runge-Kutta methods only.
    pub fn undeclared() -> Self {
        Self::runge_kutta_only(
            "the problem does not declare drift and kick sub-flows (it is not set up as a Hamiltonian or a \
             Lorentz-force problem)",
        )
    }

    /// Every general splitting and composition (the drift and kick of [`Splittable`]);
    /// Runge-Kutta-Nystrom methods are refused.
    pub fn general_splittings() -> Self
    where
        P: Splittable + 'static,
    {
        Families {
            splitting: Ok(general::<P>),
            quadratic_kinetic: Err(None),
            particle: Err(NOT_CHARGED.into()),
            relativistic: Err(NOT_RELATIVISTIC.into()),
        }
    }

    /// Every splitting and composition, Runge-Kutta-Nystrom ones included: the kinetic
    /// energy is quadratic in `p`.
    pub fn all_splittings() -> Self
    where
        P: QuadraticKinetic + 'static,
    {
        Families {
            splitting: Ok(quadratic::<P>),
            quadratic_kinetic: Ok(()),
            particle: Err(NOT_CHARGED.into()),
            relativistic: Err(NOT_RELATIVISTIC.into()),
        }
    }

    /// Whether this problem admits the splitting or composition `method`: `Ok`, or the
    /// sentence saying why not and what to use instead.
    pub fn admit_splitting(&self, method: SplittingSource<'_>) -> Result<(), Error> {
        self.splitting_builder(method).map(|_| ())
    }

    /// A stepper for the splitting or composition `method` (its run-time stepper, built
    /// from its data), or the sentence saying why this problem does not admit it and what
    /// to use instead.
    pub fn splitting(&self, method: SplittingSource<'_>, y0: &P::State) -> BuildResult<P> {
        self.splitting_builder(method)?(method, y0)
    }

    /// The builder of `method`'s stepper, or the refusal.
    fn splitting_builder(&self, method: SplittingSource<'_>) -> Result<SplittingBuilder<P>, Error> {
        let build = *self.splitting.as_ref().map_err(|why| Error::Unsupported {
            name: method.name().to_string(),
            reason: format!("{why}; use a Runge-Kutta method instead, such as rk4 or dop853"),
        })?;
        if let (true, Err(why)) = (method.requires_quadratic_kinetic(), self.quadratic_kinetic) {
            return Err(match why {
                None => quadratic_kinetic_refused(method.name()),
                Some(why) => Error::Unsupported {
                    name: method.name().to_string(),
                    reason: why.into(),
                },
            });
        }
        Ok(build)
    }

    /// A charged-particle pusher, or the sentence saying why it does not apply.
    pub fn particle(&self, method: ParticleMethod, y0: &P::State) -> BuildResult<P> {
        admitted(&self.particle, method.name())?(method, y0)
    }

    /// A relativistic pusher, or the sentence saying why it does not apply.
    pub fn relativistic(&self, method: RelativisticMethod, y0: &P::State) -> BuildResult<P> {
        admitted(&self.relativistic, method.name())?(method, y0)
    }
}

/// The builder of a family of pushers, or, for the method `name`, the sentence saying why
/// the problem refuses the family.
fn admitted<B: Copy>(family: &Result<B, String>, name: &str) -> Result<B, Error> {
    family.as_ref().copied().map_err(|why| Error::Unsupported {
        name: name.to_string(),
        reason: why.clone(),
    })
}

const NOT_CHARGED: &str = "it is a charged-particle method, for Lorentz-force problems (charged particles in a \
                           magnetic field), not for this problem; use a Runge-Kutta method or a splitting";

const NOT_RELATIVISTIC: &str = "it is a relativistic pusher, for relativistic charged particles (state x, u = gamma v, with a \
                                speed of light c: a scene of model \"relativistic-particles\"), not for this problem; use \
                                a Runge-Kutta method or a splitting";

impl<T: Real, S: State<Scalar = T> + 'static> Families<RelativisticParticles<T, S>> {
    /// Relativistic charged particles: the relativistic pushers (and every Runge-Kutta
    /// method); the non-relativistic pushers and the splittings are refused, each with the
    /// sentence saying why.
    pub fn relativistic_particles() -> Self {
        Families {
            splitting: Err(
                "the particles are relativistic (state x, u = gamma v): the drift and kick of the \
                            splittings are those of non-relativistic particles; use boris_relativistic, vay or \
                            higuera_cary"
                    .into(),
            ),
            quadratic_kinetic: Err(None),
            particle: Err(
                "it is a non-relativistic pusher (state q, v, speeds unbounded), and the particles of \
                           this scene are relativistic (state x, u = gamma v, speed of light c); use \
                           boris_relativistic, vay or higuera_cary"
                    .into(),
            ),
            relativistic: Ok(|method, y0| method.stepper::<T, S>(y0)),
        }
    }
}

impl<L: Lorentz + 'static> Families<Charged<L>> {
    /// A charged-particle problem: the pushers always; in a uniform field every general
    /// splitting and composition too (their drift is the exact gyration, so velocity Verlet
    /// is the magnetic Verlet). In a non-uniform field the drift freezes the field at the
    /// start of each drift: first order and not an exact flow, so splittings are refused
    /// rather than run silently at order 1.
    pub fn charged(uniform_field: bool) -> Self {
        let splitting =
            if uniform_field {
                Ok(general::<Charged<L>> as SplittingBuilder<Charged<L>>)
            } else {
                Err("the magnetic field of this problem is not uniform, and the splittings' drift (the gyration in the \
                 field frozen at the start of the drift) is then only first-order accurate and not an exact flow: \
                 every splitting and composition would drop to order 1; use boris (order 2)"
                .to_string())
            };
        Families {
            splitting,
            // the general rule's sentence, with why the rotation is not a free flight
            quadratic_kinetic: Err(Some(
                "it is a Runge-Kutta-Nystrom method, which reaches its order only when the kinetic energy is \
                 quadratic in p and the drift a free flight, and the drift here is the rotation by the magnetic \
                 field (or by the Coriolis force of a rotating frame); use a general splitting or composition \
                 (velocity_verlet_kdk is the magnetic Verlet, triple_jump4 and kahan_li6 compose it), boris, or a \
                 Runge-Kutta method",
            )),
            particle: Ok(|method, y0| method.stepper::<L>(y0)),
            relativistic: Err(
                "it is a relativistic pusher (state x, u = gamma v, with a speed of light c), and the \
                               particles of this problem are non-relativistic (state q, v); use boris, \
                               boris_exact_phase or a splitting, or a scene of model \"relativistic-particles\""
                    .into(),
            ),
        }
    }
}

/// The run-time data of a splitting source.
fn runtime_word(method: SplittingSource<'_>) -> Result<std::borrow::Cow<'_, Splitting>, Error> {
    Ok(match method {
        SplittingSource::Compiled(d) => std::borrow::Cow::Owned(Splitting::from_data(d)?),
        SplittingSource::Runtime(s) => std::borrow::Cow::Borrowed(s),
    })
}

/// A general splitting's stepper; the caller has refused Runge-Kutta-Nystrom methods.
fn general<P: Splittable + 'static>(method: SplittingSource<'_>, y0: &P::State) -> BuildResult<P> {
    Ok(Box::new(RuntimeSplitting::<P::State, P::FlowCache>::new(
        &*runtime_word(method)?,
        y0,
    )?))
}

/// Any splitting's stepper, on a quadratic kinetic energy.
fn quadratic<P: QuadraticKinetic + 'static>(method: SplittingSource<'_>, y0: &P::State) -> BuildResult<P> {
    Ok(Box::new(RuntimeSplitting::new_quadratic(&*runtime_word(method)?, y0)?))
}
