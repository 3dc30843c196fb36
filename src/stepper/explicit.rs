//! The explicit Runge-Kutta stepper, one for compiled and run-time tableaus: FSAL
//! bookkeeping, compensated summation and the error estimate over the stages of an
//! [`ExplicitStages`] (the macro's unrolled code, or loops over a run-time tableau).

use super::compensated::CompensatedCombination;
use super::{Counters, Stepper, StepperState, Tolerances};
use crate::method::ExplicitMethod;
use crate::method::MethodInfo;
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Problem, State};

/// The stages of an explicit tableau, as [`ExplicitStepper`] runs them: compiled
/// ([`Unrolled`], the code `tableau!` generates) or read at run time
/// ([`super::RuntimeStages`]). Both perform the same floating-point operations in the same
/// order, so their trajectories are bitwise equal (`tests/methods/compiled_vs_runtime.rs`).
pub trait ExplicitStages<S: State>: Clone + core::fmt::Debug {
    /// Name, order, stages and flags.
    fn info(&self) -> MethodInfo;
    /// The weights `b` as declared (for the compensated combination).
    fn weights(&self) -> &[f64];
    /// Whether the tableau has `b_hat`, and DOP853's `b_hat3`.
    fn estimates(&self) -> (bool, bool);
    /// Stages 2..=s and the new state: `k[0]` already holds `f(t, y)`; writes `k[1..s]`
    /// and `y_new = y + h sum_i b_i k_i` (`y_new` doubles as the stage state).
    fn stages<P>(&self, p: &P, t: S::Scalar, h: S::Scalar, y: &S, k: &mut [S], y_new: &mut S)
    where
        P: Problem<Scalar = S::Scalar, State = S>;
    /// `err = h sum_i (b_i - b_hat_i) k_i`.
    fn error(&self, h: S::Scalar, k: &[S], err: &mut S);
    /// `err = h sum_i (b_i - b_hat3_i) k_i`.
    fn error3(&self, h: S::Scalar, k: &[S], err: &mut S);
    /// The number of powers `m` of the method's own dense output, `None` without one.
    fn dense_powers(&self) -> Option<usize>;
    /// The dense output's coefficients of theta^1 .. theta^m in `b_stage(theta)`.
    fn dense_row(&self, stage: usize) -> &[f64];
    /// The stages the dense output adds after the step: their nodes, and their rows
    /// `e x (s + e)` row-major (both empty for most methods).
    fn dense_added(&self) -> (&[f64], &[f64]);
}

/// The stages `tableau!` generated for `M`, with its coefficients converted to the
/// state's scalar.
#[derive(Debug, Clone, Copy)]
pub struct Unrolled<M: ExplicitMethod, S: State> {
    co: M::Coeffs<S::Scalar>,
}

impl<M: ExplicitMethod, S: State> ExplicitStages<S> for Unrolled<M, S> {
    fn info(&self) -> MethodInfo {
        M::DATA.info()
    }

    fn weights(&self) -> &[f64] {
        M::DATA.b
    }

    #[inline(always)]
    fn estimates(&self) -> (bool, bool) {
        (M::DATA.b_hat.is_some(), M::DATA.b_hat3.is_some())
    }

    #[inline(always)]
    fn stages<P>(&self, p: &P, t: S::Scalar, h: S::Scalar, y: &S, k: &mut [S], y_new: &mut S)
    where
        P: Problem<Scalar = S::Scalar, State = S>,
    {
        M::stages(&self.co, p, t, h, y, k, y_new);
    }

    #[inline(always)]
    fn error(&self, h: S::Scalar, k: &[S], err: &mut S) {
        M::error(&self.co, h, k, err);
    }

    #[inline(always)]
    fn error3(&self, h: S::Scalar, k: &[S], err: &mut S) {
        M::error3(&self.co, h, k, err);
    }

    fn dense_powers(&self) -> Option<usize> {
        M::DATA.dense.map(|d| d.powers)
    }

