//! Sub-flows: the exact flows a splitting method composes.
//!
//! A problem that can be split provides two flows on its phase-space state `(q, p)`:
//! the **drift** (the flow of the first part, `A`; for `H = T(p) + V(q)` it is
//! `q += tau dT/dp`) and the **kick** (the flow of the second part, `B`: `p += tau F(t, q)`).
//! Splitting and composition steppers only call these two flows; they never assume what
//! "drift" means, so a problem whose drift is another exactly solvable flow (the rotation
//! of a charged particle in a magnetic field, Kepler motion) gets every method of the
//! catalog without new code.
//!
//! The kick is split into the force evaluation and its application, so that a stepper can
//! reuse the force at the end of one step for the first kick of the next (FSAL).

use crate::{Problem, Real};

/// A problem with exact drift and kick sub-flows on a state `(q, p)` of length `2n`.
///
/// Implemented for every [`crate::hamiltonian::Hamiltonian`] (and so every [`crate::SecondOrder`]
/// problem); implement it directly for a problem whose drift is not `q += tau dT/dp`.
pub trait Splittable: Problem {
    /// Memory a stepper keeps for the sub-flows between calls, e.g. the rotation of a
    /// uniform magnetic field for the step sizes in use (computed once, not per step);
    /// `()` for most problems. Each stepper owns one, created with `Default`.
    type FlowCache: Default + Clone + core::fmt::Debug;

    /// Why this problem cannot be stepped with compensated summation, or `None` (every
    /// problem whose kick adds a term that does not depend on `p`, as
    /// [`Splittable::kick`] asks). A problem whose kick reads `p` (the time-transformed
    /// leapfrog's auxiliary variable, [`crate::time_transform::Ttl`]) says why here, and a
    /// splitting stepper refuses [`crate::Stepper::set_compensated`] on it with that reason.
    const COMPENSATION_REFUSED: Option<&'static str> = None;

    /// The exact flow of the first part for time `tau` (possibly negative), starting at
    /// time `t`, in place on the halves `q` and `p` (each of length `n`). `scratch` is `n`
    /// values of workspace, with no meaning before or after the call; `cache` is the
    /// calling stepper's [`Splittable::FlowCache`].
    fn drift(
        &self,
        t: Self::Scalar,
        tau: Self::Scalar,
        q: &mut [Self::Scalar],
        p: &mut [Self::Scalar],
        scratch: &mut [Self::Scalar],
        cache: &mut Self::FlowCache,
    );

    /// The drift's increment, for compensated summation: ADDS to `(dq, dp)` what
    /// [`Splittable::drift`] for time `tau` from `t` would add to `(q, p)`, leaving `q` and
    /// `p` as they are. `scratch` is `3n` values of workspace.
    ///
    /// A compensated stepper ([`crate::Stepper::set_compensated`]) sums a step's
    /// increments apart from the state and adds them once, with Kahan's carry; the benefit
    /// comes from increments computed without forming the new state. The provided form
    /// does form it (the drift applied to a copy, minus the start), so the rounding of the
    /// new state stays in the increment: a problem that keeps this default gets no
    /// compensation benefit for its drift. Every [`crate::hamiltonian::Hamiltonian`] and
    /// [`crate::magnetic::Charged`] model has an exact increment form.
    ///
    /// ```
    /// use stormer::flows::Splittable;
    /// use stormer::hamiltonian::Hamiltonian;
    /// struct Free;
    /// impl Hamiltonian for Free {
    ///     type Scalar = f64;
    ///     type State = [f64; 2];
    ///     fn force(&self, _t: f64, _q: &[f64], f: &mut [f64]) { f[0] = 0.0; }
    /// }
    /// let (mut dq, mut dp, mut scratch) = ([1.0], [0.0], [0.0; 3]);
    /// Free.drift_increment(0.0, 0.5, &[10.0], &[2.0], &mut dq, &mut dp, &mut scratch, &mut ());
    /// assert_eq!((dq, dp), ([2.0], [0.0])); // 1 + 0.5 * 2
    /// ```
    #[allow(clippy::too_many_arguments)]
    fn drift_increment(
        &self,
        t: Self::Scalar,
        tau: Self::Scalar,
        q: &[Self::Scalar],
        p: &[Self::Scalar],
        dq: &mut [Self::Scalar],
        dp: &mut [Self::Scalar],
        scratch: &mut [Self::Scalar],
        cache: &mut Self::FlowCache,
    ) {
        let n = q.len();
        let (moved_q, rest) = scratch.split_at_mut(n);
        let (moved_p, drift_scratch) = rest.split_at_mut(n);
        moved_q.copy_from_slice(q);
        moved_p.copy_from_slice(p);
        self.drift(t, tau, moved_q, moved_p, drift_scratch, cache);
        for (d, (&new, &old)) in dq.iter_mut().zip(moved_q.iter().zip(q)) {
            *d += new - old;
        }
        for (d, (&new, &old)) in dp.iter_mut().zip(moved_p.iter().zip(p)) {
            *d += new - old;
        }
    }

