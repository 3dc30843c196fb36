//! The `[[particles]]` list of the charged-particle scene files, read into masses, charges,
//! positions and velocities: one particle per entry, or, with `count`, a sample of many
//! particles drawn from a seed (the same particles on every machine and every run).
//!
//! ```toml
//! [[particles]]                  # 100000 particles, uniform in boxes
//! count = 100000
//! seed = 7                       # optional, default 1
//! ratio = -1.0
//! position = [0.0, 0.0, 0.0]     # the centre of the positions' box
//! position_spread = [1.0, 1.0, 0.5]    # its half-widths (optional, default 0)
//! velocity = [0.0, 0.0, 0.0]
//! velocity_spread = [0.3, 0.3, 0.3]
//! ```

use super::charged_file::{mass_and_charge, vector3, ParticleEntry};
use super::file::Source;
use super::nbody_file::{column, Taken};
use stormer::models::SplitMix64;
use stormer::Error;
use toml::Spanned;

/// Particles read from a `[[particles]]` list.
#[derive(Debug, Default)]
pub(super) struct ParticleList {
    pub names: Vec<String>,
    pub masses: Vec<f64>,
    pub charges: Vec<f64>,
    /// `3N` positions, particle after particle.
    pub positions: Vec<f64>,
    /// `3N` velocities.
    pub velocities: Vec<f64>,
}

/// At most this many particles in one scene (10^8: 4.8 GB per state in `f64`).
const MOST_PARTICLES: u64 = 100_000_000;

/// A point of the box `centre +- spread`, drawn from `sample`.
fn in_box(sample: &mut SplitMix64, centre: &[f64; 3], spread: &[f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| centre[i] + spread[i] * sample.draw())
}

/// The CSV columns of particles in 3-D named `names`: `<name>_x, <name>_y, <name>_z` for
/// every particle, then `<name>_<rate>x, ...` (`rate` is `v` for velocities, `u` for
/// momenta per unit mass); a single particle has `x, y, z, <rate>x, <rate>y, <rate>z`.
pub(super) fn particle_columns(names: &[String], rate: &str) -> Vec<String> {
    let single = names.len() == 1;
    let prefix = |n: &String| {
        if single {
            String::new()
        } else {
            format!("{}_", column(n))
        }
    };
    let q = names
        .iter()
        .flat_map(|n| ["x", "y", "z"].map(|a| format!("{}{a}", prefix(n))));
    let v = names
        .iter()
        .flat_map(|n| ["x", "y", "z"].map(|a| format!("{}{rate}{a}", prefix(n))));
    q.chain(v).collect()
}

/// Reads the list, calling `check(entry, name, position, entry's span)` on every particle
/// (a scene's own conditions: not at a Coulomb centre, ...).
pub(super) fn read_particles(
    src: &Source<'_>,
    entries: &Spanned<Vec<Spanned<ParticleEntry>>>,
    mut check: impl FnMut(usize, &str, &[f64; 3], &ParticleList) -> Result<(), Error>,
) -> Result<ParticleList, Error> {
    if entries.get_ref().is_empty() {
        return Err(src.error_at(
            entries.span(),
            "the scene has no particles: give at least one [[particles]] entry",
        ));
    }
    let mut list = ParticleList::default();
    let mut taken = Taken::default();
    for (k, entry) in entries.get_ref().iter().enumerate() {
        let p = entry.get_ref();
        let name = match &p.name {
            Some(n) => taken.name(src, "particles", k, n)?,
            None => format!("p{k}"),
        };
        let (mass, charge) = mass_and_charge(src, k, &name, entry)?;
        let q = vector3(src, &format!("particles[{k}].position ({name})"), &p.position)?;
        let v = vector3(src, &format!("particles[{k}].velocity ({name})"), &p.velocity)?;
        let spread = |what: &str, s: &Option<Spanned<Vec<toml::Spanned<f64>>>>| -> Result<[f64; 3], Error> {
            let Some(s) = s else { return Ok([0.0; 3]) };
            if p.count.is_none() {
                return Err(src.error_at(
                    s.span(),
                    format!("particles[{k}].{what} ({name}) needs count = ... (it spreads a sample of particles)"),
                ));
            }
            let x = vector3(src, &format!("particles[{k}].{what} ({name})"), s)?;
            match x.iter().find(|&&c| c < 0.0) {
                Some(c) => Err(src.error_at(
                    s.span(),
                    format!("particles[{k}].{what} ({name}) must be >= 0 in each direction, got {c}"),
                )),
                None => Ok(x),
            }
        };
        let (q_spread, v_spread) = (
            spread("position_spread", &p.position_spread)?,
            spread("velocity_spread", &p.velocity_spread)?,
        );
        let Some(count) = &p.count else {
            if let Some(seed) = &p.seed {
                return Err(src.error_at(
                    seed.span(),
                    format!("particles[{k}].seed ({name}) needs count = ... (it seeds a sample of particles)"),
                ));
            }
            check(k, &name, &q, &list)?;
            list.push(name, mass, charge, q, v);
            continue;
        };
        let n = *count.get_ref();
        let room = MOST_PARTICLES.saturating_sub(list.masses.len() as u64);
        if n == 0 || n > room {
            return Err(src.error_at(
                count.span(),
                format!(
                    "particles[{k}].count ({name}) must be between 1 and {room} (at most {MOST_PARTICLES} particles in \
                     a scene), got {n}"
                ),
            ));
        }
        let mut sample = SplitMix64::new(p.seed.as_ref().map_or(1, |s| *s.get_ref()));
        list.reserve(n as usize);
        for j in 0..n {
            let (qj, vj) = (in_box(&mut sample, &q, &q_spread), in_box(&mut sample, &v, &v_spread));
            let name_j = format!("{name}_{j}");
            check(k, &name_j, &qj, &list)?;
            list.push(name_j, mass, charge, qj, vj);
        }
    }
    Ok(list)
}

impl ParticleList {
    fn push(&mut self, name: String, mass: f64, charge: f64, q: [f64; 3], v: [f64; 3]) {
        self.names.push(name);
        self.masses.push(mass);
        self.charges.push(charge);
        self.positions.extend_from_slice(&q);
        self.velocities.extend_from_slice(&v);
    }

    fn reserve(&mut self, n: usize) {
        self.names.reserve(n);
        self.masses.reserve(n);
        self.charges.reserve(n);
        self.positions.reserve(3 * n);
        self.velocities.reserve(3 * n);
    }
}
