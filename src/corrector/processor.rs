//! A processor: a fixed sequence of drifts and kicks, applied to a state outside the step
//! loop (a symplectic corrector and its inverse).

use super::CorrectorData;
use crate::flows::Splittable;
use crate::hamiltonian::halves_mut;
use crate::real::lit;
use crate::{Error, Method, Real, State};

/// One of the two sub-flows of a [`Splittable`] problem.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SubFlow {
    /// [`Splittable::drift`] (the Kepler motion of a planetary system).
    Drift,
    /// [`Splittable::kick`] by [`Splittable::force`] (the planets' interaction).
    Kick,
}

/// The second-order kernel a corrector is built for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kernel {
    /// Drift `h/2`, kick `h`, drift `h/2` (`stormer_verlet_dkd`, alias `wisdom_holman`;
    /// REBOUND's WHFast).
    DriftKickDrift,
    /// Kick `h/2`, drift `h`, kick `h/2` (`velocity_verlet_kdk`): conjugate to the
    /// drift-kick-drift kernel by a half drift and a half kick, which its processor adds.
    KickDriftKick,
}

impl Kernel {
    /// The kernel `method` is, from its coefficients, or an error saying that correctors
    /// apply only to these two.
    ///
    /// ```
    /// use stormer::corrector::Kernel;
    /// use stormer::Method;
    /// let kernel = |name| Kernel::of(&Method::named(name).unwrap());
    /// assert_eq!(kernel("wisdom_holman").unwrap(), Kernel::DriftKickDrift);
    /// assert_eq!(kernel("velocity_verlet_kdk").unwrap(), Kernel::KickDriftKick);
    /// assert!(kernel("saba4").unwrap_err().to_string().contains("wisdom_holman"));
    /// ```
    pub fn of(method: &Method) -> Result<Kernel, Error> {
        let coefficients = match method {
            Method::Splitting(d) if d.gamma.is_none() => Some((d.drift, d.kick)),
            Method::RuntimeSplitting(s) if s.gamma().is_none() => Some((s.drift(), s.kick())),
            _ => None,
        };
        match coefficients {
            Some((drift, kick)) if drift == [0.5, 0.5] && kick == [1.0, 0.0] => Ok(Kernel::DriftKickDrift),
            Some((drift, kick)) if drift == [0.0, 1.0] && kick == [0.5, 0.5] => Ok(Kernel::KickDriftKick),
            _ => Err(Error::Unsupported {
                name: method.name().to_string(),
                reason: "symplectic correctors are built for the second-order Wisdom-Holman kernel only: \
                         drift-kick-drift (wisdom_holman, alias of stormer_verlet_dkd) or kick-drift-kick \
                         (velocity_verlet_kdk); run this method without --corrector"
                    .to_string(),
            }),
        }
    }
}

/// A sequence of sub-flows `(flow, tau)`, applied first to last: the map into a kernel's
/// mapping coordinates. [`Processor::apply`] applies it, [`Processor::apply_inverse`] its
/// inverse (the sequence reversed, every `tau` negated: both sub-flows are exact flows).
#[derive(Debug, Clone, PartialEq)]
pub struct Processor<T> {
    ops: Vec<(SubFlow, T)>,
}

impl<T: Real> Processor<T> {
    /// The identity: no sub-flow.
    pub fn identity() -> Self {
        Processor { ops: Vec::new() }
    }

    /// The corrector `data` of `kernel` with steps of `h`: its factors `Z(a h, b h) =
    /// D(a h) K(-b h) D(-2a h) K(b h) D(a h)`, then, for [`Kernel::KickDriftKick`],
    /// `D(-h/2) K(-h/2)` (the kick-drift-kick map is `(K(h/2) D(h/2))`, the
    /// drift-kick-drift map, then `(D(-h/2) K(-h/2))`). Adjacent drifts are merged.
    pub fn corrector(data: &CorrectorData, kernel: Kernel, h: T) -> Self {
        let mut processor = Processor::identity();
        for &(a, b) in data.z {
            let (a, b) = (lit::<T>(a) * h, lit::<T>(b) * h);
            processor.push(SubFlow::Drift, a);
            processor.push(SubFlow::Kick, -b);
            processor.push(SubFlow::Drift, -(a + a));
            processor.push(SubFlow::Kick, b);
            processor.push(SubFlow::Drift, a);
        }
        if kernel == Kernel::KickDriftKick {
            let half = h * lit::<T>(0.5);
            processor.push(SubFlow::Drift, -half);
            processor.push(SubFlow::Kick, -half);
        }
        processor
    }

    /// Appends `(flow, tau)`, merged into the last one when it is the same sub-flow.
    pub fn push(&mut self, flow: SubFlow, tau: T) {
        match self.ops.last_mut() {
            Some((last, t)) if *last == flow => *t += tau,
            _ => self.ops.push((flow, tau)),
        }
    }

    /// The sub-flows, first to last.
    pub fn ops(&self) -> &[(SubFlow, T)] {
        &self.ops
    }

    /// True when there is no sub-flow.
    pub fn is_identity(&self) -> bool {
        self.ops.is_empty()
    }

    /// Applies the sequence to `y` (positions, then momenta) of `problem` at time `t`
    /// (the sub-flows are taken at `t`: a corrector is for autonomous problems).
    pub fn apply<P: Splittable<Scalar = T>>(&self, problem: &P, t: T, y: &mut P::State) {
        self.run(problem, t, y, self.ops.iter().copied());
    }

    /// Applies the inverse sequence to `y`.
    pub fn apply_inverse<P: Splittable<Scalar = T>>(&self, problem: &P, t: T, y: &mut P::State) {
        self.run(problem, t, y, self.ops.iter().rev().map(|&(flow, tau)| (flow, -tau)));
    }

    fn run<P: Splittable<Scalar = T>>(
        &self,
        problem: &P,
        t: T,
        y: &mut P::State,
        ops: impl Iterator<Item = (SubFlow, T)>,
    ) {
        if self.ops.is_empty() {
            return;
        }
        // the force and the drift's scratch, in a state's storage: no heap for static states
        let mut work = y.zeros_like();
        let (force, scratch) = halves_mut(work.as_mut_slice());
        let mut cache = P::FlowCache::default();
        let (q, p) = halves_mut(y.as_mut_slice());
        for (flow, tau) in ops {
            match flow {
                SubFlow::Drift => problem.drift(t, tau, q, p, scratch, &mut cache),
                SubFlow::Kick => {
                    problem.force(t, q, force);
                    problem.kick(tau, force, p);
                }
            }
        }
    }
}
