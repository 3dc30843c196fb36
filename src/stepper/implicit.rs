//! Implicit Runge-Kutta: the stage equations solved by fixed-point iteration or by
//! simplified Newton iteration.
//!
//! One step of an `s`-stage tableau from `(t, y)` with step `h` solves, for the stage
//! increments `Z_i = Y_i - y`,
//!
//! ```text
//! Z_i = h sum_j a_ij f(t + c_j h, y + Z_j),     i = 1..s            (1)
//! ```
//!
//! and then forms `y_new = y + h sum_i b_i f(Y_i)` (see [`ImplicitRk`] for the variants
//! used when the tableau allows a better formula). Working with the increments `Z`
//! rather than the stage values `Y` keeps round-off small (Hairer & Wanner, *Solving
//! ODEs II*, IV.8).

mod newton;

use super::compensated::CompensatedSum;
use super::{Counters, Stepper, StepperState, Tolerances};
use crate::method::{MethodInfo, Tableau};
use crate::real::magnitude;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::{Error, Problem, Real, State};
use newton::Newton;

/// How the stage equations (1) are solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ImplicitSolver {
    /// Fixed-point iteration `Z <- h (A ⊗ I) F(Z)` until the update is below the
    /// tolerance. Costs `s` evaluations per sweep and no linear algebra; converges only
    /// when `|h| L rho(A) < 1` (L = Lipschitz constant of `f`), i.e. on non-stiff problems
    /// with moderate steps. This is the classical choice for symplectic Gauss methods on
    /// Hamiltonian problems (Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
    /// VIII.6) and the scheme of docs/scenes.md 6.
    #[default]
    FixedPoint,
    /// Simplified Newton iteration (Hairer & Wanner, *Solving ODEs II*, IV.8): the Jacobian
    /// `J = df/dy` at `(t, y)` by forward differences, the `(s n) x (s n)` matrix
    /// `I - h (A ⊗ J)` factorised once per step (nalgebra's LU with partial pivoting),
    /// then `Z <- Z + dZ` with `(I - h A ⊗ J) dZ = -Z + h (A ⊗ I) F(Z)`. Converges on
    /// stiff problems, whatever `h L`. Its dense matrices grow as the square of the
    /// dimension: a problem whose matrices would take more than
    /// [`ImplicitOptions::newton_memory`] is refused before anything is allocated.
    Newton,
}

/// Options of the implicit solver.
///
/// With `Δ_k` the max-norm of the `k`-th update `Z^k - Z^{k-1}` and `σ = 1 + max_j |y_j|`
/// (`y` = the state at the start of the step), both solvers stop when
///
/// - `Δ_k <= tol σ`, or
/// - the iteration has reached round-off: `Δ_k >= Δ_{k-1}` while `Δ_k <= 100 ε σ`
///   (`ε` = the scalar's machine epsilon): the update stopped decreasing, what is left is
///   rounding noise (Hairer, Lubich & Wanner, *Geometric Numerical Integration*, VIII.6,
///   "iterate until round-off"), or
/// - the error left is negligible: with the observed rate `θ_k = Δ_k / Δ_{k-1} < 1`, the
///   remaining error `θ_k / (1 - θ_k) Δ_k` (Hairer & Wanner, *Solving ODEs II*, IV.8) is at
///   most `ε σ / 100`. This ends a fast (Newton) iteration as soon as it has converged,
///   and one whose updates keep shrinking below the noise of the large components
///   because a tiny component still converges.
///
/// They return [`Error::SolverDiverged`] — never an unconverged number — when neither has
/// happened after `max_iterations` iterations, or as soon as an update is not finite.
///
/// `tol = 0` (the default) means *to round-off*, in `f32` as in `f64`. It is the right
/// default for the methods this crate runs at fixed steps for their structure: a
/// symplectic Gauss method keeps quadratic invariants only for the exact stage solution,
/// and an iteration stopped early leaves an error of the same sign at every step. On the
/// harmonic oscillator (midpoint rule, `h = 0.5`, fixed point, 10^4 steps) `tol = 1e-14`
/// drifts the invariant linearly to `3e-11`, and even stopping at `Δ_k <= ε σ` leaves
/// `1.5e-12`; to round-off it stays at the level of a random walk of rounding errors. A
/// `tol > 0` trades that for fewer iterations when only the order of the method matters.
///
/// ```
/// use stormer::stepper::{ImplicitOptions, ImplicitSolver};
/// let stiff = ImplicitOptions::newton();
/// assert_eq!(stiff.solver, ImplicitSolver::Newton);
/// assert_eq!(ImplicitOptions::default(), ImplicitOptions::fixed_point());
/// let loose = ImplicitOptions { tol: 1e-10, ..ImplicitOptions::newton() };
/// assert_eq!(loose.max_iterations, ImplicitOptions::newton().max_iterations);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImplicitOptions {
    /// Solver choice.
    pub solver: ImplicitSolver,
    /// Stop when the max-norm of the stage update is at most `tol * (1 + max|y|)`;
    /// `0` (or negative, or not finite) iterates to round-off.
    pub tol: f64,
    /// Give up (an error, never a wrong number) after this many iterations.
    pub max_iterations: usize,
    /// The most memory, in bytes, Newton's dense matrices may take: the `n x n` Jacobian
    /// and the `(s n) x (s n)` matrix `I - h A ⊗ J`, `s` stages of `n` components. A
    /// larger problem is refused ([`Error::Unsupported`], naming the size and the
    /// fixed-point solver) at its first Newton step, before anything is allocated, rather
    /// than aborted by a failed allocation. [`ImplicitOptions::NEWTON_MEMORY`] by default.
    pub newton_memory: usize,
}

