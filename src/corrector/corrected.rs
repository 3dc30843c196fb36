//! A splittable problem run in a corrector's mapping coordinates: its states are the
//! kernel's, its energy and outputs those of the corrected states.

use super::{CorrectorData, Kernel, Processor};
use crate::flows::Splittable;
use crate::method::Families;
use crate::{Error, Method, Problem};

/// `problem` run by a second-order Wisdom-Holman kernel in the mapping coordinates of a
/// symplectic corrector ([`crate::corrector`]).
///
/// Its state is the kernel's: [`Corrected::to_mapping`] makes the initial one (the
/// corrector's inverse), [`Corrected::from_mapping`] gives the corrected state of any
/// state of the run (the corrector). Its drift, force and kick are `problem`'s (the step
/// costs the same), and [`Problem::energy`] is `problem`'s energy of the corrected state, so
/// a driver's records carry the corrected energy. Only the kernel it was built for
/// ([`Kernel`]) is corrected: it admits the general splittings, and another one would run
/// uncorrected in the wrong coordinates.
#[derive(Debug, Clone)]
pub struct Corrected<P: Splittable> {
    problem: P,
    processor: Processor<P::Scalar>,
    order: Option<usize>,
}

impl<P: Splittable> Corrected<P> {
    /// `problem` with the corrector `data` of `method` (which must be a second-order
    /// Wisdom-Holman kernel: [`Kernel::of`]) at steps of `h`, the run's fixed step.
    pub fn new(problem: P, data: &CorrectorData, method: &Method, h: P::Scalar) -> Result<Self, Error> {
        let kernel = Kernel::of(method)?;
        Ok(Corrected {
            problem,
            processor: Processor::corrector(data, kernel, h),
            order: Some(data.order),
        })
    }

    /// `problem` with no corrector: the mapping coordinates are the problem's own.
    pub fn uncorrected(problem: P) -> Self {
        Corrected {
            problem,
            processor: Processor::identity(),
            order: None,
        }
    }

    /// The problem corrected.
    pub fn problem(&self) -> &P {
        &self.problem
    }

    /// The corrector's order, `None` when uncorrected.
    pub fn order(&self) -> Option<usize> {
        self.order
    }

    /// The map into the mapping coordinates.
    pub fn processor(&self) -> &Processor<P::Scalar> {
        &self.processor
    }

    /// The kernel's initial state for the problem's state `y` at `t`: the map into the
    /// mapping coordinates, applied once before the first step.
    pub fn to_mapping(&self, t: P::Scalar, y: &P::State) -> P::State {
        let mut mapped = y.clone();
        self.processor.apply(&self.problem, t, &mut mapped);
        mapped
    }

    /// The corrected state (the problem's) of the kernel's state `y` at `t`: the map out
    /// of the mapping coordinates, applied at each output.
    pub fn from_mapping(&self, t: P::Scalar, y: &P::State) -> P::State {
        let mut corrected = y.clone();
        self.processor.apply_inverse(&self.problem, t, &mut corrected);
        corrected
    }
}

impl<P: Splittable + 'static> Problem for Corrected<P> {
    type Scalar = P::Scalar;
    type State = P::State;

    /// The problem's equations, in the mapping coordinates (for the continuous extension
    /// of a step; the kernel does not use them).
    fn rhs(&self, t: P::Scalar, y: &P::State, dy: &mut P::State) {
        self.problem.rhs(t, y, dy)
    }

    /// The problem's energy of the corrected state.
    fn energy(&self, t: P::Scalar, y: &P::State) -> Option<P::Scalar> {
        if self.processor.is_identity() {
            return self.problem.energy(t, y);
        }
        self.problem.energy(t, &self.from_mapping(t, y))
    }

    /// The general splittings: the kernel is one.
    fn families(&self) -> Families<Self> {
        Families::general_splittings()
    }
}

impl<P: Splittable + 'static> Splittable for Corrected<P> {
    type FlowCache = P::FlowCache;

    #[inline(always)]
    fn drift(
        &self,
        t: P::Scalar,
        tau: P::Scalar,
        q: &mut [P::Scalar],
        p: &mut [P::Scalar],
        scratch: &mut [P::Scalar],
        cache: &mut P::FlowCache,
    ) {
        self.problem.drift(t, tau, q, p, scratch, cache)
    }

    #[inline(always)]
    fn drift_increment(
        &self,
        t: P::Scalar,
        tau: P::Scalar,
        q: &[P::Scalar],
        p: &[P::Scalar],
        dq: &mut [P::Scalar],
        dp: &mut [P::Scalar],
        scratch: &mut [P::Scalar],
        cache: &mut P::FlowCache,
    ) {
        self.problem.drift_increment(t, tau, q, p, dq, dp, scratch, cache)
    }

    #[inline(always)]
    fn force(&self, t: P::Scalar, q: &[P::Scalar], f: &mut [P::Scalar]) {
        self.problem.force(t, q, f)
    }

    #[inline(always)]
    fn kick(&self, tau: P::Scalar, f: &[P::Scalar], p: &mut [P::Scalar]) {
        self.problem.kick(tau, f, p)
    }
}
