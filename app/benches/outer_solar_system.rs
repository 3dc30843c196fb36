//! Generated splitting steppers against hand-written loops on the outer solar system
//! (docs/scenes.md 4: Sun, Jupiter, Saturn, Uranus in 3-D, dt = 10 days), in one binary.
//!
//! Two methods: velocity Verlet (`velocity_verlet_kdk`, one force evaluation per step with
//! FSAL) and the triple jump (`triple_jump4`, the composition expanded over drift-kick-drift
//! Verlet: three evaluations per step). For each:
//!
//! - **hand_written**: the step typed out on `[f64; 12]` positions and momenta, with its own
//!   four-body force (all sizes known at compile time), in the operation order of the
//!   generated code (same coefficients, same pair order, same sums);
//! - **generated**: `SplittingStepper<M, [f64; 24]>` on `NBody<f64, [f64; 24], Bodies<3, 4>>`
//!   (four bodies in 3-D fixed at compile time, as the hand-written loop has them) through the
//!   `Stepper` interface, stepping in place (`Stepper::step_in_place`, what the fixed-step
//!   driver calls);
//! - **generated_any_shape**: the same on `NBody<f64, [f64; 24]>`, whose force loop is chosen
//!   from the bodies at run time;
//! - **driver**: the same stepper run by the library's `Driver` (fixed steps, a record at
//!   the start and at the end), the path of the CLI;
//! - **generated_flows_copy**: the macro's unrolled word (`M::flows`) without the
//!   `Stepper` trait but with its data flow: `y_new <- y`, then the word on `y_new`;
//! - **generated_flows_local**: the same on a local copy of `y`, written to `y_new` at the
//!   end;
//! - **generated_in_place**: the word in place on one `[f64; 24]` state and its halves (what
//!   an in-place step, without a second state, would do);
//! - **generated_flows**: the word in place on local `q` and `p` arrays, as the
//!   hand-written loop does (the code the macro generates, without the `Stepper` data flow);
//! - **hand_loop_nbody_force**: the hand-written step calling `NBody`'s force and velocity
//!   (the problem's generality without the stepper);
//! - **file_scene**: the generated stepper on the scene read from `scenes/`, a
//!   `DVector<f64>` state (docs/anchors.md's "cost of generality", target 1.3x).
//!
//! Before any timing the bench asserts that all of them (and the boxed stepper of the
//! registry, the CLI's path) give trajectories bitwise equal to the hand-written loop over
//! 10 000 steps. After criterion's report it times the kernels interleaved (31 rounds) and
//! prints min and median ns per step, the ratio to hand-written, and ns per force
//! evaluation.
//!
//! Run: `cargo bench --bench outer_solar_system`

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "../../benches/support/interleaved.rs"]
mod interleaved;

use std::hint::black_box;

use criterion::{criterion_group, Criterion};
use interleaved::Kernel;
use nalgebra::DVector;
use stormer::catalog::{TripleJump4, VelocityVerletKdk};
use stormer::driver::Recorder;
use stormer::hamiltonian::Hamiltonian;
use stormer::method::SplittingMethod;
use stormer::models::{Bodies, NBody};
use stormer::stepper::SplittingStepper;
use stormer::verify::conditions::splitting::Flow;
use stormer::{Driver, Method, Stepper};
use stormer_app::scenes::{self, AnyScene};

const STEPS: usize = 1000;
const H: f64 = 10.0;
const N: usize = 4;

type Problem = NBody<f64, [f64; 24], Bodies<3, 4>>;
type AnyShapeProblem = NBody<f64, [f64; 24]>;
type FileProblem = NBody<f64, DVector<f64>>;

/// The scene as shipped (file values), both as a static-size problem and as read.
struct Setup {
    nbody: Problem,
    any_shape: AnyShapeProblem,
    file: FileProblem,
    y0: [f64; 24],
    y0_file: DVector<f64>,
    /// `G m_k m_l` for the pairs in order, and `1 / m_k` per coordinate.
    pair_gm: [f64; 6],
    inverse_mass: [f64; 12],
}