impl ImplicitOptions {
    /// Default tolerance of both solvers: `0`, iterate to round-off (see above).
    pub const DEFAULT_TOL: f64 = 0.0;

    /// Default [`ImplicitOptions::newton_memory`]: 1 GiB, Newton's matrices for about 5000
    /// components with 2 stages (gauss_legendre4), 3700 with 3 (`5 n^2` and `10 n^2`
    /// numbers of 8 bytes).
    pub const NEWTON_MEMORY: usize = 1 << 30;

    /// Fixed-point iteration to round-off, at most 100 sweeps (the default options).
    ///
    /// A sweep multiplies the error by about `q = |h| L rho(A)`; 100 sweeps gain the 16
    /// digits of `f64` from a zero start as long as `q <~ 0.7`. A step that needs more is
    /// too large for fixed-point iteration: use Newton or a smaller `h`.
    pub fn fixed_point() -> Self {
        ImplicitOptions {
            solver: ImplicitSolver::FixedPoint,
            tol: Self::DEFAULT_TOL,
            max_iterations: 100,
            newton_memory: Self::NEWTON_MEMORY,
        }
    }

    /// Simplified Newton to round-off, at most 50 iterations.
    ///
    /// Hairer & Wanner's RADAU5 allows 7 Newton iterations, but it stops at a fraction of
    /// its (much looser) local error tolerance and can reject the step when convergence is
    /// slow. Here the step is the user's, and the target is round-off: simplified Newton
    /// converges linearly at a rate `θ` set by how much `J` changes over the step, so it
    /// needs about `16 / -log10(θ)` iterations. On smooth problems at moderate `h`
    /// (`θ ~ 1e-3`) that is 2 to 6 (the tests measure 2 to 4 per step on average); a
    /// coarse step of a strongly nonlinear problem takes more (Hairer's 4-D problem at
    /// `h = 0.25`: 12 to 21 iterations to round-off). The cap of 50 covers `θ` up to
    /// `~0.5`: beyond, the step is too large for a Jacobian frozen at its start.
    pub fn newton() -> Self {
        ImplicitOptions {
            solver: ImplicitSolver::Newton,
            tol: Self::DEFAULT_TOL,
            max_iterations: NEWTON_MAX,
            newton_memory: Self::NEWTON_MEMORY,
        }
    }
}

/// [`ImplicitOptions::newton`]'s iteration cap.
const NEWTON_MAX: usize = 50;

/// The stopping rule of both solvers within one step (see [`ImplicitOptions`]).
#[derive(Debug, Clone, Copy)]
struct Stop<T> {
    /// `tol σ`.
    tol: T,
    /// `100 ε σ`: an update that stops decreasing below this is rounding noise.
    round_off: T,
    /// `ε σ / 100`: a remaining error below this is negligible.
    negligible: T,
    previous: Option<T>,
}

impl<T: Real> Stop<T> {
    /// The rule's factors for `σ = 1` (converted to `T` once, when the stepper is built).
    fn factors(tol: T) -> Self {
        let eps = T::default_epsilon();
        Stop {
            tol,
            round_off: lit::<T>(100.0) * eps,
            negligible: lit::<T>(0.01) * eps,
            previous: None,
        }
    }

    /// The rule for a step from `y`: the factors times `σ = 1 + max|y|`.
    fn for_step(&self, y: &[T]) -> Self {
        let sigma = T::one() + y.iter().fold(T::zero(), |m, x| m.max(x.abs()));
        Stop {
            tol: self.tol * sigma,
            round_off: self.round_off * sigma,
            negligible: self.negligible * sigma,
            previous: None,
        }
    }

    /// Whether an update of size `delta` ends the iteration.
    fn converged(&mut self, delta: T) -> bool {
        let done = delta <= self.tol
            || match self.previous {
                // Stalled: what is left is rounding noise.
                Some(p) if delta >= p => delta <= self.round_off,
                // Contracting at the rate θ = delta / p: the remaining error is about
                // θ / (1 - θ) delta = delta^2 / (p - delta).
                Some(p) => delta * delta <= self.negligible * (p - delta),
                None => false,
            };
        self.previous = Some(delta);
        done
    }
}

