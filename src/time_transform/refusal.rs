//! The transformations by name, and the one error for a problem that does not have the
//! structure they need.

use crate::Error;

/// A time transformation, as a program chooses it at run time.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Transform {
    /// The logarithmic Hamiltonian ([`super::LogH`]), `logh`.
    LogH,
    /// The time-transformed leapfrog ([`super::Ttl`]), `ttl`.
    Ttl,
}

impl Transform {
    /// Every transformation, by its name.
    pub const ALL: [(&'static str, Transform); 2] = [("logh", Transform::LogH), ("ttl", Transform::Ttl)];

    /// The transformation's name (`logh`, `ttl`).
    pub fn name(self) -> &'static str {
        match self {
            Transform::LogH => "logh",
            Transform::Ttl => "ttl",
        }
    }

    /// The transformation of that name (case-insensitive), or an error listing the names.
    ///
    /// ```
    /// use stormer::time_transform::Transform;
    /// assert_eq!(Transform::named("LogH").unwrap(), Transform::LogH);
    /// let e = Transform::named("sundman").unwrap_err().to_string();
    /// assert!(e.contains("sundman") && e.contains("logh, ttl"), "{e}");
    /// ```
    pub fn named(name: &str) -> Result<Transform, Error> {
        let wanted = name.trim().to_ascii_lowercase();
        Self::ALL
            .iter()
            .find(|(n, _)| *n == wanted)
            .map(|&(_, t)| t)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(|(n, _)| *n).collect();
                Error::invalid(
                    "time transformation",
                    format!("unknown name '{name}': the transformations are {}", names.join(", ")),
                )
            })
    }
}

/// The refusal of `transform` on the problem named `problem`, which lacks the structure
/// (`why`: what it has instead, e.g. "a velocity-dependent force (the Lorentz force of a
/// magnetic field)"). For a program that chooses the problem at run time: the compiler
/// already refuses the wrappers on a problem that does not implement
/// [`super::TimeTransformable`].
///
/// ```
/// use stormer::time_transform::{refused, Transform};
/// let e = refused(Transform::LogH, "magnetic-bottle", "its force depends on the velocity (Lorentz force)");
/// let text = e.to_string();
/// assert!(text.starts_with("invalid time transformation logh: the problem 'magnetic-bottle'"), "{text}");
/// assert!(text.contains("depends on the velocity"), "{text}");
/// ```
pub fn refused(transform: Transform, problem: &str, why: &str) -> Error {
    // "invalid time transformation logh: the problem ..." (not Unsupported, whose message
    // speaks of a method)
    Error::invalid(
        format!("time transformation {}", transform.name()),
        format!(
            "the problem '{problem}' has no separable Hamiltonian H = T(p) + V(q) with V < 0 and an \
             autonomous potential, which the transformation needs: {why}"
        ),
    )
}