fn setup() -> Setup {
    let AnyScene::NBody(scene) = scenes::load("outer-solar-system").expect("built-in scene") else {
        panic!("outer-solar-system is an n-body scene")
    };
    let masses = scene.model.masses().to_vec();
    let g = scene.model.g();
    let nbody = Problem::new(g, &masses, 3).expect("valid bodies");
    let any_shape = AnyShapeProblem::new(g, &masses, 3).expect("valid bodies");
    let y0: [f64; 24] = scene.y0.as_slice().try_into().expect("4 bodies in 3-D");
    let mut pair_gm = [0.0; 6];
    let mut pair = 0;
    for k in 0..N {
        for l in k + 1..N {
            pair_gm[pair] = g * masses[k] * masses[l];
            pair += 1;
        }
    }
    let inverse_mass = std::array::from_fn(|i| 1.0 / masses[i / 3]);
    Setup {
        nbody,
        any_shape,
        y0_file: scene.y0.clone(),
        file: scene.model,
        y0,
        pair_gm,
        inverse_mass,
    }
}

/// The four-body force written for four bodies in 3-D: each pair once, its share added to
/// the later body and summed in registers for the earlier one (the order of `NBody`'s).
#[inline(always)]
fn hand_force(gm: &[f64; 6], q: &[f64; 12], f: &mut [f64; 12]) {
    *f = [0.0; 12];
    let mut pair = 0;
    for k in 0..N {
        let mut fk = [0.0; 3];
        for l in k + 1..N {
            let d = [
                q[3 * k] - q[3 * l],
                q[3 * k + 1] - q[3 * l + 1],
                q[3 * k + 2] - q[3 * l + 2],
            ];
            let r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            let s = gm[pair] / (r2 * r2.sqrt());
            pair += 1;
            for c in 0..3 {
                let x = s * d[c];
                fk[c] -= x;
                f[3 * l + c] += x;
            }
        }
        for c in 0..3 {
            f[3 * k + c] += fk[c];
        }
    }
}

#[inline(always)]
fn split(y: &[f64; 24]) -> ([f64; 12], [f64; 12]) {
    (
        y[..12].try_into().expect("12 positions"),
        y[12..].try_into().expect("12 momenta"),
    )
}

#[inline(always)]
fn join(q: &[f64; 12], p: &[f64; 12]) -> [f64; 24] {
    std::array::from_fn(|i| if i < 12 { q[i] } else { p[i - 12] })
}

#[inline(always)]
fn drift(tau: f64, w: &[f64; 12], q: &mut [f64; 12], p: &[f64; 12]) {
    for i in 0..12 {
        q[i] += tau * (p[i] * w[i]);
    }
}

#[inline(always)]
fn kick(tau: f64, f: &[f64; 12], p: &mut [f64; 12]) {
    for i in 0..12 {
        p[i] += tau * f[i];
    }
}

/// Velocity Verlet by hand: K(h/2) D(h) K(h/2), the last force reused by the next step.
fn hand_verlet(s: &Setup, steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24] {
    let (mut q, mut p) = split(y0);
    let mut f = [0.0; 12];
    hand_force(&s.pair_gm, &q, &mut f);
    let (half, whole) = (0.5 * h, 1.0 * h);
    for _ in 0..steps {
        kick(half, &f, &mut p);
        drift(whole, &s.inverse_mass, &mut q, &p);
        hand_force(&s.pair_gm, &q, &mut f);
        kick(half, &f, &mut p);
    }
    join(&q, &p)
}

/// The triple jump's word over DKD Verlet, D K D K D K D, as seven fractions.
fn jump_word() -> [f64; 7] {
    let word = TripleJump4::DATA.word();
    let flows: Vec<Flow> = word.iter().map(|op| op.flow).collect();
    use Flow::{Drift as D, Kick as K};
    assert_eq!(flows, [D, K, D, K, D, K, D], "triple_jump4's word");
    std::array::from_fn(|i| word[i].coef)
}

/// The triple jump by hand: three kicks, four drifts, no force carried over.
fn hand_jump(s: &Setup, c: &[f64; 7], steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24] {
    let (mut q, mut p) = split(y0);
    let mut f = [0.0; 12];
    for _ in 0..steps {
        drift(c[0] * h, &s.inverse_mass, &mut q, &p);
        hand_force(&s.pair_gm, &q, &mut f);
        kick(c[1] * h, &f, &mut p);
        drift(c[2] * h, &s.inverse_mass, &mut q, &p);
        hand_force(&s.pair_gm, &q, &mut f);
        kick(c[3] * h, &f, &mut p);
        drift(c[4] * h, &s.inverse_mass, &mut q, &p);
        hand_force(&s.pair_gm, &q, &mut f);
        kick(c[5] * h, &f, &mut p);
        drift(c[6] * h, &s.inverse_mass, &mut q, &p);
    }
    join(&q, &p)
}