impl Default for ImplicitOptions {
    /// [`ImplicitOptions::fixed_point`]: no linear algebra, no allocation per step.
    fn default() -> Self {
        ImplicitOptions::fixed_point()
    }
}

/// A row of the stage matrix without its zero entries: `(column, a_ij)`.
type Row<T> = Vec<(usize, T)>;

/// How `y_new` is formed from the converged stages.
#[derive(Debug, Clone)]
enum Update<T> {
    /// Stiffly accurate tableau (last row of `A` = `b`): `y_new = y + Z_s`.
    LastStage,
    /// `y_new = y + h sum_i b_i F_i` with the last evaluated stage derivatives.
    Weights,
    /// Newton on a tableau with invertible `A`: `y_new = y + sum_i d_i Z_i`, `d = b^T A^-1`.
    Inverse(Vec<T>),
}

/// The starting guess for `Z`: the previous step's stage polynomial, extrapolated.
///
/// The last accepted step's increments `Z_j` and `0` at `theta = 0` define the polynomial
/// `P(theta)` of degree <= s through `(0, 0)` and `(c_j, Z_j)` (distinct non-zero nodes
/// only); for a collocation method it is the collocation polynomial, `y_old + P(theta)`
/// approximating the solution at `t_old + theta h_old`. The new stage `i` lies at
/// `theta = 1 + c_i r`, `r = h / h_old`, so the guess is `Z_i = P(1 + c_i r) - P(1)`, a
/// fixed linear combination `sum_j e_ij(r) Z_j^old` (RADAU5's default starting values;
/// Hairer & Wanner, IV.8). It is used only for `0 < r <= 2`; otherwise, after
/// [`Stepper::reset`], and on the first step, the guess is `Z = 0`. The guess changes
/// only the number of iterations, not what they converge to.
#[derive(Debug, Clone)]
struct Extrapolation<S: State> {
    enabled: bool,
    /// Stages whose node is distinct from 0 and from the nodes before it.
    nodes: Vec<usize>,
    /// `Z` of the last accepted step.
    previous: Vec<S>,
    h_previous: S::Scalar,
    valid: bool,
    /// The ratio `coef` was computed for.
    ratio: Option<S::Scalar>,
    /// `e_ij`, `s x s` row-major (zero outside the node columns).
    coef: Vec<S::Scalar>,
}

