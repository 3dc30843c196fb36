//! A method to run, of any family: the one value that a name, an alias or a method file
//! resolves to, and the one builder of its stepper for a problem.

use crate::families::SplittingSource;
use crate::method::{MethodInfo, Splitting, SplittingData, Tableau, TableauData};
use crate::stepper::ImplicitOptions;
use crate::stepper::{ParticleMethod, RelativisticMethod};
use crate::{registry, Error, Problem, Stepper};
use std::path::Path;
use stormer_order::stability::{butcher_interval, splitting_interval, Interval};

/// A method to run: a catalog tableau, splitting or composition (its generated stepper
/// runs), one built at run time (a method file, the theta method, your own coefficients),
/// or a charged-particle pusher.
///
/// [`Method::resolve`] turns what a user types (a catalog name, an alias such as `RK45` or
/// `leapfrog`, a pusher, or a method file's path) into one, once; [`Method::stepper_for`]
/// builds its stepper for a problem, asking the problem which families it admits
/// ([`crate::Problem::families`]).
///
/// ```
/// use stormer::{Driver, Method, SecondOrder};
///
/// /// The pendulum q'' = -sin q.
/// struct Pendulum;
/// impl SecondOrder for Pendulum {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) { a[0] = -q[0].sin(); }
/// }
/// let y0 = [0.5, 0.0];
/// for name in ["rk4", "dopri5", "kahan_li6", "leapfrog"] {
///     let method = Method::resolve(name).unwrap();
///     let mut stepper = method.stepper_for(&Pendulum, &y0, &Default::default()).unwrap();
///     let run = Driver::fixed(0.01).run(&Pendulum, &mut stepper, 0.0, &y0, 1.0).unwrap();
///     assert!((run.y.last().unwrap()[0] - 0.5 * 1f64.cos()).abs() < 0.01, "{name}");
/// }
/// assert_eq!(Method::resolve("RK45").unwrap().name(), "dormand_prince5");
/// assert!(Method::resolve("rk-5").unwrap_err().to_string().contains("did you mean"));
/// ```
#[derive(Debug, Clone)]
pub enum Method {
    /// A Butcher tableau compiled into the crate.
    Tableau(&'static TableauData),
    /// A splitting or composition compiled into the crate.
    Splitting(&'static SplittingData),
    /// A Butcher tableau built at run time (a method file, [`Method::theta`], code).
    RuntimeTableau(Tableau),
    /// A splitting or composition built at run time.
    RuntimeSplitting(Splitting),
    /// A charged-particle pusher (Boris, Euler-Cromer).
    Particle(ParticleMethod),
    /// A relativistic pusher (relativistic Boris, Vay, Higuera-Cary).
    Relativistic(RelativisticMethod),
}

impl Method {
    /// Resolves what a user names: a charged-particle pusher, a method file (a path: it
    /// ends in `.toml` or has a path separator), or a catalog name or alias (spelling rules
    /// and suggestions of [`Method::named`]); a bare name that is none of these is read
    /// as a file when one of that name exists. A stray file named `rk4` never shadows the
    /// catalog's `rk4` (write `./rk4` to read it).
    pub fn resolve(name_or_path: &str) -> Result<Self, Error> {
        if let Some(pusher) = ParticleMethod::find(name_or_path) {
            return Ok(Method::Particle(pusher));
        }
        if let Some(pusher) = RelativisticMethod::find(name_or_path) {
            return Ok(Method::Relativistic(pusher));
        }
        if looks_like_path(name_or_path) {
            return Method::from_file(Path::new(name_or_path));
        }
        match Method::named(name_or_path) {
            Err(Error::UnknownMethod { .. }) if Path::new(name_or_path).is_file() => {
                Method::from_file(Path::new(name_or_path))
            }
            found => found,
        }
    }

    /// A catalog method by name or alias: `-`, `_` and spaces are one separator, and
    /// separators are optional when that names one method (`rk-4` is `rk4`); an unknown
    /// name is an error that suggests the nearest names and aliases.
    ///
    /// ```
    /// use stormer::Method;
    /// assert_eq!(Method::named("rk-4").unwrap().name(), "rk4");
    /// assert_eq!(Method::named("Tsit5").unwrap().name(), "tsitouras5");
    /// assert_eq!(Method::named("leapfrog").unwrap().name(), "stormer_verlet_dkd");
    /// let err = Method::named("rk-5").unwrap_err().to_string();
    /// assert!(err.contains("did you mean"), "{err}");
    /// ```
    pub fn named(name: &str) -> Result<Self, Error> {
        registry::lookup(name)
    }

    /// Reads a method file: a splitting or composition when its family says so or it has
    /// `drift`/`kick`/`word`/`gamma` keys, otherwise a Butcher tableau.
    pub fn from_file(path: &Path) -> Result<Self, Error> {
        let (text, origin) = super::file::read_file(path)?;
        Method::from_toml_str(&text, &origin)
    }

    /// Reads a method from TOML text as [`Method::from_file`] reads a file (`origin` names
    /// it in messages): the same checks, the same refusals.
    ///
    /// ```
    /// use stormer::Method;
    /// let leapfrog = "name = \"mine\"\norder = 2\ndrift = [\"1/2\", \"1/2\"]\nkick = [\"1\", \"0\"]";
    /// assert_eq!(Method::from_toml_str(leapfrog, "inline").unwrap().info().family, "splitting");
    /// let bad = "name = \"bad\"\norder = 2\nc = [\"0\", \"1\"]\na = [[\"0\", \"0\"], [\"1\", \"0\"]]\nb = [\"0.4\", \"0.6\"]";
    /// let err = Method::from_toml_str(bad, "inline").unwrap_err().to_string();
    /// assert!(err.contains("order 2 condition"), "{err}");
    /// ```
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self, Error> {
        if is_splitting_text(text) {
            Ok(Method::RuntimeSplitting(Splitting::from_toml_str(text, origin)?))
        } else {
            Ok(Method::RuntimeTableau(Tableau::from_toml_str(text, origin)?))
        }
    }

    /// The theta method with weight `alpha` ([`crate::catalog::theta`]).
    pub fn theta(alpha: f64) -> Result<Self, Error> {
        Ok(Method::RuntimeTableau(registry::theta(alpha)?))
    }

    /// The method's name.
    pub fn name(&self) -> &str {
        match self {
            Method::Tableau(d) => d.name,
            Method::Splitting(d) => d.name,
            Method::RuntimeTableau(t) => t.name(),
            Method::RuntimeSplitting(s) => s.name(),
            Method::Particle(m) => m.name(),
            Method::Relativistic(m) => m.name(),
        }
    }

    /// Name, family, order, stages and flags.
    pub fn info(&self) -> MethodInfo {
        match self {
            Method::Tableau(d) => d.info(),
            Method::Splitting(d) => d.info(),
            Method::RuntimeTableau(t) => t.info(),
            Method::RuntimeSplitting(s) => s.info(),
            Method::Particle(m) => m.info(),
            Method::Relativistic(m) => m.info(),
        }
    }

    /// True for a method that reaches its order only when the kinetic energy is
    /// quadratic (a Runge-Kutta-Nystrom splitting).
    pub fn requires_quadratic_kinetic(&self) -> bool {
        self.splitting_source().is_some_and(|s| s.requires_quadratic_kinetic())
    }

    /// The run-time tableau of a Butcher method; `None` for the other families.
    pub fn tableau(&self) -> Option<Result<Tableau, Error>> {
        match self {
            Method::Tableau(d) => Some(Tableau::from_data(d)),
            Method::RuntimeTableau(t) => Some(Ok(t.clone())),
            _ => None,
        }
    }

    /// The splitting or composition to build, for the splitting families.
    pub fn splitting_source(&self) -> Option<SplittingSource<'_>> {
        match self {
            Method::Splitting(d) => Some(SplittingSource::Compiled(d)),
            Method::RuntimeSplitting(s) => Some(SplittingSource::Runtime(s)),
            _ => None,
        }
    }

    /// The linear stability interval on the imaginary axis, from the coefficients: the
    /// largest `h omega` such that a step of every `h` up to it does not grow on the
    /// harmonic oscillator `q'' = -omega^2 q` (`|R(i h omega)| <= 1` for a tableau, the
    /// transfer matrix's `|trace| <= 2` for a splitting or composition;
    /// [`stormer_order::stability`]). A pusher's is not computed here (`Bounded(0)`).
    ///
    /// ```
    /// use stormer::verify::conditions::stability::Interval;
    /// use stormer::Method;
    /// let rk4 = Method::named("rk4").unwrap().stability_interval().value();
    /// assert!((rk4 - 8f64.sqrt()).abs() < 1e-9);
    /// let verlet = Method::named("velocity_verlet_kdk").unwrap().stability_interval().value();
    /// assert!((verlet - 2.0).abs() < 1e-9);
    /// assert_eq!(Method::named("euler").unwrap().stability_interval(), Interval::Bounded(0.0));
    /// assert_eq!(Method::named("gauss_legendre4").unwrap().stability_interval(), Interval::Unbounded);
    /// ```
    pub fn stability_interval(&self) -> Interval {
        match self {
            Method::Tableau(d) => butcher_interval(d.a, d.b),
            Method::Splitting(d) => splitting_interval(d.drift, d.kick),
            Method::RuntimeTableau(t) => butcher_interval(t.a(), t.b()),
            Method::RuntimeSplitting(s) => splitting_interval(s.drift(), s.kick()),
            Method::Particle(_) | Method::Relativistic(_) => Interval::Bounded(0.0),
        }
    }

    /// The stepper of this method for `problem`, starting from states shaped like `y0`.
    ///
    /// A Butcher tableau runs on every problem (a compiled explicit one as its generated,
    /// unrolled stepper; an implicit one with the solver `implicit` sets). A splitting or a
    /// pusher runs when the problem admits it ([`crate::Problem::families`]); otherwise the
    /// error is the sentence saying why and what to use instead.
    pub fn stepper_for<P>(&self, problem: &P, y0: &P::State, implicit: &ImplicitOptions) -> StepperResult<P>
    where
        P: Problem + 'static,
    {
        match self {
            Method::Tableau(d) => registry::runtime_tableau::<P>(&Tableau::from_data(d)?, y0, implicit),
            Method::RuntimeTableau(t) => registry::runtime_tableau::<P>(t, y0, implicit),
            Method::Splitting(d) => problem.families().splitting(SplittingSource::Compiled(d), y0),
            Method::RuntimeSplitting(s) => problem.families().splitting(SplittingSource::Runtime(s), y0),
            Method::Particle(m) => problem.families().particle(*m, y0),
            Method::Relativistic(m) => problem.families().relativistic(*m, y0),
        }
    }
}

/// A boxed stepper for problem `P`, or why it cannot be built.
pub type StepperResult<P> = Result<Box<dyn Stepper<P>>, Error>;

impl From<Tableau> for Method {
    fn from(tableau: Tableau) -> Self {
        Method::RuntimeTableau(tableau)
    }
}

impl From<Splitting> for Method {
    fn from(splitting: Splitting) -> Self {
        Method::RuntimeSplitting(splitting)
    }
}

/// True when `arg` is written as a file: it ends in `.toml` or has a path separator
/// (a bare name is a catalog name first: [`Method::resolve`]).
pub fn looks_like_path(arg: &str) -> bool {
    arg.ends_with(".toml") || arg.contains(['/', '\\'])
}

/// A method file's text holding a splitting or composition: its family says so, or it
/// has `drift`/`kick`/`word`/`gamma` keys (text that does not parse is left to the tableau
/// reader, which reports the TOML error).
fn is_splitting_text(text: &str) -> bool {
    let Ok(table) = text.parse::<toml::Table>() else {
        return false;
    };
    let entry = match table.get("method") {
        Some(toml::Value::Array(list)) => list.first().and_then(|m| m.as_table()).cloned(),
        _ => Some(table),
    };
    entry.is_some_and(|m| match m.get("family").and_then(|f| f.as_str()) {
        Some(family) => family == "splitting" || family == "composition",
        None => ["drift", "kick", "word", "gamma"].iter().any(|k| m.contains_key(*k)),
    })
}
