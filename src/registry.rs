//! Methods by name: the compiled catalog as a table, lookup with suggestions, and
//! steppers chosen at run time (the CLI's `--method`).

use crate::catalog;
use crate::method::{ButcherMethod, TableauData};
use crate::{Error, ImplicitOptions, ImplicitRk, Problem, RuntimeRk, Stepper, Tableau};

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

/// Every Butcher method compiled into the crate, in catalog order.
pub const BUTCHER: &[TableauData] = catalog::for_each_butcher_method!(data_list);

catalog::for_each_butcher_method!(dispatch);

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

/// Up to three catalog names closest to `key` (edit distance, prefix matches first).
fn nearest(key: &str) -> Vec<String> {
    let mut scored: Vec<(usize, &str)> = BUTCHER
        .iter()
        .map(|d| {
            let distance = strsim::damerau_levenshtein(key, d.name);
            let prefix = d.name.starts_with(key) || key.starts_with(d.name);
            (if prefix { distance.min(1) } else { distance }, d.name)
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