    fn dense_row(&self, stage: usize) -> &[f64] {
        M::DATA
            .dense
            .map_or(&[], |d| &d.d[stage * d.powers..(stage + 1) * d.powers])
    }

    fn dense_added(&self) -> (&[f64], &[f64]) {
        M::DATA.dense.map_or((&[], &[]), |d| (d.c, d.a))
    }
}

/// Stepper for an explicit tableau whose stages `C` gives, on states `S`: the generated
/// code of a compiled method ([`ExplicitRk`]) or a tableau read at run time
/// ([`super::RuntimeRk`]).
#[derive(Debug, Clone)]
pub struct ExplicitStepper<C, S: State> {
    stages: C,
    /// Whether the last stage is `f` at the new state (and becomes the next `k[0]`).
    fsal: bool,
    /// The order of the error estimate ([`Stepper::error_order`]).
    error_order: Option<usize>,
    k: Vec<S>,
    err: Option<S>,
    err3: Option<S>,
    k0_valid: bool,
    /// The last step's size, for its error estimate ([`Stepper::error_norm`]).
    last_h: S::Scalar,
    /// The final combination summed with a carry, when turned on. Boxed: held inline, its
    /// buffers changed the plain stepper's layout enough that the generated RK4 step lost
    /// its register allocation (1.21x the hand-written loop instead of 0.98x, bisected to
    /// the commit that added it; docs/benchmarks.md).
    compensated: Option<Box<CompensatedCombination<S>>>,
    /// The dense output's coefficients and the stages it adds after a step (DOP853's),
    /// made at the first output time inside a step. Boxed and created then: a run without
    /// output pays nothing.
    dense: Option<Box<Dense<S>>>,
    counters: Counters,
}

/// The method's own dense output in the state's scalar (converted once), and the stages it
/// adds after the step with the step `(t, h)` they are of.
#[derive(Debug, Clone)]
struct Dense<S: State> {
    /// The powers `m` of `b_i(theta)`.
    powers: usize,
    /// The stages whose `b_i(theta)` is not zero, with the coefficients of theta^1 .. theta^m.
    rows: Vec<(usize, Vec<S::Scalar>)>,
    /// The added stages: their nodes and rows of `a` (`e x (s + e)`), and their values.
    c: Vec<S::Scalar>,
    a: Vec<S::Scalar>,
    k: Vec<S>,
    stage: S,
    of_step: Option<(S::Scalar, S::Scalar)>,
}

/// Powers of theta a dense output may use (DOP853's is 7).
const MAX_POWERS: usize = 12;

impl<S: State> Dense<S> {
    fn new<C: ExplicitStages<S>>(stages: &C, s: usize, y: &S) -> Option<Self> {
        let powers = stages.dense_powers().filter(|&m| m <= MAX_POWERS)?;
        let (c, a) = stages.dense_added();
        let rows = (0..s + c.len())
            .map(|i| (i, stages.dense_row(i)))
            .filter(|(_, row)| row.iter().any(|&d| d != 0.0))
            .map(|(i, row)| (i, row.iter().map(|&d| lit(d)).collect()))
            .collect();
        Some(Dense {
            powers,
            rows,
            c: c.iter().map(|&x| lit(x)).collect(),
            a: a.iter().map(|&x| lit(x)).collect(),
            k: vec![y.zeros_like(); c.len()],
            stage: y.zeros_like(),
            of_step: None,
        })
    }
}

/// Stepper for an explicit method `M` declared with [`crate::tableau!`], on states `S`.
///
/// ```
/// use stormer::{Problem, Stepper};
/// use stormer::catalog::Rk4;
/// use stormer::stepper::ExplicitRk;
/// struct Decay;
/// impl Problem for Decay {
///     type Scalar = f64;
///     type State = [f64; 1];
///     fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) { dy[0] = -y[0]; }
/// }
/// let mut rk4 = ExplicitRk::<Rk4, [f64; 1]>::new(&[1.0]);
/// let mut y = [0.0];
/// rk4.step(&Decay, 0.0, 0.1, &[1.0], &mut y).unwrap();
/// assert!((y[0] - (-0.1f64).exp()).abs() < 1e-7);
/// ```
pub type ExplicitRk<M, S> = ExplicitStepper<Unrolled<M, S>, S>;

