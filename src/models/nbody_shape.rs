//! The shape of an N-body force loop (bodies and dimension): chosen at run time, or fixed
//! when the program is compiled so that the step loop holds only that unrolled force.

use super::NBody;
use crate::{Real, State};

/// Expands `$each!((D, N), ...)` over the shapes that have an unrolled force loop: 2 to 6
/// bodies in 3-D and in 2-D. One list for [`NBody`]'s force and the Kepler split's
/// interaction, which choose among them the same way.
macro_rules! unrolled_shapes {
    ($each:ident) => {
        $each!(
            (3, 2),
            (3, 3),
            (3, 4),
            (3, 5),
            (3, 6),
            (2, 2),
            (2, 3),
            (2, 4),
            (2, 5),
            (2, 6)
        )
    };
}
pub(super) use unrolled_shapes;

/// How [`NBody`] computes its forces: a type-level choice, so that a problem whose bodies
/// are known when the program is compiled carries no dispatch and no fallback code in its
/// step loop (a call anywhere in a loop, even on a branch never taken, makes the register
/// allocator keep the state in memory across every step).
pub trait Shape: Copy + Default + core::fmt::Debug + Send + Sync + 'static {
    /// `(dimension, bodies)` when fixed at compile time; [`NBody::new`] refuses other bodies.
    const FIXED: Option<(usize, usize)>;

    /// The forces of `nbody`'s bodies at positions `q`, into `f`.
    fn force<T: Real, S: State<Scalar = T>>(nbody: &NBody<T, S, Self>, q: &[T], f: &mut [T]);
}

/// Any number of bodies in any dimension, the force loop chosen at run time (unrolled for
/// 2 to 6 bodies in 2-D and 3-D when the state's length allows the shape): the shape of a
/// scene read from a file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AnyShape;

impl Shape for AnyShape {
    const FIXED: Option<(usize, usize)> = None;

    #[inline(always)]
    fn force<T: Real, S: State<Scalar = T>>(nbody: &NBody<T, S, Self>, q: &[T], f: &mut [T]) {
        nbody.force_by_run_time_shape(q, f)
    }
}

/// Exactly `N` bodies in `D` dimensions, fixed at compile time: the step loop holds the
/// unrolled force of those bodies, as a force written by hand for them would be.
///
/// ```
/// use stormer::models::{Bodies, NBody};
/// // two bodies in the plane; any other number is refused
/// let pair = NBody::<f64, [f64; 8], Bodies<2, 2>>::new(1.0, &[1.0, 1.0], 2).unwrap();
/// assert!(NBody::<f64, [f64; 12], Bodies<2, 2>>::new(1.0, &[1.0, 1.0, 1.0], 2).is_err());
/// # let _ = pair;
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Bodies<const D: usize, const N: usize>;

impl<const D: usize, const N: usize> Shape for Bodies<D, N> {
    const FIXED: Option<(usize, usize)> = Some((D, N));

    #[inline(always)]
    fn force<T: Real, S: State<Scalar = T>>(nbody: &NBody<T, S, Self>, q: &[T], f: &mut [T]) {
        nbody.pairwise_fixed::<D, N>(q, f)
    }
}
