//! Boris in a uniform field, on lanes of particles: the positions and velocities of
//! [`LANES`] particles gathered component by component (`x[i][lane]`), so that each
//! operation of the step is one loop over the lanes, which the compiler turns into SIMD
//! instructions (two `f64` per SSE2 instruction, four with AVX2).

use crate::models::ExternalFields;
use crate::real::lit;
use crate::Real;

/// Particles per lane group: 2, one SSE2 register per component (4 spill registers on
/// x86-64's 16 with the default target; measured in docs/benchmarks.md).
pub(crate) const LANES: usize = 2;

/// `[T; LANES]` for each of the 3 components.
type Vec3<T> = [[T; LANES]; 3];

/// `a x b`, lane by lane.
#[inline(always)]
fn cross<T: Real>(a: &Vec3<T>, b: &Vec3<T>) -> Vec3<T> {
    let mut c = [[T::zero(); LANES]; 3];
    for l in 0..LANES {
        c[0][l] = a[1][l] * b[2][l] - a[2][l] * b[1][l];
        c[1][l] = a[2][l] * b[0][l] - a[0][l] * b[2][l];
        c[2][l] = a[0][l] * b[1][l] - a[1][l] * b[0][l];
    }
    c
}

/// Each lane's `(h/2) a`, Boris vector `t = -(h/2) omega` and `2 / (1 + |t|^2)`: constant
/// for a particle in a uniform field, computed as Boris's general loop computes them.
#[derive(Clone, Copy)]
struct Constants<T> {
    half_a: Vec3<T>,
    turn: Vec3<T>,
    s: [T; LANES],
}

impl<T: Real> Constants<T> {
    /// Sets lane `l` to particle `k`'s constants.
    #[inline(always)]
    fn set(&mut self, l: usize, fields: &ExternalFields<'_, T>, k: usize, half: T) {
        let a = fields.acceleration(k);
        // a uniform field: omega does not read the position
        let omega = fields.omega(k, &[T::zero(); 3]);
        for i in 0..3 {
            self.half_a[i][l] = half * a[i];
            self.turn[i][l] = -(omega[i] * half);
        }
        let t = [self.turn[0][l], self.turn[1][l], self.turn[2][l]];
        self.s[l] = (T::one() + T::one()) / (T::one() + (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]));
    }
}

/// One step of a group of [`LANES`] particles (positions `qg`, velocities `vg`): half a
/// drift, the kick (half the electric kick, the Cayley rotation, the other half), half a
/// drift.
#[inline(always)]
fn step_group<T: Real>(c: &Constants<T>, half: T, qg: &mut [T], vg: &mut [T]) {
    let (mut x, mut u) = ([[T::zero(); LANES]; 3], [[T::zero(); LANES]; 3]);
    for l in 0..LANES {
        for i in 0..3 {
            x[i][l] = qg[3 * l + i];
            u[i][l] = vg[3 * l + i];
        }
    }
    for i in 0..3 {
        for l in 0..LANES {
            x[i][l] += half * u[i][l];
            u[i][l] += c.half_a[i][l];
        }
    }
    let turned = cross(&u, &c.turn);
    let mut u1 = [[T::zero(); LANES]; 3];
    for i in 0..3 {
        for l in 0..LANES {
            u1[i][l] = u[i][l] + turned[i][l];
        }
    }
    let turn = cross(&u1, &c.turn);
    for i in 0..3 {
        for l in 0..LANES {
            u[i][l] += c.s[l] * turn[i][l];
            u[i][l] += c.half_a[i][l];
            x[i][l] += half * u[i][l];
        }
    }
    for l in 0..LANES {
        for i in 0..3 {
            qg[3 * l + i] = x[i][l];
            vg[3 * l + i] = u[i][l];
        }
    }
}

/// The classic (Cayley) Boris step of the particles `first, first + 1, ...` in groups of
/// [`LANES`], in the uniform fields `fields` (the caller checks the field is uniform);
/// returns how many particles it pushed (the rest, fewer than [`LANES`], is left to the
/// particle-by-particle loop). The operations are those of that loop in the same order,
/// so the numbers are bitwise the same. When all the particles have one charge-to-mass
/// ratio (one species), the constants of the step are computed once.
#[inline(always)]
pub(crate) fn push_lanes<T: Real>(
    fields: &ExternalFields<'_, T>,
    h: T,
    first: usize,
    q: &mut [T],
    v: &mut [T],
) -> usize {
    let half = lit::<T>(0.5) * h;
    let pushed = q.len() / (3 * LANES) * LANES;
    let mut c = Constants {
        half_a: [[T::zero(); LANES]; 3],
        turn: [[T::zero(); LANES]; 3],
        s: [T::zero(); LANES],
    };
    let groups = q.chunks_exact_mut(3 * LANES).zip(v.chunks_exact_mut(3 * LANES));
    #[allow(clippy::float_cmp)] // the same ratio, bit for bit, gives the same constants
    let one_species = (first..first + pushed).all(|k| fields.ratio(k) == fields.ratio(first));
    if one_species {
        for l in 0..LANES {
            c.set(l, fields, first, half);
        }
        for (qg, vg) in groups {
            step_group(&c, half, qg, vg);
        }
    } else {
        for (g, (qg, vg)) in groups.enumerate() {
            for l in 0..LANES {
                c.set(l, fields, first + g * LANES + l, half);
            }
            step_group(&c, half, qg, vg);
        }
    }
    pushed
}