impl<M: ExplicitMethod, S: State> ExplicitStepper<Unrolled<M, S>, S> {
    /// A stepper with stage buffers shaped like `y0`.
    pub fn new(y0: &S) -> Self {
        Self::with_stages(Unrolled { co: M::coeffs() }, y0)
    }

    /// Boxed for run-time method choice (used by the macro's `dyn_stepper`).
    pub fn boxed<P>(y0: &S) -> Box<dyn Stepper<P>>
    where
        P: Problem<Scalar = S::Scalar, State = S> + 'static,
        S: 'static,
    {
        Box::new(Self::new(y0))
    }
}

impl<C: ExplicitStages<S>, S: State> ExplicitStepper<C, S> {
    /// The dense output of the step `(t, y)` of size `last_h` just taken, with the stages it
    /// adds (`Y = y + h sum_j a_kj K_j` over the step's stages and the added ones before,
    /// `K_k = f(t + c_k h, Y)`), made once per step; nothing for a method without one.
    fn dense_of_step<P: Problem<Scalar = S::Scalar, State = S>>(&mut self, p: &P, t: S::Scalar, y: &S) {
        if self.dense.is_none() {
            self.dense = Dense::new(&self.stages, self.k.len(), y).map(Box::new);
        }
        let Some(dense) = self.dense.as_mut() else {
            return;
        };
        let h = self.last_h;
        if !dense.c.is_empty() && dense.of_step != Some((t, h)) {
            let (s, n) = (self.k.len(), self.k.len() + dense.c.len());
            for e in 0..dense.c.len() {
                dense.stage.copy_from(y);
                for (j, &aj) in dense.a[e * n..(e + 1) * n].iter().enumerate() {
                    if aj != S::Scalar::zero() {
                        let kj = if j < s { &self.k[j] } else { &dense.k[j - s] };
                        dense.stage.axpy(h * aj, kj);
                    }
                }
                p.rhs(t + dense.c[e] * h, &dense.stage, &mut dense.k[e]);
            }
            self.counters.evaluations += dense.c.len() as u64;
            dense.of_step = Some((t, h));
        }
    }

    /// A stepper over `stages`, with buffers shaped like `y0`.
    pub(crate) fn with_stages(stages: C, y0: &S) -> Self {
        let info = stages.info();
        let (estimate, estimate3) = stages.estimates();
        ExplicitStepper {
            // DOP853's combined estimate behaves like an order-7 one (Hairer's exponent 1/8).
            error_order: match (info.embedded_order, estimate3) {
                (Some(_), true) => Some(info.order - 1),
                (q, _) => q,
            },
            fsal: info.flags.fsal,
            k: vec![y0.zeros_like(); info.stages],
            err: estimate.then(|| y0.zeros_like()),
            err3: estimate3.then(|| y0.zeros_like()),
            k0_valid: false,
            last_h: num_traits::Zero::zero(),
            compensated: None,
            dense: None,
            counters: Counters::default(),
            stages,
        }
    }

    /// One step without error estimate: the hot path of fixed-step integration.
    #[inline]
    pub fn advance<P>(&mut self, p: &P, t: S::Scalar, h: S::Scalar, y: &S, y_new: &mut S)
    where
        P: Problem<Scalar = S::Scalar, State = S>,
    {
        if !self.k0_valid {
            p.rhs(t, y, &mut self.k[0]);
            self.counters.evaluations += 1;
        }
        self.stages.stages(p, t, h, y, &mut self.k, y_new);
        self.counters.evaluations += self.k.len() as u64 - 1;
        self.k0_valid = true;
    }
}