/// Velocity Verlet by hand, but with `NBody`'s force and velocity.
fn hand_verlet_nbody(s: &Setup, steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24] {
    let nb = &s.nbody;
    let (mut q, mut p) = split(y0);
    let (mut f, mut v) = ([0.0; 12], [0.0; 12]);
    Hamiltonian::force(nb, 0.0, &q, &mut f);
    let (half, whole) = (0.5 * h, 1.0 * h);
    for _ in 0..steps {
        kick(half, &f, &mut p);
        nb.kinetic_gradient(&p, &mut v);
        for i in 0..12 {
            q[i] += whole * v[i];
        }
        Hamiltonian::force(nb, 0.0, &q, &mut f);
        kick(half, &f, &mut p);
    }
    join(&q, &p)
}

/// The triple jump by hand, with `NBody`'s force and velocity.
fn hand_jump_nbody(s: &Setup, c: &[f64; 7], steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24] {
    let nb = &s.nbody;
    let (mut q, mut p) = split(y0);
    let (mut f, mut v) = ([0.0; 12], [0.0; 12]);
    for _ in 0..steps {
        for j in 0..3 {
            nb.kinetic_gradient(&p, &mut v);
            for i in 0..12 {
                q[i] += c[2 * j] * h * v[i];
            }
            Hamiltonian::force(nb, 0.0, &q, &mut f);
            kick(c[2 * j + 1] * h, &f, &mut p);
        }
        nb.kinetic_gradient(&p, &mut v);
        for i in 0..12 {
            q[i] += c[6] * h * v[i];
        }
    }
    join(&q, &p)
}

/// Any stepper through the `Stepper` interface: in place when it steps in place (as the
/// fixed-step driver does), else ping-ponging between two states (no swap).
fn with_stepper<P, St>(problem: &P, stepper: &mut St, steps: usize, h: f64, y0: &P::State) -> P::State
where
    P: stormer::Problem<Scalar = f64>,
    St: Stepper<P> + ?Sized,
{
    if stepper.steps_in_place() {
        let mut y = y0.clone();
        for i in 0..steps {
            let _ = stepper.step_in_place(problem, i as f64 * h, h, &mut y);
        }
        return y;
    }
    ping_pong(steps, y0, |i, from, to| {
        let _ = stepper.step(problem, i as f64 * h, h, from, to);
        stepper.accept();
    })
}

/// `steps` steps between two copies of `y0` (no swap): step `i` reads one and writes the
/// other; the state last written is returned.
#[inline(always)]
fn ping_pong<Y: Clone>(steps: usize, y0: &Y, mut step: impl FnMut(usize, &Y, &mut Y)) -> Y {
    let (mut a, mut b) = (y0.clone(), y0.clone());
    for i in 0..steps {
        let (from, to) = if i % 2 == 0 { (&a, &mut b) } else { (&b, &mut a) };
        step(i, from, to);
    }
    if steps % 2 == 0 {
        a
    } else {
        b
    }
}

/// A new `SplittingStepper` of `M` through `with_stepper` on `problem`.
fn with_new_stepper<M, P>(problem: &P, steps: usize, h: f64, y0: &P::State) -> P::State
where
    M: SplittingMethod,
    P: stormer::Problem<Scalar = f64>,
    P::State: stormer::State,
    SplittingStepper<M, P::State>: Stepper<P>,
{
    match SplittingStepper::<M, P::State>::new(y0) {
        Ok(mut st) => with_stepper(problem, &mut st, steps, h, y0),
        Err(e) => panic!("{e}"),
    }
}

fn generated<M: SplittingMethod>(s: &Setup, steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24]
where
    SplittingStepper<M, [f64; 24]>: Stepper<Problem>,
{
    with_new_stepper::<M, _>(&s.nbody, steps, h, y0)
}

