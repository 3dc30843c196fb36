//! A composition over any symmetric second-order stepper (implicit midpoint, a
//! Gauss-Legendre-like base, any user stepper): `S(gamma_s h) o ... o S(gamma_1 h)`.

use super::{Counters, Stepper, StepperState};
use crate::method::{MethodInfo, Splitting};
use crate::real::lit;
use crate::{Error, Problem, State};

/// The composition `S(gamma_s h) o ... o S(gamma_1 h)` of a base stepper `S`.
///
/// The weights' order holds for a symmetric second-order base; other bases are refused.
/// For splittable problems prefer the generated composition (its sub-flows merged into one
/// unrolled word); this form is for bases that are not splittings.
///
/// ```
/// use stormer::stepper::Composed;
/// use stormer::{Method, Problem, Stepper};
/// use stormer::method::Splitting;
/// use stormer::stepper::ImplicitOptions;
/// struct Oscillator;
/// impl Problem for Oscillator {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) { *dy = [y[1], -y[0]]; }
/// }
/// let y0 = [1.0, 0.0];
/// let midpoint = Method::named("implicit_midpoint").unwrap();
/// let base = midpoint.stepper_for(&Oscillator, &y0, &ImplicitOptions::default()).unwrap();
/// let w = 1.0 / (2.0 - 2f64.cbrt());
/// let jump = Splitting::composition("triple_jump4", &[w, 1.0 - 2.0 * w, w], 4).unwrap();
/// let mut s = Composed::new(&jump, base, &y0).unwrap();
/// let mut y = [0.0; 2];
/// s.step(&Oscillator, 0.0, 0.1, &y0, &mut y).unwrap();
/// assert!((y[0] - 0.1f64.cos()).abs() < 1e-7);
/// ```
pub struct Composed<P: Problem> {
    info: MethodInfo,
    gamma: Vec<P::Scalar>,
    base: Box<dyn Stepper<P>>,
    scratch: P::State,
}

impl<P: Problem> Composed<P> {
    /// Composes `base` with the weights of `method` (a composition).
    pub fn new(method: &Splitting, base: Box<dyn Stepper<P>>, y0: &P::State) -> Result<Self, Error> {
        let Some(gamma) = method.gamma() else {
            return Err(Error::Unsupported {
                name: method.name().to_string(),
                reason: "it is a splitting, not a composition: it has no weights to compose a base method with".into(),
            });
        };
        let b = base.info();
        if !(b.flags.symmetric && b.order == 2) {
            return Err(Error::Unsupported {
                name: method.name().to_string(),
                reason: format!(
                    "a composition needs a symmetric second-order base, and {} is {}order {}",
                    b.name,
                    if b.flags.symmetric { "" } else { "not symmetric, " },
                    b.order
                ),
            });
        }
        let mut info = method.info();
        info.name = format!("{}({})", method.name(), b.name);
        info.flags.symplectic = b.flags.symplectic;
        info.flags.explicit = b.flags.explicit;
        info.flags.fsal = false;
        info.stages = gamma.len() * b.stages;
        Ok(Composed {
            info,
            gamma: gamma.iter().map(|&g| lit(g)).collect(),
            base,
            scratch: y0.clone(),
        })
    }
}

impl<P: Problem> Stepper<P> for Composed<P> {
    fn info(&self) -> MethodInfo {
        self.info.clone()
    }

    fn step(&mut self, p: &P, t: P::Scalar, h: P::Scalar, y: &P::State, y_new: &mut P::State) -> Result<(), Error> {
        // each substep reads the state from `scratch` and writes `y_new`
        let mut time = t;
        self.scratch.copy_from(y);
        for &g in &self.gamma {
            let tau = g * h;
            self.base.step(p, time, tau, &self.scratch, y_new)?;
            self.base.accept();
            self.scratch.copy_from(y_new);
            time += tau;
        }
        Ok(())
    }

    fn accept(&mut self) {}

    fn reset(&mut self) {
        self.base.reset();
    }

    /// Compensated summation of the base: each substep starts from the state the previous
    /// one produced, so the base's carry runs through the whole composition.
    fn set_compensated(&mut self, on: bool) -> Result<(), Error> {
        self.base.set_compensated(on)
    }

    fn counters(&self) -> Counters {
        self.base.counters()
    }

    /// The base's state (its carry runs through the substeps).
    fn save(&self) -> StepperState {
        let mut state = StepperState::of(self.info.name.clone());
        state.nest("base", self.base.save());
        state
    }

    fn restore(&mut self, state: &StepperState) -> Result<(), Error> {
        state.check_method(&self.info.name)?;
        self.base.restore(&state.nested("base", self.base.info().name))
    }
}