    /// The force (the rate of `p` under the kick) at `(t, q)`, written into `f`.
    fn force(&self, t: Self::Scalar, q: &[Self::Scalar], f: &mut [Self::Scalar]);

    /// The exact flow of the second part: `p += tau f`, `f` being [`Splittable::force`] at
    /// the current `(t, q)`. A compensated stepper applies it to the step's momentum
    /// increment instead of `p`, so it must add a term that does not depend on `p`.
    #[inline(always)]
    fn kick(&self, tau: Self::Scalar, f: &[Self::Scalar], p: &mut [Self::Scalar]) {
        kick(tau, f, p)
    }
}

/// `p += tau f`, component by component.
#[inline(always)]
pub fn kick<T: Real>(tau: T, f: &[T], p: &mut [T]) {
    for (p, &f) in p.iter_mut().zip(f) {
        *p += tau * f;
    }
}

/// A splittable problem whose kinetic energy is quadratic in `p` (more precisely: whose
/// flows satisfy `[B, [B, [B, A]]] = 0`), the condition under which the methods built for
/// Runge-Kutta-Nystrom problems reach their order.
///
/// Implemented for every [`crate::SecondOrder`] problem; a [`crate::hamiltonian::Hamiltonian`] with
/// `T = |p|^2 / (2m)` (or any `p^T M^-1 p / 2`) opts in with an empty impl. A method
/// with `requires_quadratic_kinetic` only accepts problems with this trait.
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not declared `QuadraticKinetic`, which this method needs",
    label = "a method built for quadratic kinetic energies (Runge-Kutta-Nystrom) cannot step this problem",
    note = "use a general splitting or composition, or add `impl QuadraticKinetic for {Self} {{}}` if its kinetic energy is quadratic in p"
)]
pub trait QuadraticKinetic: Splittable {}

/// The refusal of a Runge-Kutta-Nystrom method (`requires_quadratic_kinetic`) on a problem
/// that does not declare [`QuadraticKinetic`]: the one place the rule is said in words
/// (the trait says it to the compiler, [`Admits`] to the generic steppers).
pub(crate) fn quadratic_kinetic_refused(method: &str) -> crate::Error {
    crate::Error::Unsupported {
        name: method.to_string(),
        reason: "it reaches its order only when the kinetic energy is quadratic in p (a Runge-Kutta-Nystrom \
                 method), which this problem does not declare; use a general splitting or composition"
            .into(),
    }
}

/// The class of problems a splitting method is valid for (a type-level flag of
/// [`crate::method::SplittingMethod`]).
pub trait ProblemClass: Copy + Default + core::fmt::Debug + Send + Sync + 'static {}

/// Valid for every splittable problem.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct General;

/// Valid only for problems with quadratic kinetic energy (Runge-Kutta-Nystrom methods).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QuadraticOnly;

impl ProblemClass for General {}
impl ProblemClass for QuadraticOnly {}

/// `P: Admits<C>` when problem `P` belongs to class `C`: every splittable problem admits
/// [`General`] methods, only [`QuadraticKinetic`] ones admit [`QuadraticOnly`] methods.
#[diagnostic::on_unimplemented(
    message = "`{Self}` does not admit methods of class `{C}`",
    note = "a method of class `QuadraticOnly` (Runge-Kutta-Nystrom) needs a `QuadraticKinetic` problem"
)]
pub trait Admits<C: ProblemClass>: Splittable {}

impl<P: Splittable> Admits<General> for P {}
impl<P: QuadraticKinetic> Admits<QuadraticOnly> for P {}
