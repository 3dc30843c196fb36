//! Methods by name: the compiled catalog as a table, the names users bring from other
//! libraries ([`ALIASES`]), and lookup with suggestions. A name resolves to a [`Method`],
//! whose [`Method::stepper_for`] builds the stepper.

use crate::catalog;
use crate::method::Tableau;
use crate::method::{ButcherMethod, SplittingData, SplittingMethod, StepperResult, TableauData};
use crate::stepper::{ImplicitOptions, ImplicitRk, RuntimeRk};
use crate::{Error, Method, Problem};

macro_rules! data_list {
    ($($method:ident),* $(,)?) => {
        &[$(<catalog::$method as ButcherMethod>::DATA),*]
    };
}

macro_rules! splitting_data_list {
    (general: [$($g:ident),* $(,)?], quadratic: [$($r:ident),* $(,)?] $(,)?) => {
        &[$(<catalog::$g as SplittingMethod>::DATA,)* $(<catalog::$r as SplittingMethod>::DATA,)*]
    };
}

/// Every Butcher method compiled into the crate, in catalog order. A static, so that each
/// entry has one address: [`Method::named`] hands out these entries, and the compiled
/// dispatch (`Method::compiled_stepper_for`) recognises the catalog's own methods by it.
pub static BUTCHER: &[TableauData] = catalog::for_each_butcher_method!(data_list);

/// Every splitting and composition compiled into the crate, in catalog order (a static, as
/// [`BUTCHER`]).
pub static SPLITTING: &[SplittingData] = catalog::for_each_splitting_method!(splitting_data_list);

/// The names users bring from other libraries, as `(alias, catalog name, where it comes
/// from)`. An alias is matched with the spelling rules of [`Method::named`] (case, `-`, `_` and
/// spaces do not matter), so `RK45`, `rk-45` and `rk45` are one alias.
pub const ALIASES: &[(&str, &str, &str)] = &[
    ("RK45", "dormand_prince5", "scipy"),
    ("RK23", "bogacki_shampine3", "scipy"),
    ("Radau", "radau_iia5", "scipy"),
    ("DP5", "dormand_prince5", "OrdinaryDiffEq.jl"),
    ("DP8", "dop853", "OrdinaryDiffEq.jl"),
    ("dopri5", "dormand_prince5", "Hairer, boost odeint"),
    ("dopri853", "dop853", "Hairer"),
    ("ode45", "dormand_prince5", "MATLAB"),
    ("ode23", "bogacki_shampine3", "MATLAB"),
    ("BS3", "bogacki_shampine3", "OrdinaryDiffEq.jl"),
    ("Tsit5", "tsitouras5", "OrdinaryDiffEq.jl"),
    ("Vern6", "verner6", "OrdinaryDiffEq.jl"),
    ("Vern7", "verner7", "OrdinaryDiffEq.jl"),
    ("Vern8", "verner8", "OrdinaryDiffEq.jl"),
    ("Vern9", "verner9", "OrdinaryDiffEq.jl"),
    ("RKF45", "fehlberg45", "Fehlberg"),
    ("RKF78", "fehlberg78", "Fehlberg"),
    ("CashKarp", "cash_karp", "Numerical Recipes"),
    ("Heun", "heun2", "OrdinaryDiffEq.jl"),
    ("Ralston", "ralston2", "OrdinaryDiffEq.jl"),
    ("RK438", "rk4_38", "OrdinaryDiffEq.jl"),
    ("SSPRK33", "ssprk33", "OrdinaryDiffEq.jl"),
    ("SSPRK43", "ssprk43", "OrdinaryDiffEq.jl"),
    ("ImplicitEuler", "backward_euler", "OrdinaryDiffEq.jl"),
    ("ImplicitMidpoint", "implicit_midpoint", "OrdinaryDiffEq.jl"),
    ("Trapezoid", "trapezoidal", "OrdinaryDiffEq.jl"),
    ("CrankNicolson", "trapezoidal", "textbooks"),
    ("RadauIIA3", "radau_iia3", "OrdinaryDiffEq.jl"),
    ("RadauIIA5", "radau_iia5", "OrdinaryDiffEq.jl"),
    ("GL4", "gauss_legendre4", "textbooks"),
    ("GL6", "gauss_legendre6", "textbooks"),
    (
        "SymplecticEuler",
        "symplectic_euler_dk",
        "OrdinaryDiffEq.jl, boost odeint (drift first)",
    ),
    ("VelocityVerlet", "velocity_verlet_kdk", "OrdinaryDiffEq.jl"),
    ("VerletLeapfrog", "velocity_verlet_kdk", "OrdinaryDiffEq.jl"),
    ("verlet", "velocity_verlet_kdk", "common usage"),
    ("leapfrog", "stormer_verlet_dkd", "REBOUND (drift-kick-drift)"),
    ("LeapfrogDriftKickDrift", "stormer_verlet_dkd", "OrdinaryDiffEq.jl"),
    ("PseudoVerletLeapfrog", "stormer_verlet_dkd", "OrdinaryDiffEq.jl"),
    ("McAte2", "mclachlan_atela2", "OrdinaryDiffEq.jl"),
    ("McAte3", "mclachlan_atela3", "OrdinaryDiffEq.jl"),
    (
        "McAte4",
        "mclachlan_atela4",
        "OrdinaryDiffEq.jl (ours has the roles right: order 4)",
    ),
    (
        "McAte5",
        "mclachlan_atela5",
        "OrdinaryDiffEq.jl (ours has the roles right: order 5)",
    ),
    ("McAte8", "mclachlan_ss15", "OrdinaryDiffEq.jl"),
    ("CandyRoz4", "forest_ruth4", "OrdinaryDiffEq.jl"),
    (
        "CalvoSanz4",
        "calvo_sanz_serna4",
        "OrdinaryDiffEq.jl (ours has the roles right: order 4)",
    ),
    ("Yoshida6", "yoshida6a", "OrdinaryDiffEq.jl"),
    ("KahanLi6", "kahan_li6", "OrdinaryDiffEq.jl"),
    ("KahanLi8", "kahan_li8", "OrdinaryDiffEq.jl"),
    ("SofSpa10", "sofroniou_spaletta10", "OrdinaryDiffEq.jl"),
    (
        "wisdom_holman",
        "stormer_verlet_dkd",
        "Wisdom and Holman 1991, REBOUND's WHFast (drift-kick-drift): the Wisdom-Holman method with --split \
         kepler-jacobi",
    ),
    ("leapfrog4", "triple_jump4", "REBOUND (LF4)"),
    ("LF6", "mclachlan_ss9", "REBOUND"),
    ("LF8", "mclachlan_ss17", "REBOUND"),
];