/// Stepper for an implicit (or any) [`Tableau`], solving the stage equations by
/// fixed-point iteration or simplified Newton ([`ImplicitSolver`]).
///
/// **Final update.** `y_new = y + h sum_i b_i f(Y_i)`, with the stage derivatives of the
/// last iteration, except:
/// - for a *stiffly accurate* tableau (last row of `A` equal to `b`: backward Euler,
///   trapezoid, Radau IIA, Lobatto IIIA and IIIC), `y_new = y + Z_s`, the last stage
///   itself. Equal to the formula above for the exact stages, but it never multiplies
///   `f` by `h` after the solve, which for stiff problems would amplify the iteration
///   error by `h L` (Hairer & Wanner, IV.8);
/// - with Newton and an invertible `A` that is not stiffly accurate (the Gauss methods),
///   `y_new = y + sum_i d_i Z_i` with `d^T = b^T A^{-1}` (Hairer & Wanner, IV.8, same
///   reason).
///
/// Stages whose row of `A` is zero (Lobatto IIIA's and the trapezoid's first stage) are
/// explicit: their `Z_i = 0` and `f(t, y)` is evaluated once per step, not per iteration.
///
/// **Starting guess**: the previous step's stage polynomial extrapolated (RADAU5's
/// default), or zero; see [`ImplicitRk::extrapolate`].
///
/// **Counters**: every right-hand-side evaluation (stage sweeps, the `n + 1` of each
/// finite-difference Jacobian, the explicit stage), every iteration (fixed-point sweep
/// or Newton iteration, failed steps included) and every Jacobian.
///
/// **Allocation**: buffers are allocated by [`ImplicitRk::new`]. The fixed-point path
/// never allocates after that (for static states: not at all). The Newton workspace
/// (`n x n` Jacobian, `(s n) x (s n)` matrix, right-hand side) is allocated on the first
/// Newton step and reused, unless its matrices would exceed
/// [`ImplicitOptions::newton_memory`]: that step is then refused with
/// [`Error::Unsupported`]; the matrix storage is recovered from the previous step's
/// factorisation. What remains is nalgebra's: `LU::new` builds a fresh pivot sequence
/// (`s n` index pairs), one small allocation per Newton step.
///
/// **Adaptive steps**: a tableau with embedded weights `b_hat` (the trapezoid) reports the
/// estimate `h sum_i (b_i - b_hat_i) f(Y_i)` and works with [`crate::Driver::adaptive`];
/// the others are fixed-step only.
///
/// ```
/// use stormer::{Problem, Stepper};
/// use stormer::catalog::GaussLegendre4;
/// use stormer::method::{ButcherMethod, Tableau};
/// use stormer::stepper::{ImplicitOptions, ImplicitRk};
/// /// The harmonic oscillator x'' = -x.
/// struct Oscillator;
/// impl Problem for Oscillator {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
///         *dy = [y[1], -y[0]];
///     }
/// }
/// let tableau = Tableau::from_data(&GaussLegendre4::DATA).unwrap();
/// let y0 = [1.0, 0.0];
/// let mut gl4 = ImplicitRk::new(&tableau, &y0, ImplicitOptions::default());
/// let (mut y, mut y_new) = (y0, y0);
/// for i in 0..1000 {
///     gl4.step(&Oscillator, i as f64 * 0.1, 0.1, &y, &mut y_new).unwrap();
///     Stepper::<Oscillator>::accept(&mut gl4);
///     std::mem::swap(&mut y, &mut y_new);
/// }
/// // Symplectic: the quadratic invariant x^2 + v^2 is kept to round-off...
/// assert!((y[0] * y[0] + y[1] * y[1] - 1.0).abs() < 1e-13);
/// // ...and the phase is fourth-order accurate.
/// assert!((y[0] - 100f64.cos()).abs() < 1e-4);
/// ```
#[derive(Debug, Clone)]
pub struct ImplicitRk<S: State> {
    info: MethodInfo,
    options: ImplicitOptions,
    /// The stopping rule's factors (`σ = 1`).
    stop: Stop<S::Scalar>,
    /// Largest step ratio `h / h_old` for which the starting guess is extrapolated.
    max_ratio: S::Scalar,
    error_order: Option<usize>,
    /// Rows of `A` without zeros (an empty row is an explicit stage).
    rows: Vec<Row<S::Scalar>>,
    /// `A`, `s x s` row-major, for the Newton matrix.
    a: Vec<S::Scalar>,
    b: Row<S::Scalar>,
    c: Vec<S::Scalar>,
    /// `b - b_hat` without zeros, when the tableau has embedded weights.
    e: Option<Row<S::Scalar>>,
    update: Update<S::Scalar>,
    /// Stage increments `Z_i = Y_i - y`.
    z: Vec<S>,
    /// `f` at the stages, as last evaluated.
    f: Vec<S>,
    stage: S,
    err: S,
    guess: Extrapolation<S>,
    newton: Option<Newton<S>>,
    /// `h` of the last successful step (what [`Stepper::accept`] keeps).
    last_h: Option<S::Scalar>,
    /// The method's own continuous extension (a collocation method's polynomial): the
    /// stages whose `b_i(theta)` is not zero, with its coefficients of theta^1 .. theta^m.
    dense: Option<Vec<(usize, Vec<S::Scalar>)>>,
    /// The final update added with a carry, when compensated summation is on.
    compensated: Option<CompensatedSum<S>>,
    counters: Counters,
}

/// `|x - y| <= 4 ε max(1, |y|)` in `f64`: equal coefficients written differently.
fn same(x: f64, y: f64) -> bool {
    (x - y).abs() <= 4.0 * f64::EPSILON * y.abs().max(1.0)
}

fn row<T: Real>(values: impl IntoIterator<Item = f64>) -> Row<T> {
    values
        .into_iter()
        .enumerate()
        .filter(|&(_, x)| x != 0.0)
        .map(|(j, x)| (j, lit(x)))
        .collect()
}

/// `d = b^T A^{-1}` when `A` is invertible and `d` is moderate.
fn inverse_weights(a: &[f64], b: &[f64]) -> Option<Vec<f64>> {
    let s = b.len();
    let inv = nalgebra::DMatrix::from_row_slice(s, s, a).try_inverse()?;
    let d: Vec<f64> = (0..s).map(|j| (0..s).map(|i| b[i] * inv[(i, j)]).sum()).collect();
    d.iter().all(|x| x.is_finite() && x.abs() < 1e8).then_some(d)
}

/// The tolerance factor: `tol`, or `0` (to round-off) when it is not finite or negative.
fn effective_tol<T: Real>(tol: f64) -> T {
    if tol.is_finite() && tol > 0.0 {
        lit(tol)
    } else {
        T::zero()
    }
}

