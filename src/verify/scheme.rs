//! A method to verify, of any family, that builds its own stepper on any problem and at
//! any scalar type (so the same method runs on `f64` and on dual numbers).

use crate::flows::{QuadraticKinetic, Splittable};
use crate::registry::{self, MethodRef};
use crate::{Error, ImplicitOptions, MethodInfo, Problem, RuntimeSplitting, Splitting, Stepper, Tableau};
use stormer_order::stability::{butcher_interval, splitting_interval, Interval};

/// A method of any family, as the verification suite runs it.
///
/// A catalog method runs its compiled (generated) stepper, so the verification covers
/// the code users run; a method held in memory (read from a file, built at run time) runs
/// the run-time stepper of its family. Implicit tableaus use [`ImplicitOptions::newton`]
/// unless told otherwise: it converges at the larger steps the order measurement takes.
///
/// ```
/// use stormer::verify::Scheme;
/// let kahan = Scheme::named("kahan-li6").unwrap();
/// assert_eq!((kahan.info().name.as_str(), kahan.info().order), ("kahan_li6", 6));
/// assert!(Scheme::named("rk5").unwrap_err().to_string().contains("did you mean"));
/// ```
#[derive(Debug, Clone)]
pub struct Scheme {
    kind: Kind,
    implicit: ImplicitOptions,
}

#[derive(Debug, Clone)]
enum Kind {
    Catalog(MethodRef),
    Tableau(Tableau),
    Splitting(Splitting),
}

impl Scheme {
    /// A catalog method by name (spelling rules and suggestions of [`registry::lookup`]).
    pub fn named(name: &str) -> Result<Self, Error> {
        Ok(Scheme::from(registry::lookup(name)?))
    }

    /// The same method with these options for an implicit tableau's solver.
    pub fn with_implicit(mut self, options: ImplicitOptions) -> Self {
        self.implicit = options;
        self
    }

    /// Name, family, order, stages and flags.
    pub fn info(&self) -> MethodInfo {
        match &self.kind {
            Kind::Catalog(MethodRef::Butcher(d)) => d.info(),
            Kind::Catalog(MethodRef::Splitting(d)) => d.info(),
            Kind::Tableau(t) => t.info(),
            Kind::Splitting(s) => s.info(),
        }
    }

    /// True for a method that reaches its order only when the kinetic energy is
    /// quadratic (a Runge-Kutta-Nystrom splitting).
    pub fn requires_quadratic_kinetic(&self) -> bool {
        match &self.kind {
            Kind::Catalog(MethodRef::Splitting(d)) => d.requires_quadratic_kinetic,
            Kind::Splitting(s) => s.requires_quadratic_kinetic(),
            _ => false,
        }
    }

    /// The tableau of a Butcher method (to which the algebraic symplecticity condition
    /// applies); `None` for a splitting or composition.
    pub fn tableau(&self) -> Option<Result<Tableau, Error>> {
        match &self.kind {
            Kind::Catalog(MethodRef::Butcher(d)) => Some(Tableau::from_data(d)),
            Kind::Tableau(t) => Some(Ok(t.clone())),
            _ => None,
        }
    }

    /// The linear stability interval on the imaginary axis, from the coefficients: the
    /// largest `h omega` such that a step of every `h` up to it does not grow on the
    /// harmonic oscillator `q'' = -omega^2 q` (`|R(i h omega)| <= 1` for a tableau, the
    /// transfer matrix's `|trace| <= 2` for a splitting or composition;
    /// [`stormer_order::stability`]).
    ///
    /// ```
    /// use stormer::order::stability::Interval;
    /// use stormer::verify::Scheme;
    /// let rk4 = Scheme::named("rk4").unwrap().stability_interval().value();
    /// assert!((rk4 - 8f64.sqrt()).abs() < 1e-9);
    /// let verlet = Scheme::named("velocity_verlet_kdk").unwrap().stability_interval().value();
    /// assert!((verlet - 2.0).abs() < 1e-9);
    /// assert_eq!(Scheme::named("euler").unwrap().stability_interval(), Interval::Bounded(0.0));
    /// assert_eq!(Scheme::named("gauss_legendre4").unwrap().stability_interval(), Interval::Unbounded);
    /// ```
    pub fn stability_interval(&self) -> Interval {
        match &self.kind {
            Kind::Catalog(MethodRef::Butcher(d)) => butcher_interval(d.a, d.b),
            Kind::Catalog(MethodRef::Splitting(d)) => splitting_interval(d.drift, d.kick),
            Kind::Tableau(t) => butcher_interval(t.a(), t.b()),
            Kind::Splitting(s) => splitting_interval(s.drift(), s.kick()),
        }
    }

    /// The method's stepper for a splittable problem; a method that needs a quadratic
    /// kinetic energy is refused (use [`Scheme::stepper_quadratic`]).
    pub fn stepper<P>(&self, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
    where
        P: Splittable + 'static,
    {
        match &self.kind {
            Kind::Catalog(MethodRef::Butcher(d)) => registry::stepper::<P>(d.name, y0, &self.implicit),
            Kind::Catalog(MethodRef::Splitting(d)) => registry::splitting_stepper::<P>(d.name, y0),
            Kind::Tableau(t) => registry::tableau_stepper::<P>(t, y0, &self.implicit),
            Kind::Splitting(s) => registry::runtime_splitting_stepper::<P>(s, y0),
        }
    }

    /// The stepper of a Butcher tableau for any problem (not only a splittable one); an
    /// error for a splitting or composition, which needs the split.
    pub fn stepper_any<P>(&self, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
    where
        P: Problem + 'static,
    {
        match &self.kind {
            Kind::Catalog(MethodRef::Butcher(d)) => registry::stepper::<P>(d.name, y0, &self.implicit),
            Kind::Tableau(t) => registry::tableau_stepper::<P>(t, y0, &self.implicit),
            Kind::Catalog(MethodRef::Splitting(_)) | Kind::Splitting(_) => Err(Error::invalid(
                self.info().name,
                "a splitting or composition runs on a splittable problem only",
            )),
        }
    }

    /// The method's stepper for a problem whose kinetic energy is quadratic (every method).
    pub fn stepper_quadratic<P>(&self, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
    where
        P: QuadraticKinetic + 'static,
    {
        match &self.kind {
            Kind::Catalog(MethodRef::Splitting(d)) => registry::splitting_stepper_quadratic::<P>(d.name, y0),
            Kind::Splitting(s) => Ok(Box::new(RuntimeSplitting::new_quadratic(s, y0)?)),
            _ => self.stepper::<P>(y0),
        }
    }
}

impl From<MethodRef> for Scheme {
    fn from(method: MethodRef) -> Self {
        Scheme {
            kind: Kind::Catalog(method),
            implicit: ImplicitOptions::newton(),
        }
    }
}

impl From<Tableau> for Scheme {
    fn from(tableau: Tableau) -> Self {
        Scheme {
            kind: Kind::Tableau(tableau),
            implicit: ImplicitOptions::newton(),
        }
    }
}

impl From<Splitting> for Scheme {
    fn from(splitting: Splitting) -> Self {
        Scheme {
            kind: Kind::Splitting(splitting),
            implicit: ImplicitOptions::newton(),
        }
    }
}
