//! The stages of an explicit tableau known only at run time: loops over its nonzero
//! coefficients where the generated code is unrolled.

use super::explicit::{ExplicitStages, ExplicitStepper};
use crate::method::{MethodInfo, Tableau};
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Problem, Real, State};

/// A row of coefficients with its zero entries dropped: `(column, value)`.
type Sparse<T> = Vec<(usize, T)>;

fn sparse<T: Real>(row: impl IntoIterator<Item = f64>) -> Sparse<T> {
    row.into_iter()
        .enumerate()
        .filter(|&(_, x)| x != 0.0)
        .map(|(j, x)| (j, lit(x)))
        .collect()
}

/// The stages of a run-time [`Tableau`], in the generated code's operation order (zero
/// coefficients skipped, sums in column order).
#[derive(Debug, Clone)]
pub struct RuntimeStages<S: State> {
    tableau: Tableau,
    a: Vec<Sparse<S::Scalar>>,
    c: Vec<S::Scalar>,
    b: Sparse<S::Scalar>,
    /// `b - b_hat` and `b - b_hat3`, computed in `f64` as the macro does.
    d: Option<Sparse<S::Scalar>>,
    d3: Option<Sparse<S::Scalar>>,
}

/// Stepper for an explicit [`Tableau`] built at run time (e.g. read from a file).
///
/// Same operation order as the generated steppers, so both give bitwise-equal
/// trajectories; it only loops where the generated code is unrolled.
pub type RuntimeRk<S> = ExplicitStepper<RuntimeStages<S>, S>;

impl<S: State> ExplicitStepper<RuntimeStages<S>, S> {
    /// A stepper for an explicit tableau; an implicit one is an error.
    pub fn new(tableau: &Tableau, y0: &S) -> Result<Self, Error> {
        if !tableau.flags().explicit {
            return Err(Error::Unsupported {
                name: tableau.name().to_string(),
                reason: "the tableau is implicit; use ImplicitRk".into(),
            });
        }
        let diff = |w: &[f64]| sparse(tableau.b().iter().zip(w).map(|(b, w)| b - w));
        let stages = RuntimeStages {
            a: tableau
                .a()
                .chunks(tableau.stages())
                .map(|row| sparse(row.iter().copied()))
                .collect(),
            c: tableau.c().iter().map(|&c| lit(c)).collect(),
            b: sparse(tableau.b().iter().copied()),
            d: tableau.b_hat().map(diff),
            d3: tableau.b_hat3().map(diff),
            tableau: tableau.clone(),
        };
        Ok(Self::with_stages(stages, y0))
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

impl<S: State> ExplicitStages<S> for RuntimeStages<S> {
    fn info(&self) -> MethodInfo {
        self.tableau.info()
    }

    fn dense_powers(&self) -> Option<usize> {
        self.tableau.dense().map(|d| d.first().map_or(0, Vec::len))
    }

    fn dense_row(&self, stage: usize) -> &[f64] {
        self.tableau.dense().map_or(&[], |d| &d[stage])
    }

    fn dense_added(&self) -> (&[f64], &[f64]) {
        (self.tableau.dense_c(), self.tableau.dense_a())
    }

    fn weights(&self) -> &[f64] {
        self.tableau.b()
    }

    fn estimates(&self) -> (bool, bool) {
        (self.d.is_some(), self.d3.is_some())
    }

    fn stages<P>(&self, p: &P, t: S::Scalar, h: S::Scalar, y: &S, k: &mut [S], y_new: &mut S)
    where
        P: Problem<Scalar = S::Scalar, State = S>,
    {
        for i in 1..k.len() {
            combine(y_new, Some(y), h, &self.a[i], k);
            let ti = if self.c[i] == S::Scalar::zero() {
                t
            } else {
                t + self.c[i] * h
            };
            p.rhs(ti, y_new, &mut k[i]);
        }
        combine(y_new, Some(y), h, &self.b, k);
    }

    fn error(&self, h: S::Scalar, k: &[S], err: &mut S) {
        if let Some(d) = &self.d {
            combine(err, None, h, d, k);
        }
    }

    fn error3(&self, h: S::Scalar, k: &[S], err: &mut S) {
        if let Some(d3) = &self.d3 {
            combine(err, None, h, d3, k);
        }
    }
}