/// The catalog spelling of a user's method name: lower case, `-` and spaces read as `_`.
pub fn normalize(name: &str) -> String {
    name.trim().to_lowercase().replace(['-', ' '], "_")
}

/// The method of `all` whose `name_of` is the user's `name`, spelled as [`normalize`]
/// reads it: the lookup of the methods that are named in code, not in the catalog.
pub(crate) fn find_named<M: Copy>(all: &[M], name_of: fn(M) -> &'static str, name: &str) -> Option<M> {
    let key = normalize(name);
    all.iter().copied().find(|&m| name_of(m) == key)
}

/// Every catalog name, Butcher tableaus first.
pub fn names() -> impl Iterator<Item = &'static str> {
    BUTCHER.iter().map(|d| d.name).chain(SPLITTING.iter().map(|d| d.name))
}

/// The aliases of the catalog method `name`.
pub fn aliases_of(name: &str) -> impl Iterator<Item = &'static str> + '_ {
    ALIASES.iter().filter(move |a| a.1 == name).map(|a| a.0)
}

/// Looks a catalog method of any family up by name or alias: `-`, `_` and spaces are one
/// separator, and separators are optional when that names one method (`rk-4` is `rk4`);
/// an unknown name is an error that suggests the nearest names and aliases. This is the
/// one place a name becomes a [`Method`] ([`Method::named`]).
pub(crate) fn lookup(name: &str) -> Result<Method, Error> {
    let key = normalize(name);
    let loose = |s: &str| normalize(s).replace('_', "");
    let alias = ALIASES.iter().find(|a| loose(a.0) == loose(&key)).map(|a| a.1);
    let exact = names().find(|n| *n == key);
    let mut without_separators = names().filter(|n| loose(n) == loose(&key));
    let unique_loose = match (without_separators.next(), without_separators.next()) {
        (Some(n), None) => Some(n),
        _ => None,
    };
    let Some(found) = exact.or(unique_loose).or(alias) else {
        return Err(Error::UnknownMethod {
            name: name.to_string(),
            suggestions: nearest(&key),
        });
    };
    Ok(match BUTCHER.iter().find(|d| d.name == found) {
        Some(d) => Method::Tableau(d),
        None => Method::Splitting(SPLITTING.iter().find(|d| d.name == found).expect("listed by names()")),
    })
}

