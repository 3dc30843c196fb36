//! The pair loop of many bodies, close to the hardware: positions copied into
//! structure-of-arrays blocks, pairs computed a SIMD register of bodies at a time, blocks
//! scheduled in rounds so that one thread or any number of threads add every body's
//! contributions in the same order (bitwise identical forces whatever the thread count).
//!
//! - **Blocks.** Bodies sit in chunks of `L` slots (a chunk stores the `x` of its `L` bodies,
//!   then their `y`, then `z`, so that they load into one register per coordinate), and the
//!   chunks are split evenly into blocks of about [`BLOCK_MIN`] bodies or more, chosen from
//!   the numbers of bodies alone ([`Layout`]). Slots past the last body are padding, masked out.
//! - **Tiles.** The pairs of two blocks `I < J` form a tile: every body `i` of `I` sums its
//!   pulls from `J` in registers (Newton's third law: each pull is also added to the body of
//!   `J`, lane by lane). The pairs inside a block form its triangle.
//! - **Rounds.** The triangles come first (all blocks at once), then the tiles in the rounds
//!   of a round-robin tournament (the circle method): in a round no block is in two tiles, so
//!   the tiles of a round run on any threads without sharing a body, and every body receives
//!   its contributions round after round, in an order fixed by the blocks alone.
//! - **Test particles** (the bodies from `active` on) feel the active bodies and pull none:
//!   each one's row over the active bodies, in registers, without third law (`O(N M)`).
//! - **SIMD.** Chunks of `L` bodies (`L` = 4 for `f64`, 8 for `f32`: one 256-bit register).
//!   The hot loop runs in AVX2 registers through `pulp` (a safe API; the CPU's AVX2 and FMA
//!   found at run time, as a default x86-64 build has only SSE2); elsewhere the same loop in
//!   plain Rust over `[F; L]` arrays, which the compiler vectorizes for the build's target.
//!   Neither uses a fused multiply-add: both round alike, so the forces do not depend on the
//!   CPU's features either (a unit test compares the two loops bit for bit).
//! - **Memory.** The blocks live in a scratch kept per thread (grown on the first call, never
//!   per step): `2 D + 2` numbers per body slot.

use core::any::Any;
use core::cell::RefCell;
use core::ops::{Add, Div, Mul, Sub};
#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Most blocks of one problem: bounds the stack arrays of block slices (no allocation).
const MAX_BLOCKS: usize = 64;

/// The smallest block, in bodies: large enough for the per-row costs (the horizontal sums)
/// to vanish beside the pairs, small enough for blocks to share work on two threads from
/// `2 BLOCK_MIN` bodies (`benches/nbody_scaling.rs`).
pub(super) const BLOCK_MIN: usize = 128;

/// The scalars with a SIMD pair loop: `f64` and `f32`.
pub(super) trait Lane:
    Copy
    + Default
    + Send
    + Sync
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + 'static
{
    const ZERO: Self;
    const ONE: Self;
    fn sqrt(self) -> Self;
    fn from_f64(x: f64) -> Self;
    fn to_f64(self) -> f64;

    /// [`pull_chunks`]'s loop (third law when `fj` is given) in AVX2 registers, `true` when
    /// done: on x86-64 CPUs with AVX2 and FMA (x86-64-v3, found at run time) and `L` the
    /// register's width; `false` otherwise, nothing done. The same operations in the same
    /// order as the portable loop (no fused multiply-add): the same bits.
    #[inline(always)]
    fn pull_chunks_avx2<const D: usize, const L: usize>(
        _qi: &[Self; D],
        _gmi: Self,
        _cols: (&[Chunk<Self, D, L>], &[[Self; L]]),
        _fi: &mut Chunk<Self, D, L>,
        _fj: Option<&mut [Chunk<Self, D, L>]>,
    ) -> bool {
        false
    }
}

