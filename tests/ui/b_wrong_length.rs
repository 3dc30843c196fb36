// b defines the number of stages; with one weight missing, a has one row too many.
stormer::tableau! {
    pub struct Rk4 {
        name: "rk4",
        order: 4,
        a: [[], [1/2], [0, 1/2], [0, 0, 1]],
        b: [1/6, 1/3, 1/3],
    }
}

fn main() {}
