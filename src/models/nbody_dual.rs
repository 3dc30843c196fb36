//! The forces of a few bodies on dual numbers ([`Dual64`]: the tangent map of a step,
//! `crate::chaos`), with the values and the dual parts of a body's position each in an
//! array of four (the components, padded): the arithmetic of num-dual's rules written out
//! on those arrays, which the compiler turns into vector instructions, instead of a
//! dual-number operation per component. The same sums, pair by pair, as
//! `NBody::pairwise_fixed`, the same values to round-off (the inverse-square factor as
//! [`crate::real::over_r_cubed`] takes it).

use core::any::{Any, TypeId};
use num_dual::Dual64;

use crate::Real;

/// A body's position, velocity or force: the values and the dual parts of its components.
#[derive(Clone, Copy)]
struct Parts {
    re: [f64; 4],
    eps: [f64; 4],
}

const ZERO: Parts = Parts {
    re: [0.0; 4],
    eps: [0.0; 4],
};

/// `a - b`, component by component (computed twice rather than kept: the arrays of every
/// pair's would be cleared at every call).
#[inline(always)]
fn separation(a: &Parts, b: &Parts) -> Parts {
    let mut d = ZERO;
    for c in 0..4 {
        d.re[c] = a.re[c] - b.re[c];
        d.eps[c] = a.eps[c] - b.eps[c];
    }
    d
}

/// `x` as the [`Dual64`] it is (`None` for another scalar; decided at compile time).
#[inline(always)]
fn dual<T: Real>(x: &T) -> Option<Dual64> {
    (x as &dyn Any).downcast_ref::<Dual64>().copied()
}

/// The forces of `N` bodies in `D` dimensions (`D <= 3`) of gravitational parameters `gm`
/// and masses `m` at the positions `q`, into `f` (the first `N D` entries), when `T` is
/// [`Dual64`]; false (nothing done) for every other scalar.
#[inline(always)]
pub(super) fn pairwise_fixed<T: Real, const D: usize, const N: usize>(gm: &[T], m: &[T], q: &[T], f: &mut [T]) -> bool {
    if TypeId::of::<T>() != TypeId::of::<Dual64>() || D > 3 {
        return false;
    }
    // (T is Dual64 here: the conversions cannot fail)
    let zero = Dual64::from(0.0);
    let (mut gms, mut ms, mut qs) = ([zero; N], [zero; N], [ZERO; N]);
    for k in 0..N {
        (gms[k], ms[k]) = (dual(&gm[k]).unwrap_or(zero), dual(&m[k]).unwrap_or(zero));
        for c in 0..D {
            let x = dual(&q[k * D + c]).unwrap_or(zero);
            (qs[k].re[c], qs[k].eps[c]) = (x.re, x.eps);
        }
    }
    let Some(fs) = forces::<D, N>(&gms, &ms, &qs) else {
        return false;
    };
    for k in 0..N {
        for c in 0..D {
            if let Some(out) = (&mut f[k * D + c] as &mut dyn Any).downcast_mut::<Dual64>() {
                *out = Dual64::new(fs[k].re[c], fs[k].eps[c]);
            }
        }
    }
    true
}

/// The forces of [`pairwise_fixed`] from the bodies' parameters and positions (`None`
/// beyond 6 bodies). Inlined in release builds; in debug builds, which keep every inlined
/// callee's arrays on the caller's stack, a call of its own (the second-order tests' deep
/// frames overflowed the stack otherwise).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline(never))]
fn forces<const D: usize, const N: usize>(gms: &[Dual64; N], ms: &[Dual64; N], qs: &[Parts; N]) -> Option<[Parts; N]> {
    // the pairs' separations first, then their roots and reciprocals together (the
    // compiler packs those into vector instructions: their latency, not the products,
    // bounds a few bodies' forces), then the forces
    const MAX_PAIRS: usize = 15;
    let pairs = N * (N - 1) / 2;
    if pairs > MAX_PAIRS {
        return None;
    }
    let (mut r2, mut r2_eps) = ([1.0; MAX_PAIRS], [0.0; MAX_PAIRS]);
    let mut pair = 0;
    for k in 0..N {
        for l in k + 1..N {
            let d = separation(&qs[k], &qs[l]);
            let (mut sum, mut sum_eps) = (0.0, 0.0);
            for c in 0..D {
                sum += d.re[c] * d.re[c];
                sum_eps += d.re[c] * d.eps[c];
            }
            (r2[pair], r2_eps[pair]) = (sum, 2.0 * sum_eps);
            pair += 1;
        }
    }
    let (mut root, mut inverse) = ([0.0; MAX_PAIRS], [0.0; MAX_PAIRS]);
    for p in 0..pairs {
        root[p] = r2[p].sqrt();
    }
    for p in 0..pairs {
        inverse[p] = 1.0 / (r2[p] * root[p]);
    }
    let mut fs = [ZERO; N];
    let mut pair = 0;
    for k in 0..N {
        let mut fk = ZERO;
        for l in k + 1..N {
            // gm_k m_l on dual numbers, then the factor over r^3 (`over_r_cubed`)
            let num = gms[k].re * ms[l].re;
            let num_eps = gms[k].eps * ms[l].re + ms[l].eps * gms[k].re;
            let (inverse, d) = (inverse[pair], separation(&qs[k], &qs[l]));
            let s = num * inverse;
            let s_eps = inverse * (num_eps - 1.5 * num * r2_eps[pair] * (root[pair] * inverse));
            pair += 1;
            for c in 0..4 {
                let x = s * d.re[c];
                let x_eps = s_eps * d.re[c] + d.eps[c] * s;
                fk.re[c] -= x;
                fk.eps[c] -= x_eps;
                fs[l].re[c] += x;
                fs[l].eps[c] += x_eps;
            }
        }
        for c in 0..4 {
            fs[k].re[c] += fk.re[c];
            fs[k].eps[c] += fk.eps[c];
        }
    }
    Some(fs)
}