impl<C, P> Stepper<P> for ExplicitStepper<C, P::State>
where
    C: ExplicitStages<P::State>,
    P: Problem,
{
    fn info(&self) -> MethodInfo {
        self.stages.info()
    }

    fn error_order(&self) -> Option<usize> {
        self.error_order
    }

    #[inline]
    fn step(&mut self, p: &P, t: P::Scalar, h: P::Scalar, y: &P::State, y_new: &mut P::State) -> Result<(), Error> {
        self.advance(p, t, h, y, y_new);
        self.last_h = h;
        if let Some(sum) = self.compensated.as_mut() {
            sum.combine(h, y, &self.k, y_new);
        }
        Ok(())
    }

    fn error_norm(&mut self, y: &P::State, y_new: &P::State, tol: &Tolerances<P::Scalar>) -> Option<P::Scalar> {
        let (h, err) = (self.last_h, self.err.as_mut()?);
        self.stages.error(h, &self.k, err);
        Some(match self.err3.as_mut() {
            Some(err3) => {
                self.stages.error3(h, &self.k, err3);
                tol.dop853(y, y_new, err, err3)
            }
            None => tol.rms(y, y_new, err),
        })
    }

    /// `k[0]` is `f(t, y)` after every step; the last stage of a FSAL tableau is
    /// `f(t + h, y_new)` (to the rounding of a compensated step's `y_new`).
    fn end_slopes(&self) -> [Option<&P::State>; 2] {
        [self.k.first(), self.k.last().filter(|_| self.fsal)]
    }

    /// `y + h sum_i b_i(theta) k_i` with the method's own `b_i(theta)`, over its stages and
    /// the ones its dense output adds (made once per step).
    fn interpolate(&mut self, p: &P, t: P::Scalar, theta: P::Scalar, y: &P::State, out: &mut P::State) -> bool {
        let (h, s) = (self.last_h, self.k.len());
        self.dense_of_step(p, t, y);
        let Some(dense) = self.dense.as_deref() else {
            return false;
        };
        // theta^1 .. theta^m once, then each b_i(theta) as independent products
        let mut power = [P::Scalar::zero(); MAX_POWERS];
        let mut x = theta;
        for p in &mut power[..dense.powers] {
            *p = x;
            x *= theta;
        }
        out.copy_from(y);
        for (i, row) in &dense.rows {
            let weight = row.iter().zip(&power).fold(P::Scalar::zero(), |w, (&d, &x)| w + d * x);
            out.axpy(h * weight, if *i < s { &self.k[*i] } else { &dense.k[*i - s] });
        }
        true
    }

    fn accept(&mut self) {
        if let Some(sum) = self.compensated.as_mut() {
            // the last stage was evaluated at the uncompensated y_new: no FSAL reuse
            sum.accept();
            self.k0_valid = false;
        } else if self.fsal {
            let s = self.k.len();
            self.k.swap(0, s - 1);
        } else {
            self.k0_valid = false;
        }
    }

    fn reset(&mut self) {
        self.k0_valid = false;
        if let Some(dense) = self.dense.as_mut() {
            dense.of_step = None;
        }
        if let Some(sum) = self.compensated.as_mut() {
            sum.reset();
        }
    }

    fn set_compensated(&mut self, on: bool) -> Result<(), Error> {
        super::compensated::switch(&mut self.compensated, on, || {
            Box::new(CompensatedCombination::new(self.stages.weights(), &self.k[0]))
        });
        Ok(())
    }

    /// The first stage's derivative when the next step reuses it (FSAL), and the carry.
    fn save(&self) -> StepperState {
        let mut state = StepperState::of(self.stages.info().name);
        state.flag("k0_valid", self.k0_valid);
        if self.k0_valid {
            state.state("k0", &self.k[0]);
        }
        super::compensated::save_form(self.compensated.as_deref(), &mut state);
        state
    }

    fn restore(&mut self, state: &StepperState) -> Result<(), Error> {
        state.check_method(&self.stages.info().name)?;
        self.k0_valid = state.read_flag("k0_valid")?;
        if self.k0_valid {
            state.read_state("k0", &mut self.k[0])?;
        }
        super::compensated::restore_form(self.compensated.as_deref_mut(), state)
    }

    fn counters(&self) -> Counters {
        self.counters
    }
}
