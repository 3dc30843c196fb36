//! Which splitting methods a scene admits: the helpers behind
//! [`Scene::splitting_stepper`](super::Scene::splitting_stepper).
//!
//! A Hamiltonian model answers with [`quadratic_splitting`] (kinetic energy quadratic in
//! `p`: every splitting and composition, Runge-Kutta-Nystrom ones included) or
//! [`general_splitting`] (the others are refused with a sentence); a model that is not a
//! Hamiltonian keeps the default, a refusal built by [`not_splittable`].

use stormer::flows::{QuadraticKinetic, Splittable};
use stormer::method::SplittingData;
use stormer::{registry, Error, Problem, RuntimeSplitting, Splitting, Stepper};

/// A splitting or composition to run: compiled into the crate (its generated stepper is
/// used) or built at run time.
#[derive(Debug, Clone, Copy)]
pub enum SplittingChoice<'a> {
    /// A catalog method.
    Compiled(&'static SplittingData),
    /// A method held in memory (read from a file, or built with [`Splitting::splitting`]).
    Runtime(&'a Splitting),
}

impl SplittingChoice<'_> {
    /// The method's name.
    pub fn name(&self) -> &str {
        match self {
            SplittingChoice::Compiled(d) => d.name,
            SplittingChoice::Runtime(s) => s.name(),
        }
    }
}

/// The refusal of a splitting method on a model that has no drift and kick sub-flows:
/// `why` says what the model is, and the sentence ends with what to use instead.
///
/// ```
/// let e = stormer_app::scenes::not_splittable("velocity_verlet_kdk", "it has friction");
/// assert_eq!(
///     e.to_string(),
///     "method velocity_verlet_kdk cannot be used here: it has friction; \
///      use a Runge-Kutta method instead, such as rk4 or dop853 (`stormer methods`)"
/// );
/// ```
pub fn not_splittable(method: &str, why: &str) -> Error {
    Error::Unsupported {
        name: method.to_string(),
        reason: format!("{why}; use a Runge-Kutta method instead, such as rk4 or dop853 (`stormer methods`)"),
    }
}

/// The stepper of any splitting or composition, for a model whose kinetic energy is
/// quadratic in `p` (Runge-Kutta-Nystrom methods included).
pub fn quadratic_splitting<P>(method: SplittingChoice<'_>, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
where
    P: QuadraticKinetic + 'static,
    <P as Problem>::State: 'static,
{
    match method {
        SplittingChoice::Compiled(d) => registry::splitting_stepper_quadratic::<P>(d.name, y0),
        SplittingChoice::Runtime(s) => Ok(Box::new(RuntimeSplitting::new_quadratic(s, y0)?)),
    }
}

/// The stepper of a general splitting or composition; a method that needs a quadratic
/// kinetic energy is refused with a sentence saying so.
pub fn general_splitting<P>(method: SplittingChoice<'_>, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
where
    P: Splittable + 'static,
    <P as Problem>::State: 'static,
{
    match method {
        SplittingChoice::Compiled(d) => registry::splitting_stepper::<P>(d.name, y0),
        SplittingChoice::Runtime(s) => Ok(Box::new(RuntimeSplitting::new(s, y0)?)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenes::{Number, Scene, Source};
    use serde::Deserialize;
    use stormer::Hamiltonian;

    /// H = p^2/2 + p^4/4 - cos q: a Hamiltonian whose kinetic energy is not quadratic.
    #[derive(Debug, Clone)]
    struct Quartic;
    impl Hamiltonian for Quartic {
        type Scalar = f64;
        type State = [f64; 2];
        fn kinetic_gradient(&self, p: &[f64], v: &mut [f64]) {
            v[0] = p[0] + p[0] * p[0] * p[0];
        }
        fn force(&self, _t: f64, q: &[f64], f: &mut [f64]) {
            f[0] = -q[0].sin();
        }
    }

    #[derive(Debug, Deserialize)]
    struct Initial {
        q: Number,
    }

    impl Scene for Quartic {
        const MODEL: &'static str = "quartic";
        type Parameters = ();
        type Initial = Initial;
        fn build(_: Option<()>, initial: Initial, src: &Source<'_>) -> Result<(Self, [f64; 2]), Error> {
            Ok((Quartic, [src.finite("initial.q", &initial.q)?, 0.0]))
        }
        fn components(&self, _y0: &[f64; 2]) -> Vec<String> {
            vec!["q".into(), "p".into()]
        }
        fn splitting_stepper(
            &self,
            method: SplittingChoice<'_>,
            y0: &[f64; 2],
        ) -> Result<Box<dyn Stepper<Self>>, Error> {
            general_splitting(method, y0)
        }
    }

    /// A model that keeps the default: no splittings at all.
    #[derive(Debug, Clone)]
    struct Opaque;
    impl Problem for Opaque {
        type Scalar = f64;
        type State = [f64; 2];
        fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
            *dy = [y[1], -y[0]];
        }
    }
    impl Scene for Opaque {
        const MODEL: &'static str = "opaque";
        type Parameters = ();
        type Initial = ();
        fn build(_: Option<()>, _: (), _: &Source<'_>) -> Result<(Self, [f64; 2]), Error> {
            Ok((Opaque, [1.0, 0.0]))
        }
        fn components(&self, _y0: &[f64; 2]) -> Vec<String> {
            vec!["x".into(), "v".into()]
        }
    }

    fn compiled(name: &str) -> SplittingChoice<'static> {
        SplittingChoice::Compiled(registry::find_splitting(name).unwrap())
    }

    #[test]
    fn an_rkn_method_is_refused_without_a_quadratic_kinetic_energy() {
        let y0 = [0.5, 0.0];
        let message = Quartic
            .splitting_stepper(compiled("blanes_moan_srkn11b"), &y0)
            .err()
            .unwrap()
            .to_string();
        assert!(message.contains("kinetic energy is quadratic in p"), "{message}");
        assert!(message.contains("use a general splitting or composition"), "{message}");
        let rkn = Splitting::splitting("my_rkn", &[0.5, 0.5], &[1.0, 0.0], 2, true).unwrap();
        let message = Quartic
            .splitting_stepper(SplittingChoice::Runtime(&rkn), &y0)
            .err()
            .unwrap()
            .to_string();
        assert!(message.contains("quadratic"), "{message}");
        // general methods run, and RKN methods run on a quadratic kinetic energy
        assert!(Quartic.splitting_stepper(compiled("blanes_moan_s6"), &y0).is_ok());
        assert!(quadratic_splitting::<crate::scenes::Pendulum>(compiled("blanes_moan_srkn11b"), &y0).is_ok());
        assert!(quadratic_splitting::<crate::scenes::Pendulum>(SplittingChoice::Runtime(&rkn), &y0).is_ok());
    }

    #[test]
    fn a_model_without_sub_flows_refuses_every_splitting() {
        let message = Opaque
            .splitting_stepper(compiled("velocity_verlet_kdk"), &[1.0, 0.0])
            .err()
            .unwrap()
            .to_string();
        assert!(
            message.contains("the opaque model does not declare drift and kick sub-flows"),
            "{message}"
        );
        assert!(message.ends_with("use a Runge-Kutta method instead, such as rk4 or dop853 (`stormer methods`)"));
        assert_eq!(compiled("triple_jump4").name(), "triple_jump4");
    }
}