macro_rules! lane {
    ($t:ty, $v:ident, $width:literal, $splat:ident, $add:ident, $sub:ident, $mul:ident, $div:ident, $sqrt:ident) => {
        impl Lane for $t {
            #[cfg(target_arch = "x86_64")]
            #[inline(always)]
            fn pull_chunks_avx2<const D: usize, const L: usize>(
                qi: &[Self; D],
                gmi: Self,
                (position, mass): (&[Chunk<Self, D, L>], &[[Self; L]]),
                fi: &mut Chunk<Self, D, L>,
                fj: Option<&mut [Chunk<Self, D, L>]>,
            ) -> bool {
                if L != $width {
                    return false;
                }
                let Some(simd) = pulp::x86::V3::try_new() else {
                    return false;
                };
                simd.vectorize(Avx2Row {
                    simd,
                    qi,
                    gmi,
                    position,
                    mass,
                    fi,
                    fj,
                });
                true
            }

            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            #[inline(always)]
            fn sqrt(self) -> Self {
                <$t>::sqrt(self)
            }
            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline(always)]
            fn to_f64(self) -> f64 {
                self as f64
            }
        }

        #[cfg(target_arch = "x86_64")]
        impl<const D: usize, const L: usize> pulp::NullaryFnOnce for Avx2Row<'_, $t, D, L> {
            type Output = ();

            #[inline(always)]
            fn call(self) {
                use pulp::{bytemuck::cast, $v, Simd};
                let simd = self.simd;
                // [F; L] is [F; $width] here: the conversions are loads and stores
                #[inline(always)]
                fn load<const L: usize>(a: &[$t; L]) -> $v {
                    cast::<[$t; $width], $v>(a[..].try_into().unwrap())
                }
                #[inline(always)]
                fn store<const L: usize>(v: $v, a: &mut [$t; L]) {
                    a.copy_from_slice(&cast::<$v, [$t; $width]>(v))
                }
                #[inline(always)]
                fn pull<const D: usize, const L: usize>(
                    simd: pulp::x86::V3,
                    (q, g): (&[$v; D], $v),
                    qj: &Chunk<$t, D, L>,
                    mj: &[$t; L],
                    acc: &mut [$v; D],
                ) -> [$v; D] {
                    let d: [$v; D] = core::array::from_fn(|c| simd.$sub(q[c], load(&qj[c])));
                    let mut r2 = simd.$mul(d[0], d[0]);
                    for c in 1..D {
                        r2 = simd.$add(r2, simd.$mul(d[c], d[c]));
                    }
                    let s = simd.$div(simd.$mul(g, load(mj)), simd.$mul(r2, simd.$sqrt(r2)));
                    let x: [$v; D] = core::array::from_fn(|c| simd.$mul(s, d[c]));
                    for c in 0..D {
                        acc[c] = simd.$sub(acc[c], x[c]);
                    }
                    x
                }
                let q: [$v; D] = core::array::from_fn(|c| simd.$splat(self.qi[c]));
                let g = simd.$splat(self.gmi);
                let mut acc: [$v; D] = core::array::from_fn(|c| load(&self.fi[c]));
                match self.fj {
                    Some(fj) => {
                        for ((qj, mj), fj) in self.position.iter().zip(self.mass).zip(fj) {
                            let x = pull(simd, (&q, g), qj, mj, &mut acc);
                            for c in 0..D {
                                store(simd.$add(load(&fj[c]), x[c]), &mut fj[c]);
                            }
                        }
                    }
                    None => {
                        for (qj, mj) in self.position.iter().zip(self.mass) {
                            pull(simd, (&q, g), qj, mj, &mut acc);
                        }
                    }
                }
                for c in 0..D {
                    store(acc[c], &mut self.fi[c]);
                }
            }
        }
    };
}

/// One row's loop in AVX2 registers ([`Lane::pull_chunks_avx2`]), as a function value that
/// `pulp` runs with the CPU's AVX2 and FMA enabled.
#[cfg(target_arch = "x86_64")]
struct Avx2Row<'a, F, const D: usize, const L: usize> {
    simd: pulp::x86::V3,
    qi: &'a [F; D],
    gmi: F,
    position: &'a [Chunk<F, D, L>],
    mass: &'a [[F; L]],
    fi: &'a mut Chunk<F, D, L>,
    fj: Option<&'a mut [Chunk<F, D, L>]>,
}

lane!(f64, f64x4, 4, splat_f64s, add_f64s, sub_f64s, mul_f64s, div_f64s, sqrt_f64s);
lane!(f32, f32x8, 8, splat_f32s, add_f32s, sub_f32s, mul_f32s, div_f32s, sqrt_f32s);

/// `L` bodies' worth of one quantity per coordinate: one SIMD register per coordinate.
type Chunk<F, const D: usize, const L: usize> = [[F; L]; D];

