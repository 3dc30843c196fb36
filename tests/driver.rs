//! The driver's step bookkeeping.

use stormer::{Driver, Problem};

struct Decay;
impl Problem for Decay {
    type Scalar = f32;
    type State = [f32; 1];
    fn rhs(&self, _t: f32, y: &[f32; 1], dy: &mut [f32; 1]) {
        dy[0] = -y[0];
    }
}

/// In f32, `span / h` is off by a few epsilon: the driver still takes exactly n steps
/// (not n plus a sliver) for every n up to 3000 over [0, 1].
#[test]
fn f32_fixed_steps_divide_the_span_exactly() {
    for n in 1..3000u32 {
        let mut s = stormer::registry::stepper::<Decay>("euler", &[1.0], &Default::default()).unwrap();
        let sol = Driver::fixed(1.0 / n as f32)
            .every(u64::MAX)
            .run(&Decay, &mut s, 0.0, &[1.0], 1.0)
            .unwrap();
        assert_eq!(sol.stats.steps, u64::from(n), "n = {n}");
    }
}
