//! The generic explicit stepper over a tableau known only at run time.

use super::compensated::CompensatedCombination;
use super::{Counters, Stepper, Tolerances};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{lit, Error, MethodInfo, Problem, Real, State, Tableau};

/// A row of coefficients with its zero entries dropped: `(column, value)`.
type Sparse<T> = Vec<(usize, T)>;

fn sparse<T: Real>(row: impl IntoIterator<Item = f64>) -> Sparse<T> {
    row.into_iter()
        .enumerate()
        .filter(|&(_, x)| x != 0.0)
        .map(|(j, x)| (j, lit(x)))
        .collect()
}

/// Stepper for an explicit [`Tableau`] built at run time (e.g. read from a file).
///
/// Same operation order as the generated steppers (zero coefficients skipped, sums in
/// column order), so both give bitwise-equal trajectories; it only loops where the
/// generated code is unrolled.
#[derive(Debug, Clone)]
pub struct RuntimeRk<S: State> {
    info: MethodInfo,
    error_order: Option<usize>,
    fsal: bool,
    a: Vec<Sparse<S::Scalar>>,
    c: Vec<S::Scalar>,
    b: Sparse<S::Scalar>,
    d: Option<Sparse<S::Scalar>>,
    d3: Option<Sparse<S::Scalar>>,
    k: Vec<S>,
    err: S,
    err3: S,
    k0_valid: bool,
    /// The weights `b` as declared, for the compensated combination.
    b_declared: Vec<f64>,
    /// The final combination summed with a carry, when turned on.
    compensated: Option<CompensatedCombination<S>>,
    counters: Counters,
}

impl<S: State> RuntimeRk<S> {
    /// A stepper for an explicit tableau; an implicit one is an error.
    pub fn new(tableau: &Tableau, y0: &S) -> Result<Self, Error> {
        if !tableau.flags().explicit {
            return Err(Error::Unsupported {
                name: tableau.name().to_string(),
                reason: "the tableau is implicit; use ImplicitRk".into(),
            });
        }
        let s = tableau.stages();
        let diff = |w: &[f64]| sparse(tableau.b().iter().zip(w).map(|(b, w)| b - w));
        Ok(RuntimeRk {
            info: tableau.info(),
            error_order: match (tableau.embedded_order(), tableau.b_hat3()) {
                (Some(_), Some(_)) => Some(tableau.order() - 1),
                (q, _) => q,
            },
            fsal: tableau.flags().fsal,
            a: tableau.a().chunks(s).map(|row| sparse(row.iter().copied())).collect(),
            c: tableau.c().iter().map(|&c| lit(c)).collect(),
            b: sparse(tableau.b().iter().copied()),
            d: tableau.b_hat().map(diff),
            d3: tableau.b_hat3().map(diff),
            k: vec![y0.zeros_like(); s],
            err: y0.zeros_like(),
            err3: y0.zeros_like(),
            k0_valid: false,
            b_declared: tableau.b().to_vec(),
            compensated: None,
            counters: Counters::default(),
        })
    }
}

/// `out = base + h * sum_j w_j k_j` (or `h * sum` without a base), terms in column order.
fn combine<S: State>(out: &mut S, base: Option<&S>, h: S::Scalar, w: &Sparse<S::Scalar>, k: &[S]) {
    let out = out.as_mut_slice();
    for m in 0..out.len() {
        let mut sum = None;
        for &(j, wj) in w {
            let term = wj * k[j].as_slice()[m];
            sum = Some(match sum {
                None => term,
                Some(s) => s + term,
            });
        }
        let inc = sum.map_or(S::Scalar::zero(), |s| h * s);
        out[m] = match base {
            Some(y) if w.is_empty() => y.as_slice()[m],
            Some(y) => y.as_slice()[m] + inc,
            None => inc,
        };
    }
}

impl<P: Problem> Stepper<P> for RuntimeRk<P::State> {
    fn info(&self) -> MethodInfo {
        self.info.clone()
    }

    fn error_order(&self) -> Option<usize> {
        self.error_order
    }

    fn step(
        &mut self,
        p: &P,
        t: P::Scalar,
        h: P::Scalar,
        y: &P::State,
        y_new: &mut P::State,
        tol: Option<&Tolerances<P::Scalar>>,
    ) -> Result<Option<P::Scalar>, Error> {
        if !self.k0_valid {
            p.rhs(t, y, &mut self.k[0]);
            self.counters.evaluations += 1;
        }
        for i in 1..self.k.len() {
            combine(y_new, Some(y), h, &self.a[i], &self.k);
            let ti = if self.c[i] == P::Scalar::zero() {
                t
            } else {
                t + self.c[i] * h
            };
            p.rhs(ti, y_new, &mut self.k[i]);
            self.counters.evaluations += 1;
        }
        match self.compensated.as_mut() {
            Some(sum) => sum.combine(h, y, &self.k, y_new),
            None => combine(y_new, Some(y), h, &self.b, &self.k),
        }
        self.k0_valid = true;
        let (Some(tol), Some(d)) = (tol, self.d.as_ref()) else {
            return Ok(None);
        };
        combine(&mut self.err, None, h, d, &self.k);
        let norm = match self.d3.as_ref() {
            Some(d3) => {
                combine(&mut self.err3, None, h, d3, &self.k);
                tol.dop853(y, y_new, &self.err, &self.err3)
            }
            None => tol.rms(y, y_new, &self.err),
        };
        Ok(Some(norm))
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
        if let Some(sum) = self.compensated.as_mut() {
            sum.reset();
        }
    }

    fn set_compensated(&mut self, on: bool) -> Result<(), Error> {
        super::compensated::switch(&mut self.compensated, on, || {
            CompensatedCombination::new(&self.b_declared, &self.k[0])
        });
        Ok(())
    }

    fn counters(&self) -> Counters {
        self.counters
    }
}