thread_local! {
    /// This thread's scratch blocks, one per scalar, dimension and width used on it.
    static SCRATCH: RefCell<Vec<Box<dyn Any>>> = const { RefCell::new(Vec::new()) };
}

/// Runs `f` on this thread's scratch blocks of this kind (made on the first call; a fresh one
/// if they are in use: a force called from a rayon task that this thread picked up while
/// waiting on its own).
fn with_scratch<F: Lane, const D: usize, const L: usize, R>(f: impl FnOnce(&mut Scratch<F, D, L>) -> R) -> R {
    SCRATCH.with(|cell| match cell.try_borrow_mut() {
        Ok(mut kinds) => {
            let at = match kinds.iter().position(|s| s.is::<Scratch<F, D, L>>()) {
                Some(at) => at,
                None => {
                    kinds.push(Box::new(Scratch::<F, D, L>::default()));
                    kinds.len() - 1
                }
            };
            f(kinds[at].downcast_mut().expect("the kind just found"))
        }
        Err(_) => f(&mut Scratch::default()),
    })
}

/// Where each body sits in the blocks: fixed by the number of bodies, the number of active
/// ones and the SIMD width, never by the number of threads.
///
/// Each kind (active bodies, test particles) fills its chunks of `lanes` slots from the
/// first, and its chunks are spread over its blocks as evenly as whole chunks allow (1000
/// bodies in `f64`: 250 chunks as 2 blocks of 32 and 6 of 31). A round's tiles then cost
/// about the same, so that no thread waits long for another at the round's end; and only
/// the kind's last chunk can hold padding (blocks of a fixed 128 slots left the last of
/// 1000 bodies 104 full, and that round's threads 5% apart: 1.79x on 2 threads).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Layout {
    /// Bodies, the active ones first.
    pub n: usize,
    /// Active bodies (they pull); `n - active` test particles.
    pub active: usize,
    /// Slots per chunk: the SIMD width.
    lanes: usize,
    /// Blocks of active bodies, then blocks of test particles.
    pub active_blocks: usize,
    pub test_blocks: usize,
}

impl Layout {
    /// The layout of `n` bodies of which the first `active` pull, for SIMD width `lanes`.
    pub(super) fn new(n: usize, active: usize, lanes: usize) -> Self {
        // as many blocks as blocks of `block` bodies would need, `block` at least BLOCK_MIN
        // and at most MAX_BLOCKS - 2 blocks' worth of bodies (the two kinds round up once
        // each, the active ones once more to an even count); fewer bodies: one block
        let block = BLOCK_MIN.min(n).max(n.div_ceil(MAX_BLOCKS - 2)).max(1);
        // an even number of active blocks: an odd one leaves a block out of every round
        // (3 blocks: one tile a round, nothing for a second thread)
        let active_blocks = active.div_ceil(block);
        Layout {
            n,
            active,
            lanes,
            active_blocks: if active_blocks > 1 {
                active_blocks + active_blocks % 2
            } else {
                active_blocks
            },
            test_blocks: (n - active).div_ceil(block),
        }
    }

    fn blocks(&self) -> usize {
        self.active_blocks + self.test_blocks
    }

    /// Chunks of active bodies and of test particles.
    fn kind_chunks(&self) -> (usize, usize) {
        (
            self.active.div_ceil(self.lanes),
            (self.n - self.active).div_ceil(self.lanes),
        )
    }

    /// Chunks of all blocks.
    fn chunks(&self) -> usize {
        let (a, t) = self.kind_chunks();
        a + t
    }

    /// The chunks of block `b`: its kind's chunks in even shares, the first shares one
    /// chunk larger when they do not divide.
    fn block_chunks(&self, b: usize) -> core::ops::Range<usize> {
        let (active, test) = self.kind_chunks();
        let (origin, chunks, blocks, j) = if b < self.active_blocks {
            (0, active, self.active_blocks, b)
        } else {
            (active, test, self.test_blocks, b - self.active_blocks)
        };
        let (share, extra) = (chunks / blocks, chunks % blocks);
        let start = origin + j * share + j.min(extra);
        start..start + share + usize::from(j < extra)
    }

