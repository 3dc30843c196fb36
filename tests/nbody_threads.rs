//! The many-body force (SIMD blocks, rayon's threads): the forces of every kernel agree with
//! a plain double loop, trajectories are bitwise equal on 1, 2 and 3 threads, and test
//! particles feel the active bodies and pull none.

#[path = "../benches/support/star_and_disc.rs"]
mod star_and_disc;

use nalgebra::DVector;
use star_and_disc::star_and_disc;
use stormer::catalog::VelocityVerletKdk;
use stormer::hamiltonian::Hamiltonian;
use stormer::models::NBody;
use stormer::stepper::SplittingStepper;
use stormer::Stepper;

/// The forces by the definition, in `f64` whatever the problem's scalar: body `l` pulls
/// body `k` with `G m_k m_l (q_l - q_k) / |q_l - q_k|^3` when `l < active`; and per body the
/// sum of the pulls' sizes (the scale of the rounding errors of any order of summation).
fn plain(g: f64, m: &[f64], active: usize, q: &[f64], dim: usize) -> (Vec<f64>, Vec<f64>) {
    let mut f = vec![0.0; q.len()];
    let mut size = vec![0.0; m.len()];
    for k in 0..m.len() {
        for l in 0..active {
            if l == k {
                continue;
            }
            let d: Vec<f64> = (0..dim).map(|c| q[l * dim + c] - q[k * dim + c]).collect();
            let r = d.iter().map(|x| x * x).sum::<f64>().sqrt();
            for c in 0..dim {
                f[k * dim + c] += g * m[k] * m[l] * d[c] / (r * r * r);
            }
            size[k] += g * m[k] * m[l] / (r * r);
        }
    }
    (f, size)
}

/// Largest difference relative to the sum of the sizes of its body's pulls.
fn worst(f: &[f64], (reference, size): &(Vec<f64>, Vec<f64>), dim: usize) -> f64 {
    f.chunks(dim)
        .zip(reference.chunks(dim))
        .zip(size)
        .map(|((a, b), &scale)| {
            a.iter()
                .zip(b)
                .fold(0.0f64, |s, (x, y)| s.max((x - y).abs() / scale.max(1e-300)))
        })
        .fold(0.0, f64::max)
}

/// `n` bodies in `dim` dimensions at quasi-random places, unequal masses.
fn scattered(n: usize, dim: usize) -> (Vec<f64>, Vec<f64>) {
    let frac = |x: f64| x - x.floor();
    let q = (0..n * dim)
        .map(|i| 4.0 * frac((i as f64 + 1.0) * 0.754_877_666_246_692_7) - 2.0)
        .collect();
    let m = (0..n).map(|k| 0.1 + frac(k as f64 * 0.618_033_988_749_894_9)).collect();
    (q, m)
}

#[test]
fn every_kernel_agrees_with_the_definition() {
    for dim in 1..=4 {
        for n in [2, 3, 5, 7, 8, 9, 31, 130, 300] {
            for active in [n, n / 2, 1] {
                let (q, m) = scattered(n, dim);
                let reference = plain(1.3, &m, active, &q, dim);
                let nb = NBody::<f64, DVector<f64>>::new(1.3, &m, dim)
                    .unwrap()
                    .with_active(active)
                    .unwrap();
                let mut f = vec![0.0; n * dim];
                nb.force(0.0, &q, &mut f);
                let e = worst(&f, &reference, dim);
                assert!(e < 1e-14, "f64, {n} bodies ({active} active) in {dim}-D: {e:e}");
                let nb32 = NBody::<f32, DVector<f32>>::new(1.3, &m.iter().map(|&x| x as f32).collect::<Vec<_>>(), dim)
                    .unwrap()
                    .with_active(active)
                    .unwrap();
                let q32: Vec<f32> = q.iter().map(|&x| x as f32).collect();
                let mut f32s = vec![0.0f32; n * dim];
                nb32.force(0.0, &q32, &mut f32s);
                let reference32 = plain(
                    1.3,
                    &m.iter().map(|&x| f64::from(x as f32)).collect::<Vec<_>>(),
                    active,
                    &q32.iter().map(|&x| f64::from(x)).collect::<Vec<_>>(),
                    dim,
                );
                let f32s: Vec<f64> = f32s.iter().map(|&x| f64::from(x)).collect();
                let e = worst(&f32s, &reference32, dim);
                assert!(e < 1e-5, "f32, {n} bodies ({active} active) in {dim}-D: {e:e}");
            }
        }
    }
}

/// `steps` velocity Verlet steps of `dt = 0.001` of the star and `n - 1` bodies (the first
/// `active` pulling) on a pool of `threads` threads: the final state.
fn verlet_on(threads: usize, n: usize, active: usize, steps: usize) -> DVector<f64> {
    let (q, v, m) = star_and_disc(n);
    let nb = NBody::<f64, DVector<f64>>::new(1.0, &m, 3)
        .unwrap()
        .with_active(active)
        .unwrap();
    let mut y = DVector::zeros(6 * n);
    nb.set_state(&q, &v, &mut y).unwrap();
    let mut stepper = SplittingStepper::<VelocityVerletKdk, DVector<f64>>::new(&y).unwrap();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    pool.install(|| {
        for i in 0..steps {
            stepper.step_in_place(&nb, i as f64 * 1e-3, 1e-3, &mut y).unwrap();
        }
    });
    y
}

