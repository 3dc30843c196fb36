// Weights belong to `composition!`.
stormer::splitting! {
    pub struct Weights {
        name: "weights",
        order: 4,
        gamma: [1],
    }
}

fn main() {}