impl<T: Real, S: State<Scalar = T>> ImplicitRk<S> {
    /// A stepper for `tableau` with stage buffers shaped like `y0`.
    ///
    /// Coefficients are converted to the scalar type here, once. Any valid tableau works,
    /// explicit ones included (fixed-point iteration then converges in at most `s` sweeps).
    pub fn new(tableau: &Tableau, y0: &S, options: ImplicitOptions) -> Self {
        let s = tableau.stages();
        let (a, b, c) = (tableau.a(), tableau.b(), tableau.c());
        let stiffly_accurate = (0..s).all(|j| same(a[(s - 1) * s + j], b[j]));
        let update = if stiffly_accurate {
            Update::LastStage
        } else {
            match (options.solver, inverse_weights(a, b)) {
                (ImplicitSolver::Newton, Some(d)) => Update::Inverse(d.into_iter().map(lit).collect()),
                _ => Update::Weights,
            }
        };
        let mut nodes: Vec<usize> = Vec::new();
        for i in 0..s {
            if c[i] != 0.0 && nodes.iter().all(|&j| !same(c[j], c[i])) {
                nodes.push(i);
            }
        }
        let zero = y0.zeros_like();
        ImplicitRk {
            info: tableau.info(),
            options,
            stop: Stop::factors(effective_tol(options.tol)),
            max_ratio: lit(2.0),
            error_order: tableau.b_hat().and(tableau.embedded_order()),
            rows: a.chunks(s).map(|r| row(r.iter().copied())).collect(),
            a: a.iter().map(|&x| lit(x)).collect(),
            b: row(b.iter().copied()),
            c: c.iter().map(|&x| lit(x)).collect(),
            e: tableau.b_hat().map(|bh| row(b.iter().zip(bh).map(|(b, bh)| b - bh))),
            update,
            z: vec![zero.clone(); s],
            f: vec![zero.clone(); s],
            stage: zero.clone(),
            err: zero.clone(),
            guess: Extrapolation {
                enabled: true,
                nodes,
                previous: vec![zero; s],
                h_previous: S::Scalar::zero(),
                valid: false,
                ratio: None,
                coef: vec![S::Scalar::zero(); s * s],
            },
            newton: None,
            last_h: None,
            dense: tableau.dense().map(|rows| {
                let nonzero = rows.iter().enumerate().filter(|(_, row)| row.iter().any(|&d| d != 0.0));
                nonzero
                    .map(|(i, row)| (i, row.iter().map(|&d| lit(d)).collect()))
                    .collect()
            }),
            compensated: None,
            counters: Counters::default(),
        }
    }

    /// Turns the extrapolated starting guess on (the default) or off (`Z = 0` every step,
    /// which RADAU5 recommends when Newton struggles on very stiff problems, where the
    /// previous step's polynomial says little about the next one).
    pub fn extrapolate(mut self, on: bool) -> Self {
        self.guess.enabled = on;
        self.guess.valid = false;
        self
    }

    /// The options this stepper was built with.
    pub fn options(&self) -> &ImplicitOptions {
        &self.options
    }

    /// Writes the starting guess into `z`.
    fn start(&mut self, h: S::Scalar) {
        let s = self.z.len();
        for z in &mut self.z {
            // Not `scale(0)`: a failed step may have left NaN behind.
            z.as_mut_slice().fill(S::Scalar::zero());
        }
        let g = &mut self.guess;
        if !(g.enabled && g.valid && !g.nodes.is_empty()) {
            return;
        }
        let r = h / g.h_previous;
        if !(r > S::Scalar::zero() && r <= self.max_ratio) {
            return;
        }
        if g.ratio != Some(r) {
            // e_ij = l_j(1 + c_i r) - l_j(1), l_j the Lagrange basis on {0} ∪ {c_k : k in nodes}.
            let lagrange = |j: usize, x: S::Scalar| {
                let cj = self.c[j];
                let mut l = x / cj;
                for &k in &g.nodes {
                    if k != j {
                        l *= (x - self.c[k]) / (cj - self.c[k]);
                    }
                }
                l
            };
            for i in 0..s {
                for j in 0..s {
                    g.coef[i * s + j] = S::Scalar::zero();
                }
                if self.rows[i].is_empty() {
                    continue;
                }
                let x = S::Scalar::one() + self.c[i] * r;
                for &j in &g.nodes {
                    g.coef[i * s + j] = lagrange(j, x) - lagrange(j, S::Scalar::one());
                }
            }
            g.ratio = Some(r);
        }
        for i in 0..s {
            for &j in &g.nodes {
                let e = g.coef[i * s + j];
                if e != S::Scalar::zero() {
                    self.z[i].axpy(e, &g.previous[j]);
                }
            }
        }
    }

    /// `f` at the implicit stages (the explicit ones keep `f(t, y)`).
    fn evaluate<P: Problem<Scalar = S::Scalar, State = S>>(&mut self, p: &P, t: S::Scalar, h: S::Scalar, y: &S) {
        for i in 0..self.z.len() {
            if self.rows[i].is_empty() {
                continue;
            }
            self.stage.copy_from(y);
            self.stage.axpy(S::Scalar::one(), &self.z[i]);
            p.rhs(t + self.c[i] * h, &self.stage, &mut self.f[i]);
            self.counters.evaluations += 1;
        }
    }

    /// `f(t, y)` into the explicit stages' slots (one evaluation, or a copy of `f0`).
    fn explicit_stages<P: Problem<Scalar = S::Scalar, State = S>>(
        &mut self,
        p: &P,
        t: S::Scalar,
        y: &S,
        f0: Option<&S>,
    ) {
        let Some(first) = self.rows.iter().position(Vec::is_empty) else {
            return;
        };
        match f0 {
            Some(f0) => self.f[first].copy_from(f0),
            None => {
                p.rhs(t, y, &mut self.f[first]);
                self.counters.evaluations += 1;
            }
        }
        for i in first + 1..self.z.len() {
            if self.rows[i].is_empty() {
                let (done, rest) = self.f.split_at_mut(i);
                rest[0].copy_from(&done[first]);
            }
        }
    }

