//! Output at chosen physical times and a stop at a physical end: the driver integrates in
//! the fictitious time `s`, and the physical time is a coordinate, so both are crossings
//! of `t(y) - t_k` that the driver's events and stop condition locate by root finding.

use super::state::time_of;
use crate::driver::{Crossing, Driver, Solution};
use crate::{Real, State};

/// `driver` with one event per physical time of `times` (crossing either way, so that a
/// run backwards in time works too), added after the events it has: the run's
/// [`Solution::events`] then hold the extended state at each of these times, located on
/// the step's continuous extension (the driver's Hermite interpolant in `s`, order
/// [`crate::driver::hermite_order`] of the method's). Each output time costs one
/// subtraction per step. [`physical_records`] reads them back.
///
/// ```
/// use stormer::catalog::TripleJump4;
/// use stormer::models::CentralForce;
/// use stormer::stepper::SplittingStepper;
/// use stormer::time_transform::{at_physical_times, physical_records, stop_at_physical_time, LogH};
/// use stormer::Driver;
/// let kepler = CentralForce::<f64, [f64; 4]>::new(1.0);
/// let logh = LogH::<_, [f64; 6]>::new(kepler).unwrap();
/// let y0 = logh.extend(0.0, &[1.0, 0.0, 0.0, 1.0]).unwrap(); // circular, period 2 pi
/// let mut stepper = SplittingStepper::<TripleJump4, [f64; 6]>::new(&y0).unwrap();
/// let driver = stop_at_physical_time(at_physical_times(Driver::fixed(0.01), &[1.0, 2.0]), 3.0);
/// // s runs to at most 10; the physical end t = 3 stops the run before
/// let run = driver.run(&logh, &mut stepper, 0.0, &y0, 10.0).unwrap();
/// let records = physical_records(&logh, &run, 0).unwrap();
/// assert_eq!(records.len(), 2);
/// let (t, y) = &records[1];
/// assert!((t - 2.0).abs() < 1e-12, "{t}");
/// assert!((y[0] - 2f64.cos()).abs() < 1e-8, "{}", y[0] - 2f64.cos());
/// let end = &run.stopped.unwrap().y;
/// assert!((logh.time(end) - 3.0).abs() < 1e-12);
/// ```
pub fn at_physical_times<'a, T: Real, E: State<Scalar = T>>(
    mut driver: Driver<'a, T, E>,
    times: &[T],
) -> Driver<'a, T, E> {
    for &t in times {
        driver = driver.event(move |_s, y: &E| time_of(y) - t, Crossing::Either, false);
    }
    driver
}

/// `driver` stopping where the physical time reaches `t_end` ([`Driver::stop_when`]: the
/// crossing is located by stepping again with the method, so the last state has the
/// method's own accuracy, and becomes the last record and [`Solution::stopped`]). The
/// run's span in `s` is then an upper bound: give one long enough to reach `t_end`.
pub fn stop_at_physical_time<'a, T: Real, E: State<Scalar = T>>(
    driver: Driver<'a, T, E>,
    t_end: T,
) -> Driver<'a, T, E> {
    driver.stop_when(move |_s, y: &E| time_of(y) - t_end)
}

/// A transformed problem's way back to the physical state ([`super::LogH::physical`],
/// [`super::Ttl::physical`]).
pub trait ToPhysical<T, E, S> {
    /// `(t, y)` of an extended state.
    fn to_physical(&self, extended: &E) -> Result<(T, S), crate::Error>;
}

/// The physical `(t, y)` of each event of `solution` from index `first` on, in the order
/// they happened: the output of [`at_physical_times`] when its events were added after
/// `first` others.
pub fn physical_records<T, E, S, W>(
    transformed: &W,
    solution: &Solution<T, E>,
    first: usize,
) -> Result<Vec<(T, S)>, crate::Error>
where
    W: ToPhysical<T, E, S>,
{
    solution
        .events
        .iter()
        .filter(|hit| hit.index >= first)
        .map(|hit| transformed.to_physical(&hit.y))
        .collect()
}
