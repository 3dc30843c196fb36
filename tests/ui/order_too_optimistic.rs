// Heun's third-order method declared as fourth order: all conditions up to order 3 hold,
// the bushy tree of order 4 does not.
stormer::tableau! {
    pub struct Heun3 {
        name: "heun3",
        order: 4,
        c: [0, 1/3, 2/3],
        a: [[], [1/3], [0, 2/3]],
        b: [1/4, 0, 3/4],
    }
}

fn main() {}
