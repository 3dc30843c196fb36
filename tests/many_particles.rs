#![allow(unsafe_code)] // the counting allocator (tests/support/counting_alloc.rs); the library itself forbids unsafe code
//! Many independent particles: Boris pushes them one by one ([`Lorentz::external_fields`])
//! with bitwise the numbers of its general loop; the pushers give bitwise the same states
//! on 1 thread and on 2 (fixed chunks, no reduction); a step allocates nothing.

#[path = "support/counting_alloc.rs"]
mod counting_alloc;
use counting_alloc::allocations;
use nalgebra::DVector;
use stormer::magnetic::{Charged, Lorentz};
use stormer::models::SplitMix64;
use stormer::models::{ChargedParticles, MagneticField, RelativisticParticles};
use stormer::stepper::{Boris, BorisRotation, RelativisticPush, PARALLEL_FROM, RELATIVISTIC_METHODS};
use stormer::Stepper;

/// `n` particles of two species (ratios -1 and 1/2) in a magnetic bottle and a uniform E: positions in a box,
/// velocities up to 1.
fn bottle(n: usize) -> (ChargedParticles<f64, DVector<f64>>, DVector<f64>) {
    let masses: Vec<f64> = (0..n).map(|k| if k % 2 == 0 { 1.0 } else { 4.0 }).collect();
    let charges: Vec<f64> = (0..n).map(|k| if k % 2 == 0 { -1.0 } else { 2.0 }).collect();
    let model = ChargedParticles::new(&masses, &charges)
        .unwrap()
        .with_field(MagneticField::Bottle { b0: 1.0, length: 3.0 })
        .with_electric_field([0.05, 0.0, 0.01]);
    let mut sample = SplitMix64::new(7);
    let mut y0 = DVector::zeros(6 * n);
    model
        .set_state(
            &sample.by_ref().take(3 * n).collect::<Vec<_>>(),
            &sample.by_ref().take(3 * n).collect::<Vec<_>>(),
            &mut y0,
        )
        .unwrap();
    (model, y0)
}

/// The model, hiding that its particles are independent: Boris takes its general loop.
struct Coupled(ChargedParticles<f64, DVector<f64>>);

impl Lorentz for Coupled {
    type Scalar = f64;
    type State = DVector<f64>;
    fn omega(&self, particle: usize, q: &[f64]) -> [f64; 3] {
        self.0.omega(particle, q)
    }
    fn uniform(&self) -> bool {
        self.0.uniform()
    }
    fn acceleration(&self, t: f64, q: &[f64], a: &mut [f64]) {
        self.0.acceleration(t, q, a)
    }
}

fn boris_steps<L: Lorentz<Scalar = f64, State = DVector<f64>>>(
    rotation: BorisRotation,
    p: &Charged<L>,
    y0: &DVector<f64>,
    steps: usize,
) -> DVector<f64> {
    let mut boris = Boris::new(rotation, y0).unwrap();
    let mut y = y0.clone();
    for n in 0..steps {
        boris.step_in_place(p, n as f64 * 0.05, 0.05, &mut y).unwrap();
    }
    y
}

#[test]
fn boris_pushes_independent_particles_with_the_numbers_of_its_general_loop() {
    // 1003 particles: lanes of 4 in a uniform field, and 3 pushed one by one
    let (bottled, y0) = bottle(1003);
    assert!(bottled.external_fields().is_some());
    let uniform = bottled.clone().with_field(MagneticField::uniform_b([0.3, -0.2, 1.1]));
    let none = bottled.clone().with_field(MagneticField::None);
    for model in [bottled.clone(), uniform, none] {
        for rotation in [BorisRotation::Cayley, BorisRotation::ExactPhase] {
            let fast = boris_steps(rotation, &Charged(model.clone()), &y0, 50);
            let general = boris_steps(rotation, &Charged(Coupled(model.clone())), &y0, 50);
            assert!(
                fast.iter().zip(&general).all(|(a, b)| a.to_bits() == b.to_bits()),
                "{rotation:?} in {:?}",
                model.field()
            );
            assert!(fast != y0);
        }
    }
    let model = bottled;
    // a centre (or a quadrupole, or interaction) couples them to more than the fields
    assert!(model.clone().with_centre(1.0).external_fields().is_none());
}

