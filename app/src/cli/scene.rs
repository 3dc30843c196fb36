//! `stormer scene list | show NAME`: the built-in scene files.

use super::output::print;
use crate::scenes::{self, builtin, BUILTIN};
use stormer::Error;

/// Lists the built-in scenes: name, model, description.
pub fn list() -> anyhow::Result<()> {
    let width = BUILTIN.iter().map(|s| s.name.len()).max().unwrap_or(0);
    let mut text = String::new();
    for s in BUILTIN {
        let scene = scenes::parse(s.text, "built-in", s.name)?;
        let description = scene.description().unwrap_or("");
        text.push_str(&format!("{:<width$}  {:<17}  {description}\n", s.name, scene.model()));
    }
    print(&text)?;
    Ok(())
}

/// Prints a built-in scene's TOML, to copy and edit.
pub fn show(name: &str) -> anyhow::Result<()> {
    let scene = builtin(name).ok_or_else(|| Error::Scene {
        file: name.to_string(),
        reason: format!(
            "not a built-in scene; the built-in scenes are {}",
            BUILTIN.iter().map(|s| s.name).collect::<Vec<_>>().join(", ")
        ),
    })?;
    print(scene.text)?;
    Ok(())
}
