// RK4 with b_4 = 1/5 (and b_1 = 2/15 so that the weights still sum to 1): the error is on
// `b`, naming the first condition that fails.
stormer::tableau! {
    pub struct BadRk4 {
        name: "bad_rk4",
        order: 4,
        a: [[], [1/2], [0, 1/2], [0, 0, 1]],
        b: [2/15, 1/3, 1/3, 1/5],
    }
}

fn main() {}
