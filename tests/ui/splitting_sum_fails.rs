// Stormer-Verlet with a mistyped second half drift: the drifts no longer sum to 1.
stormer::splitting! {
    pub struct BadVerlet {
        name: "bad_verlet",
        order: 2,
        drift: [1/2, 0.45],
        kick: [1, 0],
    }
}

fn main() {}