    /// The slot of body `k` (active bodies from slot 0, test particles from the first chunk
    /// after the active ones).
    #[inline(always)]
    fn slot(&self, k: usize) -> usize {
        if k < self.active {
            k
        } else {
            self.kind_chunks().0 * self.lanes + (k - self.active)
        }
    }

    /// Bodies in block `b`.
    fn filled(&self, b: usize) -> usize {
        let (origin, count) = if b < self.active_blocks {
            (0, self.active)
        } else {
            (self.kind_chunks().0 * self.lanes, self.n - self.active)
        };
        let slots = self.block_chunks(b);
        let (first, end) = (slots.start * self.lanes - origin, slots.end * self.lanes - origin);
        end.min(count).saturating_sub(first)
    }
}

/// The blocks of one force evaluation, in chunks of `L` slots: positions and forces
/// (`D` registers per chunk), masses and `G m` (padding slots hold zeros).
#[derive(Debug, Default)]
struct Scratch<F, const D: usize, const L: usize> {
    position: Vec<Chunk<F, D, L>>,
    force: Vec<Chunk<F, D, L>>,
    mass: Vec<[F; L]>,
    gm: Vec<[F; L]>,
}

/// One block, read-only: its chunks of positions, masses and `G m`, and how many of its
/// slots hold bodies.
struct Block<'a, F, const D: usize, const L: usize> {
    position: &'a [Chunk<F, D, L>],
    mass: &'a [[F; L]],
    gm: &'a [[F; L]],
    filled: usize,
}

impl<F, const D: usize, const L: usize> Clone for Block<'_, F, D, L> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<F, const D: usize, const L: usize> Copy for Block<'_, F, D, L> {}

impl<F: Lane, const D: usize, const L: usize> Block<'_, F, D, L> {
    /// Body `i`'s coordinates.
    #[inline(always)]
    fn point(&self, i: usize) -> [F; D] {
        let chunk = &self.position[i / L];
        core::array::from_fn(|c| chunk[c][i % L])
    }
}

/// The forces of `layout`'s bodies at positions `q` (body by body, `D` coordinates each)
/// into `f`, with masses `mass` and `G m` `gm` (converted from the problem's scalar by
/// `to` and back by `from`); the tiles of a round on rayon's threads when `parallel`.
pub(super) fn forces<T: Copy, F: Lane, const D: usize, const L: usize>(
    layout: Layout,
    mass: &[T],
    gm: &[T],
    q: &[T],
    f: &mut [T],
    parallel: bool,
    to: impl Fn(T) -> F,
    from: impl Fn(F) -> T,
) {
    with_scratch::<F, D, L, ()>(|scratch| {
        let chunks = layout.chunks();
        for v in [&mut scratch.position, &mut scratch.force] {
            v.clear();
            v.resize(chunks, [[F::ZERO; L]; D]);
        }
        for v in [&mut scratch.mass, &mut scratch.gm] {
            v.clear();
            v.resize(chunks, [F::ZERO; L]);
        }
        for k in 0..layout.n {
            let s = layout.slot(k);
            let (chunk, l) = (s / L, s % L);
            scratch.mass[chunk][l] = to(mass[k]);
            scratch.gm[chunk][l] = to(gm[k]);
            for c in 0..D {
                scratch.position[chunk][c][l] = to(q[k * D + c]);
            }
        }
        schedule::<F, D, L>(layout, scratch, parallel);
        for k in 0..layout.n {
            let s = layout.slot(k);
            for c in 0..D {
                f[k * D + c] = from(scratch.force[s / L][c][s % L]);
            }
        }
    })
}

/// Runs `work` on every item, on rayon's threads when `parallel` (and feature `parallel`).
fn each<I: Send>(items: &mut [I], parallel: bool, work: impl Fn(&mut I) + Sync + Send) {
    #[cfg(feature = "parallel")]
    if parallel {
        return items.par_iter_mut().with_max_len(1).for_each(work);
    }
    #[cfg(not(feature = "parallel"))]
    let _ = parallel;
    items.iter_mut().for_each(work)
}

/// The pairs of round `r` of a round-robin tournament of `teams` (even) teams: every pair
/// of teams meets in exactly one of the `teams - 1` rounds, and no team plays twice in one.
fn round(r: usize, teams: usize) -> impl Iterator<Item = (usize, usize)> {
    let m = teams - 1;
    core::iter::once((r, m)).chain((1..teams / 2).map(move |t| ((r + t) % m, (r + m - t) % m)))
}

