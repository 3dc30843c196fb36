//! Methods by name: the compiled catalog as a table, lookup with suggestions, and
//! steppers chosen at run time (the CLI's `--method`).

use crate::catalog;
use crate::flows::{QuadraticKinetic, Splittable};
use crate::method::{ButcherMethod, SplittingData, SplittingMethod, TableauData};
use crate::{
    Error, ImplicitOptions, ImplicitRk, Problem, RuntimeRk, RuntimeSplitting, Splitting, SplittingStepper, Stepper,
    Tableau,
};

macro_rules! data_list {
    ($($method:ident),* $(,)?) => {
        &[$(<catalog::$method as ButcherMethod>::DATA),*]
    };
}

macro_rules! dispatch {
    ($($method:ident),* $(,)?) => {
        fn compiled_stepper<P>(name: &str, y0: &P::State, implicit: &ImplicitOptions) -> Option<Box<dyn Stepper<P>>>
        where
            P: Problem + 'static,
        {
            $(
                if name == <catalog::$method as ButcherMethod>::DATA.name {
                    return Some(<catalog::$method as ButcherMethod>::dyn_stepper::<P>(y0, implicit));
                }
            )*
            None
        }
    };
}

macro_rules! splitting_data_list {
    (general: [$($g:ident),* $(,)?], quadratic: [$($r:ident),* $(,)?] $(,)?) => {
        &[$(<catalog::$g as SplittingMethod>::DATA,)* $(<catalog::$r as SplittingMethod>::DATA,)*]
    };
}

macro_rules! splitting_dispatch {
    (general: [$($g:ident),* $(,)?], quadratic: [$($r:ident),* $(,)?] $(,)?) => {
        /// The compiled stepper of the general splitting `name` (`None` when `name` is not
        /// one: unknown, or a method that needs a quadratic kinetic energy).
        #[allow(unused_variables)]
        fn compiled_splitting<P>(name: &str, y0: &P::State) -> Option<Result<Box<dyn Stepper<P>>, Error>>
        where
            P: Splittable + 'static,
        {
            $(
                if name == <catalog::$g as SplittingMethod>::DATA.name {
                    return Some(SplittingStepper::<catalog::$g, P::State, P::FlowCache>::boxed::<P>(y0));
                }
            )*
            None
        }

        /// The compiled stepper of any splitting `name`, for a quadratic-kinetic problem.
        #[allow(unused_variables)]
        fn compiled_splitting_quadratic<P>(name: &str, y0: &P::State) -> Option<Result<Box<dyn Stepper<P>>, Error>>
        where
            P: QuadraticKinetic + 'static,
        {
            $(
                if name == <catalog::$g as SplittingMethod>::DATA.name {
                    return Some(SplittingStepper::<catalog::$g, P::State, P::FlowCache>::boxed::<P>(y0));
                }
            )*
            $(
                if name == <catalog::$r as SplittingMethod>::DATA.name {
                    return Some(SplittingStepper::<catalog::$r, P::State, P::FlowCache>::boxed::<P>(y0));
                }
            )*
            None
        }
    };
}

/// Every Butcher method compiled into the crate, in catalog order.
pub const BUTCHER: &[TableauData] = catalog::for_each_butcher_method!(data_list);

/// Every splitting and composition compiled into the crate, in catalog order.
pub const SPLITTING: &[SplittingData] = catalog::for_each_splitting_method!(splitting_data_list);

catalog::for_each_butcher_method!(dispatch);
catalog::for_each_splitting_method!(splitting_dispatch);

/// The catalog spelling of a user's method name: lower case, `-` and spaces read as `_`.
pub fn normalize(name: &str) -> String {
    name.trim().to_lowercase().replace(['-', ' '], "_")
}

/// Looks a method up by name (`-` and `_` both accepted, and separators optional when
/// that names one method: `rk-4` is `rk4`); an unknown name is an error that suggests
/// the nearest catalog names.
///
/// ```
/// let rk4 = stormer::registry::find("rk4").unwrap();
/// assert_eq!(rk4.order, 4);
/// assert_eq!(stormer::registry::find("rk-4").unwrap().name, "rk4");
/// let err = stormer::registry::find("rk-5").unwrap_err();
/// assert!(err.to_string().contains("did you mean"));
/// ```
pub fn find(name: &str) -> Result<&'static TableauData, Error> {
    let key = normalize(name);
    let loose = |s: &str| s.replace('_', "");
    let mut without_separators = BUTCHER.iter().filter(|d| loose(d.name) == loose(&key));
    let unique_loose = match (without_separators.next(), without_separators.next()) {
        (Some(data), None) => Some(data),
        _ => None,
    };
    BUTCHER
        .iter()
        .find(|d| d.name == key)
        .or(unique_loose)
        .ok_or_else(|| Error::UnknownMethod {
            name: name.to_string(),
            suggestions: nearest(&key),
        })
}

/// A catalog method of any family.
#[derive(Debug, Clone, Copy)]
pub enum MethodRef {
    /// A Butcher tableau.
    Butcher(&'static TableauData),
    /// A splitting or composition.
    Splitting(&'static SplittingData),
}

impl MethodRef {
    /// The catalog name.
    pub fn name(&self) -> &'static str {
        match self {
            MethodRef::Butcher(d) => d.name,
            MethodRef::Splitting(d) => d.name,
        }
    }
}

/// Every catalog name, Butcher tableaus first.
pub fn names() -> impl Iterator<Item = &'static str> {
    BUTCHER.iter().map(|d| d.name).chain(SPLITTING.iter().map(|d| d.name))
}

