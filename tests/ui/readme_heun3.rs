// The README's example: Heun's third-order method with `b` changed is rejected,
// naming the failing condition.
stormer::tableau! {
    pub struct Heun3 {
        name: "heun3",
        order: 3,
        c: [0, 1/3, 2/3],
        a: [[0, 0, 0], [1/3, 0, 0], [0, 2/3, 0]],
        b: [1/4, 1/4, 1/2],
    }
}

fn main() {}
