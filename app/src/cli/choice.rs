//! What `--method` names, as the library's [`Method`]: the theta method takes its weight
//! from `--alpha`; every other name, alias or method file is [`Method::resolve`]'s.

use stormer::catalog::normalize;
use stormer::{Error, Method};

/// Resolves `name` once for a run: `theta` (with `alpha`, default 1/2), or what
/// [`Method::resolve`] reads (a pusher, a method file, a catalog name or alias; an unknown
/// name is an error suggesting the nearest ones).
pub fn resolve(name: &str, alpha: Option<f64>) -> Result<Method, Error> {
    if normalize(name) == "theta" {
        return Method::theta(alpha.unwrap_or(0.5)).map_err(|e| match e {
            Error::InvalidArgument { reason, .. } => Error::invalid("--alpha", reason),
            other => other,
        });
    }
    if alpha.is_some() {
        return Err(Error::invalid(
            "--alpha",
            format!("it applies to --method theta only, not to {name}"),
        ));
    }
    Method::resolve(name)
}