/// `f` run in a pool of `threads` threads.
fn with_threads<R: Send>(threads: usize, f: impl FnOnce() -> R + Send) -> R {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

#[test]
fn one_thread_or_two_give_bitwise_the_same_states() {
    // enough particles for the parallel chunks, and a last chunk that is not full
    let n = 2 * PARALLEL_FROM + 123;
    let (model, y0) = bottle(n);
    let p = Charged(model.clone());
    let boris = |threads| with_threads(threads, || boris_steps(BorisRotation::Cayley, &p, &y0, 20));
    assert_eq!(boris(1), boris(2));
    let relativistic = RelativisticParticles::<f64, DVector<f64>>::new(model.masses(), model.charges(), 2.0)
        .unwrap()
        .with_field(MagneticField::Dipole { moment: -5.0 })
        .with_electric_field([0.0, 0.3, 0.0]);
    let mut y1 = y0.clone();
    // the dipole's field is infinite at the origin: start outside the unit sphere
    for x in y1.as_mut_slice()[..3 * n].iter_mut() {
        *x += x.signum() * 2.0;
    }
    for &method in RELATIVISTIC_METHODS {
        let push = |threads| {
            with_threads(threads, || {
                let mut stepper = RelativisticPush::new(method, &y1).unwrap();
                let mut y = y1.clone();
                for n in 0..20 {
                    stepper
                        .step_in_place(&relativistic, n as f64 * 0.05, 0.05, &mut y)
                        .unwrap();
                }
                y
            })
        };
        let (one, two) = (push(1), push(2));
        assert!(one.iter().all(|x| x.is_finite()));
        assert!(
            one.iter().zip(&two).all(|(a, b)| a.to_bits() == b.to_bits()),
            "{method:?}"
        );
    }
}

/// The allocations of the calling thread over `steps` Boris and Vay steps of `n` particles
/// (after one step of each, which may start the thread pool).
fn allocations_in_steps(n: usize, steps: usize) -> usize {
    let (model, y0) = bottle(n);
    let p = Charged(model.clone());
    let mut boris = Boris::new(BorisRotation::Cayley, &y0).unwrap();
    let mut y = y0.clone();
    let relativistic = RelativisticParticles::<f64, DVector<f64>>::new(model.masses(), model.charges(), 3.0)
        .unwrap()
        .with_field(MagneticField::Bottle { b0: 1.0, length: 3.0 });
    let mut vay = RelativisticPush::new(stormer::stepper::RelativisticMethod::Vay, &y0).unwrap();
    let mut u = y0.clone();
    boris.step_in_place(&p, 0.0, 0.01, &mut y).unwrap();
    vay.step_in_place(&relativistic, 0.0, 0.01, &mut u).unwrap();
    let before = allocations();
    for n in 0..steps {
        boris.step_in_place(&p, n as f64 * 0.01, 0.01, &mut y).unwrap();
        vay.step_in_place(&relativistic, n as f64 * 0.01, 0.01, &mut u).unwrap();
    }
    allocations() - before
}

/// A step allocates nothing. In parallel (with the feature `parallel`), handing the step to
/// rayon's pool from outside it puts one job in the pool's queue, which allocates a block
/// of 63 slots when the last is full: at most one allocation per 63 parallel steps, none in
/// the step's own code (measured: 3 in 200 steps of each pusher).
#[test]
fn a_step_of_many_particles_allocates_nothing() {
    assert_eq!(allocations_in_steps(PARALLEL_FROM - 1, 100), 0);
    let steps = 2 * 63 * 5;
    let parallel = allocations_in_steps(PARALLEL_FROM + 1, steps / 2);
    assert!(
        parallel <= steps / 63 + 1,
        "{parallel} allocations in {steps} parallel steps"
    );
}