/// A tile of a round: its two blocks and their forces.
type Tile<'a, F, const D: usize, const L: usize> = (usize, usize, &'a mut [Chunk<F, D, L>], &'a mut [Chunk<F, D, L>]);

/// Triangles, then tiles round by round, then the test particles' rows.
fn schedule<F: Lane, const D: usize, const L: usize>(layout: Layout, scratch: &mut Scratch<F, D, L>, parallel: bool) {
    if layout.blocks() == 1 && layout.test_blocks == 0 {
        // one block, its triangle: what the rounds below come to, without their arrays
        let block = Block {
            position: &scratch.position,
            mass: &scratch.mass,
            gm: &scratch.gm,
            filled: layout.n,
        };
        return triangle::<F, D, L>(block, &mut scratch.force);
    }
    let blocks: [Block<'_, F, D, L>; MAX_BLOCKS] = core::array::from_fn(|k| {
        let range = if k < layout.blocks() {
            layout.block_chunks(k)
        } else {
            0..0
        };
        Block {
            position: &scratch.position[range.clone()],
            mass: &scratch.mass[range.clone()],
            gm: &scratch.gm[range],
            filled: if k < layout.blocks() { layout.filled(k) } else { 0 },
        }
    });
    let mut rest = scratch.force.as_mut_slice();
    let mut force: [&mut [Chunk<F, D, L>]; MAX_BLOCKS] = core::array::from_fn(|k| {
        let len = if k < layout.blocks() {
            layout.block_chunks(k).len()
        } else {
            0
        };
        let (head, tail) = core::mem::take(&mut rest).split_at_mut(len);
        rest = tail;
        head
    });
    let active = layout.active_blocks;

    let mut triangles: [(usize, &mut [Chunk<F, D, L>]); MAX_BLOCKS] =
        core::array::from_fn(|k| (k, core::mem::take(&mut force[k])));
    each(&mut triangles[..active], parallel, |(k, f)| {
        triangle::<F, D, L>(blocks[*k], f)
    });
    for (k, f) in triangles {
        force[k] = f;
    }

    let teams = active + active % 2;
    for r in 0..teams.saturating_sub(1) {
        let mut tiles: [Tile<'_, F, D, L>; MAX_BLOCKS / 2] =
            core::array::from_fn(|_| (0, 0, Default::default(), Default::default()));
        let mut count = 0;
        for (x, y) in round(r, teams) {
            let (i, j) = (x.min(y), x.max(y));
            if j < active {
                tiles[count] = (i, j, core::mem::take(&mut force[i]), core::mem::take(&mut force[j]));
                count += 1;
            }
        }
        each(&mut tiles[..count], parallel, |(i, j, fi, fj)| {
            tile::<F, D, L>(blocks[*i], fi, blocks[*j], fj)
        });
        for (i, j, fi, fj) in tiles.into_iter().take(count) {
            force[i] = fi;
            force[j] = fj;
        }
    }

    let sources = &blocks[..active];
    let mut tests: [(usize, &mut [Chunk<F, D, L>]); MAX_BLOCKS] =
        core::array::from_fn(|k| (k, core::mem::take(&mut force[k])));
    each(&mut tests[active..layout.blocks()], parallel, |(k, f)| {
        field::<F, D, L>(blocks[*k], f, sources)
    });
}

/// The lanes of `v` summed, in a fixed tree order.
#[inline(always)]
fn lane_sum<F: Lane, const L: usize>(mut v: [F; L]) -> F {
    let mut w = L;
    while w > 1 {
        w /= 2;
        for l in 0..w {
            v[l] = v[l] + v[l + w];
        }
    }
    v[0]
}

