//! A structure matrix the problem supplies: a charged particle in `(q, v)` coordinates.
//!
//! For `q' = v`, `v' = -grad phi(q) + omega x v` with a uniform `omega`, the two-form is
//! not `dq ^ dv` but `dq ^ dv + (1/2) eps_ijk omega_k dq_i ^ dq_j` (from the canonical
//! momentum `p = v + A(q)`), i.e. `S = [[K, I], [-I, 0]]` with `K_ij = eps_ijk omega_k`.
//! The exact gyration (the magnetic drift) and the electric kick each keep it, so the
//! magnetic Verlet and every composition over it are symplectic for this `S`, and only
//! for this one: the canonical check fails them. RK4 fails both.

use core::marker::PhantomData;
use nalgebra::DMatrix;
use stormer::magnetic::{Charged, Lorentz};
use stormer::real::lit;
use stormer::stepper::ImplicitOptions;
use stormer::verify::{
    defect_bound, jacobian_dual, symplectic_defect, Canonical, Dual64, Structure, SYMPLECTIC_FACTOR,
};
use stormer::{Method, Real, Stepper};

const OMEGA: [f64; 3] = [0.3, -0.2, 1.1];

/// A particle in a uniform magnetic field and an anharmonic electric trap
/// `phi = |q|^2/2 + q1^2 q2 - q2^3/3 + q3^4/4`, at any scalar type.
struct Trap<T>(PhantomData<T>);

impl<T> Default for Trap<T> {
    fn default() -> Self {
        Trap(PhantomData)
    }
}

impl<T: Real> Lorentz for Trap<T> {
    type Scalar = T;
    type State = [T; 6];
    fn omega(&self, _particle: usize, _q: &[T]) -> [T; 3] {
        OMEGA.map(lit)
    }
    fn uniform(&self) -> bool {
        true
    }
    fn acceleration(&self, _t: T, q: &[T], a: &mut [T]) {
        let two: T = lit(2.0);
        a[0] = -q[0] - two * q[0] * q[1];
        a[1] = -q[1] - q[0] * q[0] + q[1] * q[1];
        a[2] = -q[2] - q[2] * q[2] * q[2];
    }
}

/// `S = [[K, I], [-I, 0]]`, `K_ij = eps_ijk omega_k`.
struct Magnetic;

impl Structure for Magnetic {
    fn matrix<T: Real>(&self, _y: &[T]) -> DMatrix<T> {
        let [w1, w2, w3] = OMEGA.map(lit::<T>);
        let z = T::zero();
        let k = [[z, w3, -w2], [-w3, z, w1], [w2, -w1, z]];
        let mut s = Canonical.matrix(&[T::zero(); 6]);
        for i in 0..3 {
            for j in 0..3 {
                s[(i, j)] = k[i][j];
            }
        }
        s
    }
}

/// The defects of one step for the magnetic and the canonical structure, in units of
/// `eps max(1, |J|)^2`.
fn defects(name: &str, y: [f64; 6], h: f64) -> (f64, f64) {
    type P = Charged<Trap<Dual64>>;
    let p = Charged(Trap::<Dual64>::default());
    let yd: [Dual64; 6] = y.map(lit);
    let mut stepper: Box<dyn Stepper<P>> = Method::named(name)
        .unwrap()
        .stepper_for(&p, &yd, &ImplicitOptions::newton())
        .unwrap();
    let j = jacobian_dual(&mut stepper, &p, 0.0, h, &yd).unwrap();
    let mut y1 = yd;
    stepper.reset();
    stepper.step(&p, lit(0.0), lit(h), &yd, &mut y1).unwrap();
    let y1 = y1.map(|x| x.re);
    let unit = defect_bound(&j, 1.0);
    (
        symplectic_defect(&j, &Magnetic, &y, &y1) / unit,
        symplectic_defect(&j, &Canonical, &y, &y1) / unit,
    )
}

#[test]
fn magnetic_verlet_keeps_the_magnetic_two_form_not_the_canonical_one() {
    for y in [[0.2, -0.1, 0.3, 0.5, 0.1, -0.4], [-0.3, 0.25, -0.1, 0.0, 0.6, 0.2]] {
        for h in [0.1, 0.4] {
            for name in [
                "stormer_verlet_dkd",
                "velocity_verlet_kdk",
                "kahan_li6",
                "blanes_moan_s6",
            ] {
                let (magnetic, canonical) = defects(name, y, h);
                assert!(
                    magnetic <= SYMPLECTIC_FACTOR,
                    "{name}: {magnetic} eps |J|^2 at y = {y:?}, h = {h}"
                );
                assert!(
                    canonical >= 1e3 * SYMPLECTIC_FACTOR,
                    "{name}: canonical defect only {canonical}"
                );
            }
            let (magnetic, _) = defects("rk4", y, h);
            assert!(magnetic >= 1e3 * SYMPLECTIC_FACTOR, "rk4: {magnetic} eps |J|^2");
        }
    }
}
