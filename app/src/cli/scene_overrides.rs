//! The arguments with which `stormer run` and `stormer ensemble` override a scene's run:
//! the method, the step size and the end time.

use stormer::Error;

/// `--method`, `--dt`, `--t-end`, each defaulting to the scene file's.
#[derive(Debug, clap::Args)]
pub struct SceneOverrides {
    /// The method: a catalog name (`stormer methods`), a TOML method file, or `theta`
    /// [default: the scene's].
    #[arg(long, short, value_name = "NAME|FILE")]
    pub method: Option<String>,
    /// Step size (> 0) [default: the scene's]; with `run --rtol/--atol`, the first step.
    #[arg(long, value_name = "H", allow_negative_numbers = true)]
    pub dt: Option<f64>,
    /// End time [default: the scene's].
    #[arg(long, value_name = "T", allow_negative_numbers = true)]
    pub t_end: Option<f64>,
}

impl SceneOverrides {
    /// The values' own domains: a step size is a finite number > 0, an end time finite.
    pub fn check(&self) -> Result<(), Error> {
        if let Some(h) = self.dt.filter(|h| !(h.is_finite() && *h > 0.0)) {
            return Err(Error::invalid("--dt", format!("must be a finite number > 0, got {h}")));
        }
        if let Some(t) = self.t_end.filter(|t| !t.is_finite()) {
            return Err(Error::invalid("--t-end", format!("must be a finite number, got {t}")));
        }
        Ok(())
    }
}