/// The pull of the `L` bodies of a chunk (positions `qj`, masses `mj`, slots `j0 ..`) on a
/// body at `qi` with `G m_i` `gmi`: `s d` per lane, `d = q_i - q_j`,
/// `s = G m_i m_j / |d|^3`; lanes outside slots `lo .. hi` give zero (`MASKED` only: a
/// chunk at the edge of the triangle or of the filled slots).
#[inline(always)]
fn pull<F: Lane, const D: usize, const L: usize, const MASKED: bool>(
    qi: &[F; D],
    gmi: F,
    qj: &Chunk<F, D, L>,
    mj: &[F; L],
    (j0, lo, hi): (usize, usize, usize),
) -> Chunk<F, D, L> {
    let mut d = [[F::ZERO; L]; D];
    for c in 0..D {
        for l in 0..L {
            d[c][l] = qi[c] - qj[c][l];
        }
    }
    let mut r2 = [F::ZERO; L];
    for l in 0..L {
        r2[l] = d[0][l] * d[0][l];
    }
    for c in 1..D {
        for l in 0..L {
            r2[l] = r2[l] + d[c][l] * d[c][l];
        }
    }
    let mut m = *mj;
    if MASKED {
        for l in 0..L {
            let inside = j0 + l >= lo && j0 + l < hi;
            // outside: a finite distance and no mass, so no 0 / 0 at the body itself
            r2[l] = if inside { r2[l] } else { F::ONE };
            m[l] = if inside { m[l] } else { F::ZERO };
        }
    }
    let mut s = [F::ZERO; L];
    for l in 0..L {
        s[l] = gmi * m[l] / (r2[l] * r2[l].sqrt());
    }
    let mut x = [[F::ZERO; L]; D];
    for c in 0..D {
        for l in 0..L {
            x[c][l] = s[l] * d[c][l];
        }
    }
    x
}

/// Row `i`'s pulls from chunks `from .. to` of a block (`from` and `to` chunk indices, the
/// chunks whole) into its accumulators `fi`, each one also added to the chunk's forces `fj`
/// when given (third law): the hot loop, without masks.
#[inline(always)]
fn pull_chunks<F: Lane, const D: usize, const L: usize>(
    qi: &[F; D],
    gmi: F,
    cols: Block<'_, F, D, L>,
    (from, to): (usize, usize),
    fi: &mut Chunk<F, D, L>,
    fj: Option<&mut [Chunk<F, D, L>]>,
) {
    let (position, mass) = (&cols.position[from..to], &cols.mass[from..to]);
    let fj = fj.map(|fj| &mut fj[from..to]);
    #[cfg(target_arch = "x86_64")]
    let fj = match fj {
        // the chunks' forces lent to the AVX2 loop and back when it cannot run
        Some(fj) => {
            if F::pull_chunks_avx2(qi, gmi, (position, mass), fi, Some(&mut *fj)) {
                return;
            }
            Some(fj)
        }
        None if F::pull_chunks_avx2(qi, gmi, (position, mass), fi, None) => return,
        None => None,
    };
    pull_chunks_portable(qi, gmi, (position, mass), fi, fj)
}

/// [`pull_chunks`]'s loop in plain Rust over the lanes (vectorized by the compiler for the
/// build's target: SSE2 on a default x86-64 build).
#[inline(always)]
fn pull_chunks_portable<F: Lane, const D: usize, const L: usize>(
    qi: &[F; D],
    gmi: F,
    (position, mass): (&[Chunk<F, D, L>], &[[F; L]]),
    fi: &mut Chunk<F, D, L>,
    fj: Option<&mut [Chunk<F, D, L>]>,
) {
    let chunks = position.iter().zip(mass);
    match fj {
        Some(fj) => {
            for ((qj, mj), fj) in chunks.zip(fj) {
                let x = pull::<F, D, L, false>(qi, gmi, qj, mj, (0, 0, 0));
                accumulate(fi, &x, false);
                accumulate(fj, &x, true);
            }
        }
        None => {
            for (qj, mj) in chunks {
                let x = pull::<F, D, L, false>(qi, gmi, qj, mj, (0, 0, 0));
                accumulate(fi, &x, false);
            }
        }
    }
}

/// Row `i`'s pulls from chunk `from` to the end of a block: the whole chunks, then the
/// last chunk masked if it is partly filled.
#[inline(always)]
fn pull_to_end<F: Lane, const D: usize, const L: usize>(
    qi: &[F; D],
    gmi: F,
    cols: Block<'_, F, D, L>,
    from: usize,
    fi: &mut Chunk<F, D, L>,
    mut fj: Option<&mut [Chunk<F, D, L>]>,
) {
    let (whole, used) = (cols.filled / L, cols.filled.div_ceil(L));
    pull_chunks(qi, gmi, cols, (from, whole.max(from)), fi, fj.as_deref_mut());
    if used > whole {
        pull_edge(qi, gmi, cols, (whole, 0, cols.filled), fi, fj);
    }
}