/// Looks a Butcher tableau up by name or alias ([`Method::named`]); a splitting's name is an
/// error that says so.
///
/// ```
/// let rk4 = stormer::catalog::find("rk4").unwrap();
/// assert_eq!(rk4.order, 4);
/// assert_eq!(stormer::catalog::find("DOP853").unwrap().name, "dop853");
/// assert!(stormer::catalog::find("rk-5").unwrap_err().to_string().contains("did you mean"));
/// ```
pub fn find(name: &str) -> Result<&'static TableauData, Error> {
    match lookup(name)? {
        Method::Tableau(d) => Ok(d),
        other => Err(Error::Unsupported {
            name: other.name().to_string(),
            reason: "it is a splitting or composition, not a Runge-Kutta tableau".into(),
        }),
    }
}

/// Looks a splitting or composition up by name or alias ([`Method::named`]); a Butcher method's
/// name is an error that says so.
pub fn find_splitting(name: &str) -> Result<&'static SplittingData, Error> {
    match lookup(name)? {
        Method::Splitting(d) => Ok(d),
        other => Err(Error::Unsupported {
            name: other.name().to_string(),
            reason: "it is a Runge-Kutta tableau, not a splitting or composition".into(),
        }),
    }
}

/// Up to three names or aliases closest to `key` (edit distance, prefix matches first).
fn nearest(key: &str) -> Vec<String> {
    let candidates = names().chain(ALIASES.iter().map(|a| a.0));
    let mut scored: Vec<(usize, String)> = candidates
        .map(|name| {
            let spelled = normalize(name);
            let distance = strsim::damerau_levenshtein(key, &spelled);
            let prefix = spelled.starts_with(key) || key.starts_with(spelled.as_str());
            (if prefix { distance.min(1) } else { distance }, name.to_string())
        })
        .collect();
    scored.sort();
    scored.dedup_by(|a, b| a.1 == b.1);
    let best = scored.first().map_or(0, |s| s.0);
    scored
        .into_iter()
        .filter(|(d, _)| *d <= best.max(2) + 1 && *d <= key.len().max(3))
        .take(3)
        .map(|(_, n)| n)
        .collect()
}

/// The stepper of a tableau held as data (a catalog entry, a method file, [`theta`]).
pub(crate) fn runtime_tableau<P>(tableau: &Tableau, y0: &P::State, implicit: &ImplicitOptions) -> StepperResult<P>
where
    P: Problem + 'static,
{
    if tableau.flags().explicit {
        Ok(Box::new(RuntimeRk::new(tableau, y0)?))
    } else {
        Ok(Box::new(ImplicitRk::new(tableau, y0, *implicit)))
    }
}

/// The theta method `y_{n+1} = y_n + h [alpha f(t_n, y_n) + (1 - alpha) f(t_{n+1}, y_{n+1})]`
/// (docs/scenes.md 6: "semi-implicit Euler with weight alpha"): `alpha = 1` is explicit Euler,
/// `alpha = 0` backward Euler, `alpha = 1/2` the trapezoidal rule (order 2).
///
/// As a tableau: `c = [0, 1]`, `a = [[0, 0], [alpha, 1 - alpha]]`, `b = [alpha, 1 - alpha]`.
///
/// ```
/// let t = stormer::catalog::theta(0.5).unwrap();
/// assert_eq!(t.order(), 2);
/// assert!(stormer::catalog::theta(f64::NAN).is_err());
/// ```
pub fn theta(alpha: f64) -> Result<Tableau, Error> {
    if !(alpha.is_finite() && (0.0..=1.0).contains(&alpha)) {
        return Err(Error::invalid("alpha", format!("must be in [0, 1], got {alpha}")));
    }
    #[allow(clippy::float_cmp)]
    let order = if alpha == 0.5 { 2 } else { 1 };
    let spec = stormer_order::TableauSpec {
        a: vec![vec![0.0, 0.0], vec![alpha, 1.0 - alpha]],
        b: vec![alpha, 1.0 - alpha],
        c: Some(vec![0.0, 1.0]),
        order,
        ..Default::default()
    };
    Tableau::new(format!("theta({alpha})"), &spec)
}
