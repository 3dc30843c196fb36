//! Events: where functions `g(t, y)` of the solution change sign, located inside the steps
//! on the continuous extension (no step is taken again), recorded with their time and
//! state; a terminal event ends the run there.

/// Which sign changes of an event function count.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Crossing {
    /// From negative to positive.
    Rising,
    /// From positive to negative.
    Falling,
    /// Either way.
    Either,
}

impl Crossing {
    /// Whether `g` going from `g0` to `g1` can be a crossing of this kind. From `g0 == 0` (a
    /// step that starts on zero) only a crossing towards `g1`'s side can be, if `g` left
    /// zero the other way first, which the root finder tells (`super::root`).
    pub(super) fn between<T: crate::Real>(self, g0: T, g1: T) -> bool {
        let zero = T::zero();
        let g0 = if g0 == zero { -g1 } else { g0 };
        let rising = g0 < zero && g1 >= zero;
        let falling = g0 > zero && g1 <= zero;
        match self {
            Crossing::Rising => rising,
            Crossing::Falling => falling,
            Crossing::Either => rising || falling,
        }
    }
}

/// An event function, the crossings that count and whether the run ends at the first one.
pub struct Event<'a, T, S> {
    pub(super) g: super::StopFn<'a, T, S>,
    pub(super) crossing: Crossing,
    pub(super) terminal: bool,
}

/// Where an event happened: which event (its index in the order the events were added),
/// the time and the state there.
#[derive(Debug, Clone, PartialEq)]
pub struct EventHit<T, S> {
    /// The event's index.
    pub index: usize,
    /// The located time.
    pub t: T,
    /// The state there (from the continuous extension).
    pub y: S,
}
