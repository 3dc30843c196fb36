//! The command-line arguments of `stormer compare`, `scan` and `merge`, and the checks of
//! their numbers that clap does not make.

use std::path::PathBuf;
use stormer::Error;

/// Options shared by `compare` and `scan`.
#[derive(Debug, Clone, clap::Args)]
pub struct CommonArgs {
    /// End time [default: the scene's].
    #[arg(long, value_name = "T", allow_negative_numbers = true)]
    pub t_end: Option<f64>,
    /// Directory of the tables and diagrams.
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
    /// Run only the I-th of N parts of the work list (1 <= I <= N) and write a partial
    /// table for `stormer merge`.
    #[arg(long, value_name = "I/N", value_parser = parse_shard)]
    pub shard: Option<(usize, usize)>,
    /// Where reference solutions are cached (scenes without an exact solution).
    #[arg(long, value_name = "DIR", default_value = "out/references")]
    pub cache: PathBuf,
    /// Timing: best of at least this many runs.
    #[arg(long, value_name = "N", default_value_t = 3)]
    pub runs: u32,
    /// Timing: more runs (up to 100) while their total is under this many seconds.
    #[arg(long, value_name = "SECONDS", default_value_t = 0.2)]
    pub min_time: f64,
    /// Worker threads [default: one per core]; `--jobs 1` for quieter timings.
    #[arg(long, value_name = "N")]
    pub jobs: Option<usize>,
}

/// Arguments of `stormer compare`.
#[derive(Debug, clap::Args)]
pub struct CompareArgs {
    /// A built-in scene (see `stormer scene list`) or a path to a scene file (.toml).
    pub scene: String,
    /// The methods: catalog names or TOML method files, separated by commas; a suffix
    /// `@logh`, `@ttl` or `@none` runs the method in that time transformation of the scene
    /// (`triple_jump4@logh,triple_jump4@none,dop853@none`; without one, as the scene's
    /// file says).
    #[arg(long, value_name = "A,B,..", value_delimiter = ',', required = true)]
    pub methods: Vec<String>,
    /// Fixed step sizes (of the time t), separated by commas.
    #[arg(long, value_name = "H,..", value_delimiter = ',')]
    pub dt: Vec<f64>,
    /// Fixed steps of the fictitious time s, for the methods run in a time transformation
    /// [default: --dt, read as steps of s].
    #[arg(long, value_name = "H,..", value_delimiter = ',')]
    pub ds: Vec<f64>,
    /// Tolerances (rtol = atol) of adaptive runs, for the methods with an embedded pair.
    #[arg(long, value_name = "TOL,..", value_delimiter = ',')]
    pub tolerances: Vec<f64>,
    #[command(flatten)]
    pub common: CommonArgs,
}

/// Arguments of `stormer scan`.
#[derive(Debug, clap::Args)]
pub struct ScanArgs {
    /// A built-in scene (see `stormer scene list`) or a path to a scene file (.toml).
    pub scene: String,
    /// The method (or several, separated by commas: one line each).
    #[arg(long, short, value_name = "NAME|FILE", value_delimiter = ',', required = true)]
    pub method: Vec<String>,
    /// Numbers of fixed steps over the time span, separated by commas.
    #[arg(long, value_name = "N,..", value_delimiter = ',', required = true)]
    pub steps: Vec<u64>,
    #[command(flatten)]
    pub common: CommonArgs,
}

/// Arguments of `stormer merge`.
#[derive(Debug, clap::Args)]
pub struct MergeArgs {
    /// The partial tables (`*.shard-I-of-N.json`) of one study, all of them.
    #[arg(required = true, value_name = "PART.json")]
    pub parts: Vec<PathBuf>,
    /// Directory of the tables and diagrams.
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
}

pub(super) fn parse_shard(s: &str) -> Result<(usize, usize), String> {
    let bad = || format!("expected I/N with 1 <= I <= N (e.g. 2/3), got '{s}'");
    let (i, n) = s.split_once('/').ok_or_else(bad)?;
    let i: usize = i.trim().parse().map_err(|_| bad())?;
    let n: usize = n.trim().parse().map_err(|_| bad())?;
    if i == 0 || n == 0 || i > n {
        return Err(bad());
    }
    Ok((i, n))
}

pub(super) fn check_common(c: &CommonArgs) -> Result<(), Error> {
    if let Some(t) = c.t_end.filter(|t| !t.is_finite()) {
        return Err(Error::invalid("--t-end", format!("must be a finite number, got {t}")));
    }
    if c.runs == 0 {
        return Err(Error::invalid("--runs", "must be >= 1, got 0"));
    }
    if !(c.min_time.is_finite() && c.min_time >= 0.0) {
        return Err(Error::invalid(
            "--min-time",
            format!("must be a number >= 0, got {}", c.min_time),
        ));
    }
    if c.jobs == Some(0) {
        return Err(Error::invalid("--jobs", "must be >= 1, got 0"));
    }
    Ok(())
}

pub(super) fn positive_list(what: &str, list: &[f64]) -> Result<(), Error> {
    match list.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
        Some(v) => Err(Error::invalid(what, format!("must be finite numbers > 0, got {v}"))),
        None => Ok(()),
    }
}