/// Row `i`'s pull from chunk `k` of a block, masked to slots `lo .. hi`.
#[inline(always)]
fn pull_edge<F: Lane, const D: usize, const L: usize>(
    qi: &[F; D],
    gmi: F,
    cols: Block<'_, F, D, L>,
    (k, lo, hi): (usize, usize, usize),
    fi: &mut Chunk<F, D, L>,
    fj: Option<&mut [Chunk<F, D, L>]>,
) {
    let x = pull::<F, D, L, true>(qi, gmi, &cols.position[k], &cols.mass[k], (k * L, lo, hi));
    accumulate(fi, &x, false);
    if let Some(fj) = fj {
        accumulate(&mut fj[k], &x, true);
    }
}

/// `a += x` (`add`) or `a -= x`, lane by lane.
#[inline(always)]
fn accumulate<F: Lane, const D: usize, const L: usize>(a: &mut Chunk<F, D, L>, x: &Chunk<F, D, L>, add: bool) {
    for c in 0..D {
        for l in 0..L {
            a[c][l] = if add { a[c][l] + x[c][l] } else { a[c][l] - x[c][l] };
        }
    }
}

/// Adds the lanes of the row accumulators `fi` to body `i`'s force.
#[inline(always)]
fn settle<F: Lane, const D: usize, const L: usize>(force: &mut [Chunk<F, D, L>], i: usize, fi: &Chunk<F, D, L>) {
    for c in 0..D {
        let f = &mut force[i / L][c][i % L];
        *f = *f + lane_sum(fi[c]);
    }
}

/// The pairs inside one block (`j > i`), third law: per row, the chunk holding `i + 1`
/// masked, the whole chunks after it, the last chunk masked if partly filled.
fn triangle<F: Lane, const D: usize, const L: usize>(block: Block<'_, F, D, L>, force: &mut [Chunk<F, D, L>]) {
    let used = block.filled.div_ceil(L);
    for i in 0..block.filled.saturating_sub(1) {
        let (qi, gmi) = (block.point(i), block.gm[i / L][i % L]);
        let mut fi = [[F::ZERO; L]; D];
        let first = (i + 1) / L;
        pull_edge(&qi, gmi, block, (first, i + 1, block.filled), &mut fi, Some(force));
        if first + 1 < used {
            pull_to_end(&qi, gmi, block, first + 1, &mut fi, Some(force));
        }
        settle(force, i, &fi);
    }
}

/// The pairs between block `rows` and block `cols` (different blocks), third law.
fn tile<F: Lane, const D: usize, const L: usize>(
    rows: Block<'_, F, D, L>,
    rows_force: &mut [Chunk<F, D, L>],
    cols: Block<'_, F, D, L>,
    cols_force: &mut [Chunk<F, D, L>],
) {
    for i in 0..rows.filled {
        let (qi, gmi) = (rows.point(i), rows.gm[i / L][i % L]);
        let mut fi = [[F::ZERO; L]; D];
        pull_to_end(&qi, gmi, cols, 0, &mut fi, Some(cols_force));
        settle(rows_force, i, &fi);
    }
}