/// The Kepler problems' forces `-sign mu_k m_k q_k / |q_k|^3` of bodies `1..N` (the split's
/// `add_kepler_forces`), added to `f`, when `T` is [`Dual64`]: their roots and reciprocals
/// together, as [`forces`]'s; false (nothing done) for every other scalar.
#[inline(always)]
pub(super) fn add_kepler_forces<T: Real, const D: usize, const N: usize>(
    sign: T,
    kepler: &[(T, T)],
    q: &[T],
    f: &mut [T],
) -> bool {
    if TypeId::of::<T>() != TypeId::of::<Dual64>() || D > 3 || N > 6 {
        return false;
    }
    let zero = Dual64::from(0.0);
    let sign = dual(&sign).unwrap_or(zero);
    let (mut num, mut qs) = ([zero; 6], [ZERO; 6]);
    let (mut r2, mut r2_eps) = ([1.0; 6], [0.0; 6]);
    for k in 1..N {
        let (mu, mass) = (dual(&kepler[k].0).unwrap_or(zero), dual(&kepler[k].1).unwrap_or(zero));
        num[k] = sign * mu * mass;
        let (mut sum, mut sum_eps) = (0.0, 0.0);
        for c in 0..D {
            let x = dual(&q[k * D + c]).unwrap_or(zero);
            (qs[k].re[c], qs[k].eps[c]) = (x.re, x.eps);
            sum += x.re * x.re;
            sum_eps += x.re * x.eps;
        }
        (r2[k], r2_eps[k]) = (sum, 2.0 * sum_eps);
    }
    let (mut root, mut inverse) = ([0.0; 6], [0.0; 6]);
    for k in 0..6 {
        root[k] = r2[k].sqrt();
    }
    for k in 0..6 {
        inverse[k] = 1.0 / (r2[k] * root[k]);
    }
    for k in 1..N {
        let (n, inverse) = (num[k], inverse[k]);
        let s = n.re * inverse;
        let s_eps = inverse * (n.eps - 1.5 * n.re * r2_eps[k] * (root[k] * inverse));
        for c in 0..D {
            if let Some(out) = (&mut f[k * D + c] as &mut dyn Any).downcast_mut::<Dual64>() {
                let (x, x_eps) = (qs[k].re[c], qs[k].eps[c]);
                *out = Dual64::new(out.re - s * x, out.eps - (s_eps * x + x_eps * s));
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// num-dual's rules, one operation at a time, as the generic loops run them.
    fn forces_by_num_dual(gm: &[Dual64; 4], m: &[Dual64; 4], q: &[Dual64; 12]) -> [Dual64; 12] {
        let mut f = [Dual64::from(0.0); 12];
        for k in 0..4 {
            for l in k + 1..4 {
                let d: Vec<Dual64> = (0..3).map(|c| q[k * 3 + c] - q[l * 3 + c]).collect();
                let r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                let s = gm[k] * m[l] / (r2 * nalgebra::ComplexField::sqrt(r2));
                for c in 0..3 {
                    f[k * 3 + c] -= s * d[c];
                    f[l * 3 + c] += s * d[c];
                }
            }
        }
        f
    }

    #[test]
    fn the_packed_dual_forces_are_num_duals_to_round_off_with_a_mass_varied() {
        let q: [Dual64; 12] = core::array::from_fn(|i| Dual64::new((i as f64 * 0.37).sin() * 3.0, (i as f64).cos()));
        // a derivative with respect to the second mass too
        let m = [1.0, 1e-3, 3e-4, 5e-5].map(Dual64::from);
        let mut m_varied = m;
        m_varied[1].eps = 1.0;
        for m in [m, m_varied] {
            let gm = m.map(|m| m * Dual64::from(0.5));
            let mut f = [Dual64::from(0.0); 12];
            assert!(pairwise_fixed::<Dual64, 3, 4>(&gm, &m, &q, &mut f));
            for (packed, reference) in f.iter().zip(forces_by_num_dual(&gm, &m, &q)) {
                let close = |a: f64, b: f64| (a - b).abs() <= 1e-14 * (1.0 + b.abs());
                assert!(
                    close(packed.re, reference.re) && close(packed.eps, reference.eps),
                    "{packed} {reference}"
                );
            }
        }
        // another scalar: not done here
        assert!(!pairwise_fixed::<f64, 3, 4>(
            &[1.0; 4],
            &[1.0; 4],
            &[0.0; 12],
            &mut [0.0; 12]
        ));
    }
}