    /// Fixed-point sweeps `Z_i <- h sum_j a_ij F_j(Z)` until `stop` says so.
    fn fixed_point<P: Problem<Scalar = T, State = S>>(
        &mut self,
        p: &P,
        t: T,
        h: T,
        y: &S,
        stop: Stop<T>,
    ) -> Result<(), Error> {
        self.explicit_stages(p, t, y, None);
        self.iterate(t, stop, |this| {
            this.evaluate(p, t, h, y);
            let mut residual = S::Scalar::zero();
            let mut bad = None;
            for (i, row) in this.rows.iter().enumerate() {
                if row.is_empty() {
                    continue;
                }
                let zi = this.z[i].as_mut_slice();
                for m in 0..zi.len() {
                    let mut sum = S::Scalar::zero();
                    for &(j, a) in row {
                        sum += a * this.f[j].as_slice()[m];
                    }
                    let new = h * sum;
                    let d = magnitude(new - zi[m]);
                    if !d.is_finite() {
                        bad = Some(d);
                    }
                    if d > residual {
                        residual = d;
                    }
                    zi[m] = new;
                }
            }
            // a change that is not finite is the divergence reported, not the largest one
            Some(bad.unwrap_or(residual))
        })
    }

    /// Simplified Newton iterations until `stop` says so.
    fn newton<P: Problem<Scalar = S::Scalar, State = S>>(
        &mut self,
        p: &P,
        t: S::Scalar,
        h: S::Scalar,
        y: &S,
        stop: Stop<S::Scalar>,
    ) -> Result<(), Error> {
        let s = self.z.len();
        // Allocated on the first Newton step, then reused; refused before if too large.
        let mut newton = match self.newton.take() {
            Some(newton) => newton,
            None => {
                newton::check_memory::<S::Scalar>(&self.info.name, y.dim(), s, self.options.newton_memory)?;
                Newton::new(y, s)
            }
        };
        self.counters.evaluations += newton.jacobian(p, t, y);
        self.counters.jacobians += 1;
        let invertible = newton.factor(h, &self.a, s);
        self.explicit_stages(p, t, y, Some(newton.f0()));
        let result = if invertible {
            self.iterate(t, stop, |this| {
                this.evaluate(p, t, h, y);
                newton.correct(h, &this.rows, &mut this.z, &this.f)
            })
        } else {
            Err(diverged(t, f64::INFINITY, 0))
        };
        self.newton = Some(newton);
        result
    }

    /// Repeats `sweep` (one correction of the stages of the step from `t`, from fresh
    /// derivatives, returning the size of the change, `None` when it cannot be made) until
    /// `stop` says so; a change that is not finite or cannot be made is a divergence.
    fn iterate(&mut self, t: T, mut stop: Stop<T>, mut sweep: impl FnMut(&mut Self) -> Option<T>) -> Result<(), Error> {
        let mut residual = S::Scalar::zero();
        for iteration in 1..=self.options.max_iterations {
            self.counters.solver_iterations += 1;
            match sweep(self) {
                Some(r) if r.is_finite() => residual = r,
                Some(r) => return Err(diverged(t, to_f64(r), iteration)),
                None => return Err(diverged(t, f64::INFINITY, iteration)),
            }
            if stop.converged(residual) {
                return Ok(());
            }
        }
        Err(diverged(t, to_f64(residual), self.options.max_iterations))
    }

    /// `y_new` from the converged stages.
    fn finish(&mut self, h: S::Scalar, y: &S, y_new: &mut S) {
        if let Some(mut sum) = self.compensated.take() {
            sum.add_with(y, y_new, |delta| self.increment(h, |m, inc| delta[m] = inc));
            self.compensated = Some(sum);
        } else {
            let (out, y) = (y_new.as_mut_slice(), y.as_slice());
            self.increment(h, |m, inc| out[m] = y[m] + inc);
        }
    }

    /// The step's increment `y_new - y`, component `m` handed to `put(m, increment)`.
    #[inline(always)]
    fn increment(&self, h: S::Scalar, mut put: impl FnMut(usize, S::Scalar)) {
        let dim = self.stage.dim();
        match &self.update {
            Update::LastStage => {
                let zs = self.z[self.z.len() - 1].as_slice();
                for (m, &z) in zs.iter().enumerate() {
                    put(m, z);
                }
            }
            Update::Weights => {
                for m in 0..dim {
                    let mut sum = S::Scalar::zero();
                    for &(i, b) in &self.b {
                        sum += b * self.f[i].as_slice()[m];
                    }
                    put(m, h * sum);
                }
            }
            Update::Inverse(d) => {
                for m in 0..dim {
                    let mut sum = S::Scalar::zero();
                    for (i, &d) in d.iter().enumerate() {
                        sum += d * self.z[i].as_slice()[m];
                    }
                    put(m, sum);
                }
            }
        }
    }
}

