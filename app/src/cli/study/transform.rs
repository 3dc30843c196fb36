//! Which time transformation each method of a study runs in: `--methods
//! triple_jump4@logh,triple_jump4@none,dop853@none` puts the same scene, transformed and
//! not, on one work-precision front (docs/close-approaches.md). A method without a suffix
//! runs the scene as its file says. The study keeps the transformation of each method by
//! name ([`super::MethodEntry::transform`]), so a shard's jobs run in it and its labels say it.

use crate::scenes::AnyScene;
use std::path::Path;
use stormer::time_transform::Transform;
use stormer::Error;

/// The name of the untransformed scene in a suffix and in a study.
pub const NONE: &str = "none";

/// What a method's suffix asks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Asked {
    /// No suffix: the scene as its file says.
    AsTheFileSays,
    /// `@none`: the scene untransformed, whatever its file says.
    Untransformed,
    /// `@logh`, `@ttl`.
    In(Transform),
}

/// The names a suffix can take, for the errors.
fn names() -> String {
    let mut names: Vec<&str> = Transform::ALL.iter().map(|(n, _)| *n).collect();
    names.push(NONE);
    names.join(", ")
}

/// `given` split into the method and what its suffix asks (`triple_jump4@logh`). A method
/// file that exists is read whole, whatever its name holds.
pub fn split(given: &str) -> Result<(&str, Asked), Error> {
    if Path::new(given).is_file() {
        return Ok((given, Asked::AsTheFileSays));
    }
    let Some((method, suffix)) = given.rsplit_once('@') else {
        return Ok((given, Asked::AsTheFileSays));
    };
    Ok((
        method,
        named(suffix).map_err(|why| Error::invalid("--methods", format!("{given}: {why}")))?,
    ))
}

/// The transformation of that name (`none`, `logh`, `ttl`), as a suffix and a study give
/// it; the error lists the names.
pub fn named(name: &str) -> Result<Asked, String> {
    if name.trim().eq_ignore_ascii_case(NONE) {
        return Ok(Asked::Untransformed);
    }
    Transform::named(name).map(Asked::In).map_err(|_| {
        format!(
            "unknown time transformation '{name}' (write METHOD@T, T one of {})",
            names()
        )
    })
}

/// The transformation a study keeps for a method (`None`: the scene as its file says).
pub fn kept(name: Option<&str>) -> Result<Asked, Error> {
    match name {
        None => Ok(Asked::AsTheFileSays),
        Some(name) => named(name).map_err(|why| Error::invalid("transform", why)),
    }
}

/// The scene in the transformation asked; a model without the structure, or a scene in
/// the Kepler split, is refused with the scene's sentence.
pub fn apply(scene: AnyScene, asked: Asked) -> Result<AnyScene, Error> {
    match asked {
        Asked::AsTheFileSays => Ok(scene),
        Asked::Untransformed => Ok(scene.without_time_transform()),
        Asked::In(t) if scene.time_transform() == Some(t) => Ok(scene),
        Asked::In(t) => scene.with_time_transform(t),
    }
}

/// The name of the transformation a scene runs in (`none` for none).
pub fn name_of(scene: &AnyScene) -> &'static str {
    scene.time_transform().map_or(NONE, Transform::name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suffixes_name_the_transformation() {
        assert_eq!(split("triple_jump4").unwrap(), ("triple_jump4", Asked::AsTheFileSays));
        assert_eq!(
            split("triple_jump4@LogH").unwrap(),
            ("triple_jump4", Asked::In(Transform::LogH))
        );
        assert_eq!(split("dop853@none").unwrap(), ("dop853", Asked::Untransformed));
        let e = split("triple_jump4@sundman").unwrap_err().to_string();
        assert!(
            e.contains("triple_jump4@sundman") && e.contains("'sundman'") && e.contains("logh, ttl, none"),
            "{e}"
        );
        assert_eq!(kept(Some("ttl")).unwrap(), Asked::In(Transform::Ttl));
        assert!(kept(Some("x")).is_err());
    }
}
