//! The state: a small in-place vector trait over the containers users already have.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;
use nalgebra::allocator::Allocator;
use nalgebra::{Const, DefaultAllocator, Dim, Dyn, OVector};

/// A state vector that steppers update in place.
///
/// Implemented for `[T; N]`, nalgebra's `SVector<T, N>` (both with no heap allocation) and
/// `DVector<T>`. Steppers only need a contiguous slice of components; everything else is
/// derived from it, so nalgebra's allocator bounds never reach a public signature.
///
/// ```
/// use stormer::State;
/// let mut y = [1.0, 2.0];
/// y.axpy(0.5, &[2.0, 2.0]);
/// assert_eq!(y, [2.0, 3.0]);
/// ```
pub trait State: Clone + core::fmt::Debug {
    /// The scalar type of the components.
    type Scalar: Real;

    /// The number of components when the type fixes it (`[T; N]`, `SVector<T, N>`), `None`
    /// when it is chosen at run time (`DVector`). A constant, so that a problem can select
    /// code for a static size when the code is compiled.
    const LEN: Option<usize> = None;

    /// The components, contiguous.
    fn as_slice(&self) -> &[Self::Scalar];

    /// The components, contiguous and mutable.
    fn as_mut_slice(&mut self) -> &mut [Self::Scalar];

    /// A state of the same shape with every component zero.
    fn zeros_like(&self) -> Self;

    /// Number of components.
    #[inline]
    fn dim(&self) -> usize {
        self.as_slice().len()
    }

    /// `self += a * x`, component by component.
    #[inline]
    fn axpy(&mut self, a: Self::Scalar, x: &Self) {
        for (s, &x) in self.as_mut_slice().iter_mut().zip(x.as_slice()) {
            *s += a * x;
        }
    }

    /// `self *= a`.
    #[inline]
    fn scale(&mut self, a: Self::Scalar) {
        for s in self.as_mut_slice() {
            *s *= a;
        }
    }

    /// Copies the components of `x` into `self` (same shape).
    #[inline]
    fn copy_from(&mut self, x: &Self) {
        self.as_mut_slice().copy_from_slice(x.as_slice());
    }

    /// True when every component is finite.
    #[inline]
    fn is_finite(&self) -> bool {
        // x * 0 is 0 for a finite x and NaN otherwise, and NaN survives the sum: no branch
        // per component (the driver checks every step); four independent sums, so that
        // the check is not one long chain of dependent additions
        let zero = Self::Scalar::zero();
        let x = self.as_slice();
        let mut sums = [zero; 4];
        let mut quads = x.chunks_exact(4);
        for quad in &mut quads {
            for (sum, &x) in sums.iter_mut().zip(quad) {
                *sum += x * zero;
            }
        }
        for (sum, &x) in sums.iter_mut().zip(quads.remainder()) {
            *sum += x * zero;
        }
        ((sums[0] + sums[1]) + (sums[2] + sums[3])).is_finite()
    }
}

impl<T: Real, const N: usize> State for [T; N] {
    type Scalar = T;
    const LEN: Option<usize> = Some(N);
    #[inline(always)]
    fn as_slice(&self) -> &[T] {
        self
    }
    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [T] {
        self
    }
    #[inline]
    fn zeros_like(&self) -> Self {
        [T::zero(); N]
    }
}

/// Whether a nalgebra dimension is known when the code is compiled: `Const<N>` for
/// `SVector<T, N>`, `Dyn` for `DVector<T>`.
pub trait VectorLength: Dim {
    /// [`State::LEN`] of the vectors of this dimension.
    const LEN: Option<usize>;
}

impl<const N: usize> VectorLength for Const<N> {
    const LEN: Option<usize> = Some(N);
}

impl VectorLength for Dyn {
    const LEN: Option<usize> = None;
}

/// `SVector<T, N>` and `DVector<T>`: the same contiguous storage, one impl.
impl<T: Real, D: VectorLength> State for OVector<T, D>
where
    DefaultAllocator: Allocator<D>,
{
    type Scalar = T;
    const LEN: Option<usize> = D::LEN;
    #[inline(always)]
    fn as_slice(&self) -> &[T] {
        nalgebra::Matrix::as_slice(self)
    }
    #[inline(always)]
    fn as_mut_slice(&mut self) -> &mut [T] {
        nalgebra::Matrix::as_mut_slice(self)
    }
    #[inline]
    fn zeros_like(&self) -> Self {
        OVector::zeros_generic(self.shape_generic().0, Const::<1>)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DVector, SVector};

    fn exercise<S: State<Scalar = f64>>(mut y: S) {
        let x = y.clone();
        y.axpy(2.0, &x);
        y.scale(0.5);
        assert_eq!(y.as_slice(), &[1.5, 3.0, 4.5]);
        let mut z = y.zeros_like();
        assert_eq!(z.as_slice(), &[0.0; 3]);
        z.copy_from(&y);
        assert_eq!(z.as_slice(), y.as_slice());
        assert!(z.is_finite());
        z.as_mut_slice()[1] = f64::NAN;
        assert!(!z.is_finite());
        assert_eq!(z.dim(), 3);
    }

    #[test]
    fn static_lengths_are_known() {
        assert_eq!(<[f64; 3] as State>::LEN, Some(3));
        assert_eq!(<SVector<f32, 4> as State>::LEN, Some(4));
        assert_eq!(<DVector<f64> as State>::LEN, None);
    }

    #[test]
    fn every_container_behaves_the_same() {
        exercise([1.0, 2.0, 3.0]);
        exercise(SVector::<f64, 3>::new(1.0, 2.0, 3.0));
        exercise(DVector::from_vec(vec![1.0, 2.0, 3.0]));
    }
}