fn diverged<T: Real>(t: T, residual: f64, iterations: usize) -> Error {
    Error::SolverDiverged {
        t: to_f64(t),
        residual,
        iterations,
    }
}

impl<P: Problem> Stepper<P> for ImplicitRk<P::State> {
    fn info(&self) -> MethodInfo {
        self.info.clone()
    }

    fn error_order(&self) -> Option<usize> {
        self.error_order
    }

    fn step(&mut self, p: &P, t: P::Scalar, h: P::Scalar, y: &P::State, y_new: &mut P::State) -> Result<(), Error> {
        self.last_h = None;
        self.start(h);
        let stop = self.stop.for_step(y.as_slice());
        if self.rows.iter().all(Vec::is_empty) {
            // An explicit tableau with all rows zero (explicit Euler): nothing to solve.
            self.explicit_stages(p, t, y, None);
        } else {
            match self.options.solver {
                ImplicitSolver::FixedPoint => self.fixed_point(p, t, h, y, stop)?,
                ImplicitSolver::Newton => self.newton(p, t, h, y, stop)?,
            }
        }
        self.finish(h, y, y_new);
        self.last_h = Some(h);
        Ok(())
    }

    /// `y + h sum_i b_i(theta) f(Y_i)` with the method's own `b_i(theta)` (a collocation
    /// method's polynomial: order `s` for every theta), `f` as last evaluated: at the solver's
    /// last iterate, within its tolerance of the converged stages.
    fn interpolate(&mut self, _p: &P, _t: P::Scalar, theta: P::Scalar, y: &P::State, out: &mut P::State) -> bool {
        let (Some(h), Some(dense)) = (self.last_h, self.dense.as_ref()) else {
            return false;
        };
        out.copy_from(y);
        for (i, row) in dense {
            // b_i(theta) = theta (d_1 + theta (d_2 + ...)), Horner
            let weight = row.iter().rev().fold(P::Scalar::zero(), |w, &d| (w + d) * theta);
            out.axpy(h * weight, &self.f[*i]);
        }
        true
    }

    fn error_norm(&mut self, y: &P::State, y_new: &P::State, tol: &Tolerances<P::Scalar>) -> Option<P::Scalar> {
        let (h, e) = (self.last_h?, self.e.as_ref()?);
        let err = self.err.as_mut_slice();
        for m in 0..err.len() {
            let mut sum = P::Scalar::zero();
            for &(i, w) in e {
                sum += w * self.f[i].as_slice()[m];
            }
            err[m] = h * sum;
        }
        Some(tol.rms(y, y_new, &self.err))
    }

    fn accept(&mut self) {
        if let Some(sum) = self.compensated.as_mut() {
            sum.accept();
        }
        if let Some(h) = self.last_h.take() {
            let g = &mut self.guess;
            for (prev, z) in g.previous.iter_mut().zip(&self.z) {
                prev.copy_from(z);
            }
            g.h_previous = h;
            g.valid = g.enabled;
        }
    }

    fn reset(&mut self) {
        self.guess.valid = false;
        self.last_h = None;
        if let Some(sum) = self.compensated.as_mut() {
            sum.reset();
        }
    }

    fn set_compensated(&mut self, on: bool) -> Result<(), Error> {
        super::compensated::switch(&mut self.compensated, on, || CompensatedSum::new(&self.stage));
        Ok(())
    }

    /// The last accepted step's stage increments and size (the next step's starting
    /// guess), and the carry.
    fn save(&self) -> StepperState {
        let mut state = StepperState::of(self.info.name.clone());
        let g = &self.guess;
        state.flag("guess_valid", g.valid);
        if g.valid {
            state.values("h_previous", &[g.h_previous]);
            for (i, z) in g.previous.iter().enumerate() {
                state.state(&format!("z{i}"), z);
            }
        }
        super::compensated::save_form(self.compensated.as_ref(), &mut state);
        state
    }

    fn restore(&mut self, state: &StepperState) -> Result<(), Error> {
        state.check_method(&self.info.name)?;
        self.last_h = None;
        let g = &mut self.guess;
        g.valid = state.read_flag("guess_valid")?;
        if g.valid {
            let mut h = [g.h_previous];
            state.read_values("h_previous", &mut h)?;
            g.h_previous = h[0];
            for (i, z) in g.previous.iter_mut().enumerate() {
                state.read_state(&format!("z{i}"), z)?;
            }
        }
        super::compensated::restore_form(self.compensated.as_mut(), state)
    }