/// As `generated`, on the problem whose force loop is chosen at run time.
fn generated_any_shape<M: SplittingMethod>(s: &Setup, steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24]
where
    SplittingStepper<M, [f64; 24]>: Stepper<AnyShapeProblem>,
{
    with_new_stepper::<M, _>(&s.any_shape, steps, h, y0)
}

/// The generated word in place, without the `Stepper` interface.
fn generated_flows<M: SplittingMethod>(s: &Setup, steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24] {
    let co = M::coeffs::<f64>();
    let (mut q, mut p) = split(y0);
    let (mut v, mut f) = ([0.0; 12], [0.0; 12]);
    let mut cached = false;
    for i in 0..steps {
        M::flows(
            &co,
            &s.nbody,
            i as f64 * h,
            h,
            &mut q,
            &mut p,
            &mut v,
            &mut f,
            &mut (),
            cached,
        );
        cached = M::DATA.flags.fsal;
    }
    join(&q, &p)
}

/// The generated word of `M` on the two halves of one `[f64; 24]` state, with its own work
/// halves and the FSAL flag carried from step to step.
struct Word<M: SplittingMethod> {
    co: M::Coeffs<f64>,
    work: [f64; 24],
    cached: bool,
}

impl<M: SplittingMethod> Word<M> {
    fn new() -> Self {
        Word {
            co: M::coeffs::<f64>(),
            work: [0.0; 24],
            cached: false,
        }
    }

    /// Step `i` (of size `h`) in place on `y`.
    #[inline(always)]
    fn apply(&mut self, s: &Setup, i: usize, h: f64, y: &mut [f64; 24]) {
        let (q, p) = y.split_at_mut(12);
        let (v, f) = self.work.split_at_mut(12);
        M::flows(&self.co, &s.nbody, i as f64 * h, h, q, p, v, f, &mut (), self.cached);
        self.cached = M::DATA.flags.fsal;
    }
}

/// The generated word in place on one `[f64; 24]` state (its two halves), no second
/// state: what an in-place step of a stepper would do.
fn generated_in_place<M: SplittingMethod>(s: &Setup, steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24] {
    let mut word = Word::<M>::new();
    let mut y = *y0;
    for i in 0..steps {
        word.apply(s, i, h, &mut y);
    }
    y
}

/// The generated word on a copy of the state, as the `Stepper` interface does it
/// (`y_new <- y`, then the word in place on `y_new`), ping-ponging between two states.
fn generated_flows_copy<M: SplittingMethod>(s: &Setup, steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24] {
    let mut word = Word::<M>::new();
    ping_pong(steps, y0, |i, from, to| {
        to.copy_from_slice(from);
        word.apply(s, i, h, to);
    })
}

/// As `generated_flows_copy`, but the word runs on a local copy written back at the end.
fn generated_flows_local<M: SplittingMethod>(s: &Setup, steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24] {
    let mut word = Word::<M>::new();
    ping_pong(steps, y0, |i, from, to| {
        let mut local = *from;
        word.apply(s, i, h, &mut local);
        *to = local;
    })
}

/// Keeps the last record only.
struct Last([f64; 24]);

impl Recorder<f64, [f64; 24]> for Last {
    fn record(&mut self, _t: f64, y: &[f64; 24], _energy: Option<f64>) -> Result<(), stormer::Error> {
        self.0 = *y;
        Ok(())
    }
}

/// The library's driver (fixed steps, records only at the start and the end): the path of
/// every `Driver::run` and of the CLI.
fn driver<M: SplittingMethod>(s: &Setup, steps: usize, h: f64, y0: &[f64; 24]) -> [f64; 24]
where
    SplittingStepper<M, [f64; 24]>: Stepper<Problem>,
{
    let mut st = SplittingStepper::<M, [f64; 24]>::new(y0).unwrap();
    let mut last = Last(*y0);
    let outcome =
        Driver::fixed(h)
            .every(steps as u64)
            .run_into(&s.nbody, &mut st, 0.0, y0, h * steps as f64, &mut last);
    assert!(outcome.is_ok());
    last.0
}

fn file_scene<M: SplittingMethod>(s: &Setup, steps: usize, h: f64) -> DVector<f64>
where
    SplittingStepper<M, DVector<f64>>: Stepper<FileProblem>,
{
    with_new_stepper::<M, _>(&s.file, steps, h, &s.y0_file)
}