/// The rows of the test particles of block `rows`: pulled by every active block
/// (`sources`, in order), pulling none.
fn field<F: Lane, const D: usize, const L: usize>(
    rows: Block<'_, F, D, L>,
    force: &mut [Chunk<F, D, L>],
    sources: &[Block<'_, F, D, L>],
) {
    for i in 0..rows.filled {
        let (qi, gmi) = (rows.point(i), rows.gm[i / L][i % L]);
        let mut fi = [[F::ZERO; L]; D];
        for &cols in sources {
            pull_to_end(&qi, gmi, cols, 0, &mut fi, None);
        }
        settle(force, i, &fi);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_pair_of_blocks_meets_once_and_no_block_twice_in_a_round() {
        for teams in (2..=MAX_BLOCKS).step_by(2) {
            let mut met = vec![0; teams * teams];
            for r in 0..teams - 1 {
                let mut playing = vec![false; teams];
                for (x, y) in round(r, teams) {
                    assert!(x != y && !playing[x] && !playing[y], "{teams} teams, round {r}");
                    playing[x] = true;
                    playing[y] = true;
                    met[x.min(y) * teams + x.max(y)] += 1;
                }
            }
            for x in 0..teams {
                for y in x + 1..teams {
                    assert_eq!(met[x * teams + y], 1, "{teams} teams: {x} and {y}");
                }
            }
        }
    }

    /// The AVX2 loop and the portable one give the same bits (where this CPU has AVX2).
    fn same_bits_on_both_loops<F: Lane, const L: usize>() {
        let frac = |x: f64| F::from_f64(x - x.floor());
        let chunks = 37;
        let position: Vec<Chunk<F, 3, L>> = (0..chunks)
            .map(|k| {
                core::array::from_fn(|c| {
                    core::array::from_fn(|l| frac(((k * 3 + c) * L + l) as f64 * 0.7548776662466927))
                })
            })
            .collect();
        let mass: Vec<[F; L]> = (0..chunks)
            .map(|k| core::array::from_fn(|l| frac((k * L + l) as f64 * 0.6180339887498949)))
            .collect();
        let qi = [F::from_f64(0.25), F::from_f64(-0.5), F::from_f64(1.5)];
        for third_law in [true, false] {
            let (mut fi_a, mut fi_b) = ([[F::ZERO; L]; 3], [[F::ZERO; L]; 3]);
            let (mut fj_a, mut fj_b) = (vec![[[F::ONE; L]; 3]; chunks], vec![[[F::ONE; L]; 3]; chunks]);
            fn lend<T>(f: &mut [T], on: bool) -> Option<&mut [T]> {
                on.then_some(f)
            }
            if !F::pull_chunks_avx2(
                &qi,
                F::from_f64(0.3),
                (&position, &mass),
                &mut fi_a,
                lend(&mut fj_a, third_law),
            ) {
                return; // no AVX2 here
            }
            pull_chunks_portable(
                &qi,
                F::from_f64(0.3),
                (&position, &mass),
                &mut fi_b,
                lend(&mut fj_b, third_law),
            );
            let bits = |v: &[Chunk<F, 3, L>]| {
                v.iter()
                    .flatten()
                    .flatten()
                    .map(|x| x.to_f64().to_bits())
                    .collect::<Vec<_>>()
            };
            assert_eq!(bits(&[fi_a]), bits(&[fi_b]));
            assert_eq!(bits(&fj_a), bits(&fj_b));
        }
    }

    #[test]
    fn the_avx2_and_the_portable_loops_give_the_same_bits() {
        same_bits_on_both_loops::<f64, 4>();
        same_bits_on_both_loops::<f32, 8>();
    }

    #[test]
    fn layouts_hold_every_body_in_at_most_the_blocks_there_are_room_for() {
        for n in [1, 2, 7, 8, 9, 127, 128, 129, 1000, 7937, 7938, 10_000, 1_000_000] {
            for active in [0, 1, n / 3, n - 1, n] {
                let layout = Layout::new(n, active, 4);
                assert!(layout.blocks() <= MAX_BLOCKS, "{layout:?}");
                // the rounds of an even number of blocks have no bye: two threads share them
                assert!(layout.active_blocks < 2 || layout.active_blocks % 2 == 0, "{layout:?}");
                let filled: usize = (0..layout.blocks()).map(|k| layout.filled(k)).sum();
                assert_eq!(filled, n, "{layout:?}");
                // the blocks tile the chunks in order, each kind's within one chunk of even
                let mut next = 0;
                for (kind, blocks) in [(0..layout.active_blocks), (layout.active_blocks..layout.blocks())]
                    .into_iter()
                    .enumerate()
                {
                    let sizes: Vec<usize> = blocks.clone().map(|k| layout.block_chunks(k).len()).collect();
                    let (least, most) = (sizes.iter().min(), sizes.iter().max());
                    assert!(
                        most.zip(least).is_none_or(|(m, l)| m - l <= 1),
                        "{layout:?}, kind {kind}: {sizes:?}"
                    );
                    for k in blocks {
                        assert_eq!(layout.block_chunks(k).start, next, "{layout:?}");
                        next = layout.block_chunks(k).end;
                        assert!(layout.filled(k) > 0, "{layout:?}: block {k} is empty");
                    }
                }
                assert_eq!(next, layout.chunks(), "{layout:?}");
                // the bodies' slots are those the blocks hold
                assert_eq!(layout.slot(n - 1) / 4, layout.chunks() - 1, "{layout:?}");
            }
        }
    }
}