    fn counters(&self) -> Counters {
        self.counters
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalog::*;
    use crate::method::ButcherMethod;

    fn stepper<M: ButcherMethod>(solver: ImplicitSolver) -> ImplicitRk<[f64; 1]> {
        let options = ImplicitOptions {
            solver,
            ..ImplicitOptions::default()
        };
        ImplicitRk::new(&Tableau::from_data(&M::DATA).unwrap(), &[0.0], options)
    }

    fn update<M: ButcherMethod>(solver: ImplicitSolver) -> &'static str {
        match stepper::<M>(solver).update {
            Update::LastStage => "last stage",
            Update::Weights => "weights",
            Update::Inverse(_) => "inverse",
        }
    }

    #[test]
    fn the_final_update_follows_the_tableau() {
        use ImplicitSolver::{FixedPoint, Newton};
        for solver in [FixedPoint, Newton] {
            assert_eq!(update::<BackwardEuler>(solver), "last stage");
            assert_eq!(update::<Trapezoidal>(solver), "last stage");
            assert_eq!(update::<RadauIia3>(solver), "last stage");
            assert_eq!(update::<RadauIia5>(solver), "last stage");
            assert_eq!(update::<LobattoIiia4>(solver), "last stage");
            assert_eq!(update::<LobattoIiic4>(solver), "last stage");
            // A singular (last column zero) and not stiffly accurate.
            assert_eq!(update::<LobattoIiib4>(solver), "weights");
        }
        for gauss in [
            update::<ImplicitMidpoint>,
            update::<GaussLegendre4>,
            update::<GaussLegendre6>,
        ] {
            assert_eq!(gauss(FixedPoint), "weights");
            assert_eq!(gauss(Newton), "inverse");
        }
        // d = b^T A^-1 = [-sqrt 3, sqrt 3] for the two-stage Gauss method, 2 for the midpoint rule.
        let Update::Inverse(d) = stepper::<GaussLegendre4>(Newton).update else {
            unreachable!()
        };
        assert!(
            (d[0] + 3f64.sqrt()).abs() < 1e-14 && (d[1] - 3f64.sqrt()).abs() < 1e-14,
            "{d:?}"
        );
        let Update::Inverse(d) = stepper::<ImplicitMidpoint>(Newton).update else {
            unreachable!()
        };
        assert!((d[0] - 2.0).abs() < 1e-15);
    }

    #[test]
    fn the_extrapolated_guess_is_exact_on_polynomials_of_the_stage_degree() {
        // Radau IIA5 (nodes 0, c1, c2, 1): if Z_j = p(c_j) for a cubic p with p(0) = 0,
        // the guess for the next step is p(1 + c_i r) - p(1) exactly (up to rounding).
        let mut st = stepper::<RadauIia5>(ImplicitSolver::FixedPoint);
        let p = |x: f64| 0.3 * x - 0.2 * x * x + 0.05 * x * x * x;
        let c = [st.c[0], st.c[1], st.c[2]];
        for j in 0..3 {
            st.guess.previous[j] = [p(c[j])];
        }
        st.guess.h_previous = 0.1;
        st.guess.valid = true;
        for h in [0.1, 0.05, 0.2] {
            st.start(h);
            let r = h / 0.1;
            for i in 0..3 {
                let expected = p(1.0 + c[i] * r) - p(1.0);
                assert!(
                    (st.z[i][0] - expected).abs() < 1e-14,
                    "r = {r}, stage {i}: {} vs {expected}",
                    st.z[i][0]
                );
            }
        }
        // Beyond the ratio limit, or after reset: zero.
        st.start(0.5);
        assert!(st.z.iter().all(|z| z[0] == 0.0));
        Stepper::<Unit>::reset(&mut st);
        st.start(0.1);
        assert!(st.z.iter().all(|z| z[0] == 0.0));
    }

    struct Unit;
    impl Problem for Unit {
        type Scalar = f64;
        type State = [f64; 1];
        fn rhs(&self, _t: f64, _y: &[f64; 1], dy: &mut [f64; 1]) {
            dy[0] = 1.0;
        }
    }

    #[test]
    fn the_stopping_rule() {
        let factors = Stop::factors(0.0);
        // A contracting iteration stops once the remaining error is below eps sigma / 100.
        let mut stop = factors.for_step(&[1.0]);
        assert!(!stop.converged(1e-3));
        assert!(!stop.converged(1e-6)); // theta = 1e-3: remaining ~1e-9
        assert!(stop.converged(1e-16)); // theta = 1e-10: remaining ~1e-26
                                        // Noise: an update that stops decreasing at round-off level.
        let mut stop = factors.for_step(&[1.0]);
        assert!(!stop.converged(1e-15));
        assert!(stop.converged(2e-15));
        // ... but not far above it.
        let mut stop = factors.for_step(&[1.0]);
        assert!(!stop.converged(1e-6));
        assert!(!stop.converged(2e-6));
        // A tolerance is a plain threshold on the update, relative to 1 + max|y|.
        let mut stop = Stop::factors(1e-8).for_step(&[-99.0]);
        assert!(!stop.converged(2e-6));
        assert!(stop.converged(1e-6));
    }
}