/// Force evaluations alone: `steps` evaluations of `NBody`'s force, and of the hand one.
fn forces_nbody(s: &Setup, steps: usize, y0: &[f64; 24]) -> [f64; 12] {
    let (mut q, _) = split(y0);
    let mut f = [0.0; 12];
    for _ in 0..steps {
        Hamiltonian::force(&s.nbody, 0.0, &q, &mut f);
        // every position depends on the last forces, so that no pair is loop-invariant
        kick(1e-9, &f, &mut q);
    }
    f
}

#[inline(never)]
fn forces_hand(s: &Setup, steps: usize, y0: &[f64; 24]) -> [f64; 12] {
    let (mut q, _) = split(y0);
    let mut f = [0.0; 12];
    for _ in 0..steps {
        hand_force(&s.pair_gm, &q, &mut f);
        kick(1e-9, &f, &mut q);
    }
    f
}

fn bits(y: &[f64]) -> Vec<u64> {
    y.iter().map(|x| x.to_bits()).collect()
}

/// A variant of the stepping loop: `steps` steps of size `h` from `y0`.
type Variant = fn(&Setup, usize, f64, &[f64; 24]) -> [f64; 24];

/// The library's variants of the stepping loop for the method `M`, by name.
fn variants<M: SplittingMethod>() -> [(&'static str, Variant); 7]
where
    SplittingStepper<M, [f64; 24]>: Stepper<Problem> + Stepper<AnyShapeProblem>,
{
    [
        ("generated", generated::<M>),
        ("driver", driver::<M>),
        ("generated_any_shape", generated_any_shape::<M>),
        ("generated_flows_copy", generated_flows_copy::<M>),
        ("generated_flows_local", generated_flows_local::<M>),
        ("generated_in_place", generated_in_place::<M>),
        ("generated_flows", generated_flows::<M>),
    ]
}

/// Every variant of `M` (the library's loops, the hand loop on `NBody`'s force, the file
/// scene) gives the hand-written loop's trajectory to the bit.
fn assert_method_bitwise_equal<M: SplittingMethod>(s: &Setup, n: usize, hand: &[f64; 24], hand_nbody: &[f64; 24])
where
    SplittingStepper<M, [f64; 24]>: Stepper<Problem> + Stepper<AnyShapeProblem>,
    SplittingStepper<M, DVector<f64>>: Stepper<FileProblem>,
{
    let method = M::DATA.name;
    let want = bits(hand);
    let check = |name: &str, got: Vec<u64>| {
        assert_eq!(got, want, "{method}, {name} differs from the hand-written loop");
    };
    for (name, variant) in variants::<M>() {
        check(name, bits(&variant(s, n, H, &s.y0)));
    }
    check("NBody force", bits(hand_nbody));
    check("file scene", bits(file_scene::<M>(s, n, H).as_slice()));
}

fn assert_bitwise_equal(s: &Setup) {
    let n = STEPS * 10;
    let c = jump_word();
    let verlet = hand_verlet(s, n, H, &s.y0);
    let jump = hand_jump(s, &c, n, H, &s.y0);
    assert_method_bitwise_equal::<VelocityVerletKdk>(s, n, &verlet, &hand_verlet_nbody(s, n, H, &s.y0));
    assert_method_bitwise_equal::<TripleJump4>(s, n, &jump, &hand_jump_nbody(s, &c, n, H, &s.y0));
    // the boxed steppers of the registry (the CLI's path) are the same code too
    for (name, want) in [("velocity_verlet_kdk", &verlet), ("triple_jump4", &jump)] {
        let method = Method::named(name).expect("catalog method");
        let mut boxed = method
            .compiled_stepper_for_quadratic(&s.nbody, &s.y0, &Default::default())
            .expect("admitted");
        let got = with_stepper(&s.nbody, &mut boxed, n, H, &s.y0);
        assert_eq!(
            bits(&got),
            bits(want),
            "{name}, boxed stepper differs from the hand-written loop"
        );
    }
    assert_eq!(bits(&forces_nbody(s, 100, &s.y0)), bits(&forces_hand(s, 100, &s.y0)));
}

fn bench(c: &mut Criterion) {
    let s = setup();
    assert_bitwise_equal(&s);
    let w = jump_word();
    let mut group = c.benchmark_group("outer_solar_system_1000_steps");
    group.bench_function("verlet/hand_written", |b| {
        b.iter(|| hand_verlet(&s, STEPS, black_box(H), &s.y0))
    });
    group.bench_function("verlet/generated", |b| {
        b.iter(|| generated::<VelocityVerletKdk>(&s, STEPS, black_box(H), &s.y0))
    });
    group.bench_function("jump/hand_written", |b| {
        b.iter(|| hand_jump(&s, &w, STEPS, black_box(H), &s.y0))
    });
    group.bench_function("jump/generated", |b| {
        b.iter(|| generated::<TripleJump4>(&s, STEPS, black_box(H), &s.y0))
    });
    group.finish();
}

/// Interleaved timing (31 rounds of 50 runs): min and median ns per step of each kernel,
/// with the ratio to the first kernel of the group and ns per force evaluation.
fn print_interleaved(title: &str, evaluations: f64, kernels: &[Kernel<'_, f64>]) {
    const ROUNDS: usize = 31;
    const REPEAT: usize = 50;
    let stats = interleaved::time(kernels, ROUNDS, REPEAT, STEPS);
    println!("\n{title}: interleaved, {ROUNDS} rounds x {REPEAT} runs x {STEPS} steps");
    println!("  kernel                    ns/step min  median   ratio min  median   ns/evaluation (min)");
    for ((name, _), (min, median)) in kernels.iter().zip(&stats) {
        println!(
            "  {name:<24} {min:11.2} {median:7.2}   {:9.3} {:7.3}   {:8.2}",
            min / stats[0].0,
            median / stats[0].1,
            min / evaluations
        );
    }
}

/// The kernels of one method: the hand-written loop, the library's variants between it and
/// the hand loop on `NBody`'s force, then the file scene.
fn kernels<'a, M: SplittingMethod>(
    s: &'a Setup,
    hand: Box<dyn Fn() -> f64 + 'a>,
    hand_nbody: Box<dyn Fn() -> f64 + 'a>,
) -> Vec<Kernel<'a, f64>>
where
    SplittingStepper<M, [f64; 24]>: Stepper<Problem> + Stepper<AnyShapeProblem>,
    SplittingStepper<M, DVector<f64>>: Stepper<FileProblem>,
{
    let mut v: Vec<Kernel<f64>> = vec![("hand_written", hand)];
    for (name, variant) in variants::<M>() {
        let run = move || variant(s, STEPS, black_box(H), &s.y0)[0];
        v.push((name, Box::new(run)));
    }
    v.push(("hand_loop_nbody_force", hand_nbody));
    let file = move || file_scene::<M>(s, STEPS, black_box(H))[0];
    v.push(("file_scene", Box::new(file)));
    v
}

fn interleaved_ratios() {
    let s = setup();
    let w = jump_word();
    let first = |y: [f64; 24]| y[0];
    let verlet = kernels::<VelocityVerletKdk>(
        &s,
        Box::new(|| first(hand_verlet(&s, STEPS, black_box(H), &s.y0))),
        Box::new(|| first(hand_verlet_nbody(&s, STEPS, black_box(H), &s.y0))),
    );
    print_interleaved("velocity_verlet_kdk (1 force evaluation per step)", 1.0, &verlet);
    let jump = kernels::<TripleJump4>(
        &s,
        Box::new(|| first(hand_jump(&s, &w, STEPS, black_box(H), &s.y0))),
        Box::new(|| first(hand_jump_nbody(&s, &w, STEPS, black_box(H), &s.y0))),
    );
    print_interleaved("triple_jump4 (3 force evaluations per step)", 3.0, &jump);
    let forces: Vec<Kernel<f64>> = vec![
        ("hand_force", Box::new(|| forces_hand(&s, STEPS, &s.y0)[0])),
        ("nbody_force", Box::new(|| forces_nbody(&s, STEPS, &s.y0)[0])),
    ];
    print_interleaved("force evaluations alone (per 'step' = one evaluation)", 1.0, &forces);
}

criterion_group!(benches, bench);

fn main() {
    interleaved::main(benches, interleaved_ratios);
}