#[test]
fn trajectories_are_bitwise_equal_on_any_number_of_threads() {
    // 1000 bodies: several blocks, tiles in rounds on the threads; with test particles too
    for (n, active) in [(1000, 1000), (700, 300)] {
        let one = verlet_on(1, n, active, 10);
        assert!(one.iter().all(|x| x.is_finite()));
        for threads in [2, 3] {
            let many = verlet_on(threads, n, active, 10);
            let same = one.iter().zip(&many).all(|(a, b)| a.to_bits() == b.to_bits());
            assert!(same, "{n} bodies ({active} active): 1 and {threads} threads differ");
        }
    }
}

#[test]
#[allow(clippy::float_cmp)] // a body that feels nothing keeps its zero force exactly
fn test_particles_feel_and_do_not_pull() {
    let (q, _, m) = star_and_disc(400);
    let all = NBody::<f64, DVector<f64>>::new(1.0, &m[..100], 3).unwrap();
    let some = NBody::<f64, DVector<f64>>::new(1.0, &m, 3)
        .unwrap()
        .with_active(100)
        .unwrap();
    let (mut fa, mut fs) = (vec![0.0; 300], vec![0.0; 1200]);
    all.force(0.0, &q[..300], &mut fa);
    some.force(0.0, &q, &mut fs);
    // the active bodies' forces are those without the test particles, bit for bit
    assert_eq!(fa, fs[..300]);
    // a test particle's acceleration does not depend on its mass
    let heavier: Vec<f64> = m
        .iter()
        .enumerate()
        .map(|(k, &x)| if k < 100 { x } else { 7.0 * x })
        .collect();
    let some7 = NBody::<f64, DVector<f64>>::new(1.0, &heavier, 3)
        .unwrap()
        .with_active(100)
        .unwrap();
    let mut f7 = vec![0.0; 1200];
    some7.force(0.0, &q, &mut f7);
    for k in 100..400 {
        for c in 0..3 {
            let (a, b) = (fs[3 * k + c] / m[k], f7[3 * k + c] / heavier[k]);
            assert!((a - b).abs() <= 1e-14 * a.abs().max(1e-300), "{k}: {a} {b}");
        }
    }
    // no active body: nothing pulls
    let none = NBody::<f64, DVector<f64>>::new(1.0, &m[..10], 3)
        .unwrap()
        .with_active(0)
        .unwrap();
    let mut f0 = vec![1.0; 30];
    none.force(0.0, &q[..30], &mut f0);
    assert!(f0.iter().all(|&x| x == 0.0));
}

#[test]
fn impossible_active_counts_are_errors() {
    let nb = NBody::<f64, DVector<f64>>::new(1.0, &[1.0, 1.0], 3).unwrap();
    let err = nb.clone().with_active(3).unwrap_err().to_string();
    assert!(err.contains("at most 2, got 3"), "{err}");
    let fixed = NBody::<f64, [f64; 12], stormer::models::Bodies<3, 2>>::new(1.0, &[1.0, 1.0], 3).unwrap();
    let err = fixed.with_active(1).unwrap_err().to_string();
    assert!(err.contains("AnyShape"), "{err}");
}

/// A checkpoint of a run on 2 threads resumed on 1 (docs/reproducibility.md): the force's
/// fixed order of summation makes the run continued in a new process with another number
/// of threads end bitwise where the uninterrupted run does.
#[test]
fn a_run_on_two_threads_resumed_on_one_ends_bitwise_equal() {
    use stormer::driver::{RunState, Solution};
    use stormer::Driver;
    let (n, steps) = (1000, 8);
    let (q, v, m) = star_and_disc(n);
    let nb = NBody::<f64, DVector<f64>>::new(1.0, &m, 3).unwrap();
    let mut y0 = DVector::zeros(6 * n);
    nb.set_state(&q, &v, &mut y0).unwrap();
    let t_end = steps as f64 * 1e-3;
    let pool = |threads| rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
    let stepper = || SplittingStepper::<VelocityVerletKdk, DVector<f64>>::new(&y0).unwrap();
    let driver = || Driver::fixed(1e-3).every(1000);
    let mut whole = Solution::default();
    pool(2).install(|| {
        driver()
            .run_into(&nb, &mut stepper(), 0.0, &y0, t_end, &mut whole)
            .unwrap()
    });
    // paused half way on 2 threads, its state through JSON, resumed on 1
    let mut first = Solution::default();
    let paused = pool(2).install(|| {
        let run = driver()
            .pause_at(steps / 2)
            .run_resumable(&nb, &mut stepper(), 0.0, &y0, t_end, &mut first, None);
        run.paused.unwrap()
    });
    let saved: RunState = serde_json::from_str(&serde_json::to_string(&paused).unwrap()).unwrap();
    let mut rest = Solution::default();
    pool(1).install(|| {
        let run = driver().run_resumable(&nb, &mut stepper(), 0.0, &y0, t_end, &mut rest, Some(&saved));
        run.outcome.unwrap();
    });
    let (a, b) = (whole.y.last().unwrap(), rest.y.last().unwrap());
    assert!(a.iter().all(|x| x.is_finite()));
    assert!(
        a.iter().zip(b).all(|(a, b)| a.to_bits() == b.to_bits()),
        "the resumed run differs"
    );
}