/// Looks a method of any family up by name, with the spelling rules and suggestions of
/// [`find`].
pub fn lookup(name: &str) -> Result<MethodRef, Error> {
    let key = normalize(name);
    let loose = |s: &str| s.replace('_', "");
    let exact = names().find(|n| *n == key);
    let mut without_separators = names().filter(|n| loose(n) == loose(&key));
    let unique_loose = match (without_separators.next(), without_separators.next()) {
        (Some(n), None) => Some(n),
        _ => None,
    };
    let Some(found) = exact.or(unique_loose) else {
        return Err(Error::UnknownMethod {
            name: name.to_string(),
            suggestions: nearest(&key),
        });
    };
    Ok(match BUTCHER.iter().find(|d| d.name == found) {
        Some(d) => MethodRef::Butcher(d),
        None => MethodRef::Splitting(SPLITTING.iter().find(|d| d.name == found).expect("listed by names()")),
    })
}

/// Looks a splitting or composition up by name (see [`lookup`]); a Butcher method's name
/// is an error that says so.
pub fn find_splitting(name: &str) -> Result<&'static SplittingData, Error> {
    match lookup(name)? {
        MethodRef::Splitting(d) => Ok(d),
        MethodRef::Butcher(d) => Err(Error::Unsupported {
            name: d.name.to_string(),
            reason: "it is a Runge-Kutta tableau, not a splitting or composition".into(),
        }),
    }
}

/// The compiled stepper of a catalog splitting or composition for a general splittable
/// problem. A method that needs a quadratic kinetic energy is refused with a sentence
/// saying so (the typed [`crate::SplittingStepper`] refuses it at compile time).
pub fn splitting_stepper<P>(name: &str, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
where
    P: Splittable + 'static,
{
    let data = find_splitting(name)?;
    match compiled_splitting::<P>(data.name, y0) {
        Some(stepper) => stepper,
        None => Err(Error::Unsupported {
            name: data.name.to_string(),
            reason: "it reaches its order only when the kinetic energy is quadratic in p (a Runge-Kutta-Nystrom \
                     method), which this problem does not declare; use a general splitting or composition"
                .into(),
        }),
    }
}

/// The compiled stepper of any catalog splitting or composition, for a problem whose
/// kinetic energy is quadratic.
pub fn splitting_stepper_quadratic<P>(name: &str, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
where
    P: QuadraticKinetic + 'static,
{
    let data = find_splitting(name)?;
    compiled_splitting_quadratic::<P>(data.name, y0).unwrap_or_else(|| {
        Err(Error::UnknownMethod {
            name: name.to_string(),
            suggestions: Vec::new(),
        })
    })
}

/// A stepper for a splitting or composition built at run time (e.g. read from a file).
pub fn runtime_splitting_stepper<P>(method: &Splitting, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
where
    P: Splittable + 'static,
{
    Ok(Box::new(RuntimeSplitting::<P::State, P::FlowCache>::new(method, y0)?))
}

/// Up to three catalog names closest to `key` (edit distance, prefix matches first).
fn nearest(key: &str) -> Vec<String> {
    let mut scored: Vec<(usize, &str)> = names()
        .map(|name| {
            let distance = strsim::damerau_levenshtein(key, name);
            let prefix = name.starts_with(key) || key.starts_with(name);
            (if prefix { distance.min(1) } else { distance }, name)
        })
        .collect();
    scored.sort();
    let best = scored.first().map_or(0, |s| s.0);
    scored
        .into_iter()
        .filter(|&(d, _)| d <= best.max(2) + 1 && d <= key.len().max(3))
        .take(3)
        .map(|(_, n)| n.to_string())
        .collect()
}

/// A stepper for the catalog method `name` on problem `P`: the generated, unrolled
/// stepper for explicit tableaus, the implicit solver for the others.
pub fn stepper<P>(name: &str, y0: &P::State, implicit: &ImplicitOptions) -> Result<Box<dyn Stepper<P>>, Error>
where
    P: Problem + 'static,
{
    let data = find(name)?;
    compiled_stepper::<P>(data.name, y0, implicit).ok_or_else(|| Error::UnknownMethod {
        name: name.to_string(),
        suggestions: Vec::new(),
    })
}

/// A stepper for a tableau built at run time (e.g. read from a file).
pub fn tableau_stepper<P>(
    tableau: &Tableau,
    y0: &P::State,
    implicit: &ImplicitOptions,
) -> Result<Box<dyn Stepper<P>>, Error>
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
/// (SCENES.md 6: "semi-implicit Euler with weight alpha"): `alpha = 1` is explicit Euler,
/// `alpha = 0` backward Euler, `alpha = 1/2` the trapezoidal rule (order 2).
///
/// As a tableau: `c = [0, 1]`, `a = [[0, 0], [alpha, 1 - alpha]]`, `b = [alpha, 1 - alpha]`.
///
/// ```
/// let t = stormer::registry::theta(0.5).unwrap();
/// assert_eq!(t.order(), 2);
/// assert!(stormer::registry::theta(f64::NAN).is_err());
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
        b_hat: None,
        embedded_order: None,
        b_hat3: None,
        tolerance: None,
    };
    Tableau::new(format!("theta({alpha})"), &spec)
}
