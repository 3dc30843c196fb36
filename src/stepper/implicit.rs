//! Implicit Runge-Kutta: the stage equations solved by fixed-point iteration or Newton.

use super::{Counters, Stepper, Tolerances};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{lit, to_f64, Error, MethodInfo, Problem, Real, State, Tableau};

/// How the stage equations are solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ImplicitSolver {
    /// `Z <- h A F(Z)` repeated until the update is below the tolerance: cheap, but
    /// converges only for `h L` small (L = Lipschitz constant of f).
    #[default]
    FixedPoint,
    /// Simplified Newton with a finite-difference Jacobian and an LU factorisation
    /// (nalgebra), refreshed every step: converges on stiff problems.
    Newton,
}

/// Options of the implicit solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImplicitOptions {
    /// Solver choice.
    pub solver: ImplicitSolver,
    /// Stop when the max-norm of the stage update is below `tol * (1 + max|y|)`.
    pub tol: f64,
    /// Give up (an error, never a wrong number) after this many iterations.
    pub max_iterations: usize,
}

impl Default for ImplicitOptions {
    fn default() -> Self {
        ImplicitOptions {
            solver: ImplicitSolver::FixedPoint,
            tol: 1e-14,
            max_iterations: 100,
        }
    }
}

/// Stepper for an implicit (or any) [`Tableau`].
#[derive(Debug, Clone)]
pub struct ImplicitRk<S: State> {
    info: MethodInfo,
    options: ImplicitOptions,
    a: Vec<S::Scalar>,
    b: Vec<S::Scalar>,
    c: Vec<S::Scalar>,
    /// Stage increments Z_i = Y_i - y.
    z: Vec<S>,
    /// f at the stages.
    f: Vec<S>,
    stage: S,
    counters: Counters,
}

impl<S: State> ImplicitRk<S> {
    /// A stepper for `tableau` with buffers shaped like `y0`.
    pub fn new(tableau: &Tableau, y0: &S, options: ImplicitOptions) -> Self {
        let s = tableau.stages();
        ImplicitRk {
            info: tableau.info(),
            options,
            a: tableau.a().iter().map(|&x| lit(x)).collect(),
            b: tableau.b().iter().map(|&x| lit(x)).collect(),
            c: tableau.c().iter().map(|&x| lit(x)).collect(),
            z: vec![y0.zeros_like(); s],
            f: vec![y0.zeros_like(); s],
            stage: y0.zeros_like(),
            counters: Counters::default(),
        }
    }

    fn evaluate_stages<P: Problem<Scalar = S::Scalar, State = S>>(&mut self, p: &P, t: S::Scalar, h: S::Scalar, y: &S) {
        for i in 0..self.z.len() {
            self.stage.copy_from(y);
            self.stage.axpy(S::Scalar::one(), &self.z[i]);
            p.rhs(t + self.c[i] * h, &self.stage, &mut self.f[i]);
        }
        self.counters.evaluations += self.z.len() as u64;
    }

    /// Fixed-point sweeps `Z_i <- h sum_j a_ij f(Y_j)`; returns the last update's size.
    fn fixed_point<P: Problem<Scalar = S::Scalar, State = S>>(
        &mut self,
        p: &P,
        t: S::Scalar,
        h: S::Scalar,
        y: &S,
    ) -> Result<(), Error> {
        let s = self.z.len();
        let scale = S::Scalar::one() + y.as_slice().iter().fold(S::Scalar::zero(), |m, x| m.max(x.abs()));
        let tol = lit::<S::Scalar>(self.options.tol) * scale;
        let mut residual = S::Scalar::zero();
        for iteration in 1..=self.options.max_iterations {
            self.evaluate_stages(p, t, h, y);
            self.counters.solver_iterations += 1;
            residual = S::Scalar::zero();
            for i in 0..s {
                let zi = self.z[i].as_mut_slice();
                for m in 0..zi.len() {
                    let mut sum = S::Scalar::zero();
                    for j in 0..s {
                        sum += self.a[i * s + j] * self.f[j].as_slice()[m];
                    }
                    let new = h * sum;
                    residual = residual.max((new - zi[m]).abs());
                    zi[m] = new;
                }
            }
            if !residual.is_finite() {
                break;
            }
            if residual <= tol {
                let _ = iteration;
                return Ok(());
            }
        }
        Err(Error::SolverDiverged {
            t: to_f64(t),
            residual: to_f64(residual),
            iterations: self.options.max_iterations,
        })
    }
}

impl<P: Problem> Stepper<P> for ImplicitRk<P::State> {
    fn info(&self) -> MethodInfo {
        self.info.clone()
    }

    fn error_order(&self) -> Option<usize> {
        None
    }

    fn step(
        &mut self,
        p: &P,
        t: P::Scalar,
        h: P::Scalar,
        y: &P::State,
        y_new: &mut P::State,
        _tol: Option<&Tolerances<P::Scalar>>,
    ) -> Result<Option<P::Scalar>, Error> {
        for z in &mut self.z {
            z.scale(P::Scalar::zero());
        }
        self.fixed_point(p, t, h, y)?;
        self.evaluate_stages(p, t, h, y);
        y_new.copy_from(y);
        for i in 0..self.z.len() {
            y_new.axpy(h * self.b[i], &self.f[i]);
        }
        Ok(None)
    }

    fn accept(&mut self) {}

    fn reset(&mut self) {}

    fn counters(&self) -> Counters {
        self.counters
    }
}
