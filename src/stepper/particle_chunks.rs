//! Pushing particles that do not interact, chunk by chunk: in parallel on every core
//! (rayon, with the crate's feature `parallel`) above [`PARALLEL_FROM`] particles, one
//! after the other below (and always without the feature).
//!
//! The chunks are fixed ([`CHUNK`] particles each, whatever the number of threads) and
//! each particle's push reads only its own state and the fields, so the result is bitwise
//! the same on 1 thread or many (`tests/many_particles.rs`).

use crate::Error;
#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Particles per chunk, the unit of work of a thread (a few thousand: enough to hide the
/// cost of handing a chunk over, small enough to balance 2 to 64 cores).
pub const CHUNK: usize = 4096;

/// From this many particles on, the chunks run in parallel (below, the cost of waking the
/// threads outweighs the work: measured in docs/benchmarks.md, "Many charged particles").
pub const PARALLEL_FROM: usize = 16_384;

/// Refuses, for the pusher `name`, a state of `dim` components that is not particles in
/// 3-D: `halves` (`(q, v)`, `(x, u)`) with 6 components per particle, at least one.
pub(crate) fn check_particles_in_3d(name: &str, halves: &str, dim: usize) -> Result<(), Error> {
    if dim == 0 || dim % 6 != 0 {
        return Err(Error::Unsupported {
            name: name.into(),
            reason: format!("it moves particles in 3-D: the state {halves} needs 6 components per particle, not {dim}"),
        });
    }
    Ok(())
}

/// Calls `push(first, q, v)` on every chunk of particles: `q` and `v` are the chunk's
/// positions and velocities (3 components per particle, particle after particle; `q`
/// and `v` the two halves of a state), `first` the index of its first particle. Stops at
/// the first error (with several threads, any one of the errors).
pub(crate) fn try_for_each_chunk<T, F>(q: &mut [T], v: &mut [T], push: F) -> Result<(), Error>
where
    T: Send,
    F: Fn(usize, &mut [T], &mut [T]) -> Result<(), Error> + Sync,
{
    #[cfg(feature = "parallel")]
    if q.len() / 3 >= PARALLEL_FROM {
        return q
            .par_chunks_mut(3 * CHUNK)
            .zip(v.par_chunks_mut(3 * CHUNK))
            .enumerate()
            .try_for_each(|(c, (q, v))| push(c * CHUNK, q, v));
    }
    q.chunks_mut(3 * CHUNK)
        .zip(v.chunks_mut(3 * CHUNK))
        .enumerate()
        .try_for_each(|(c, (q, v))| push(c * CHUNK, q, v))
}
