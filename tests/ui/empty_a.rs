// An empty stage matrix for a two-stage method.
stormer::tableau! {
    pub struct Heun {
        name: "heun",
        order: 2,
        a: [],
        b: [1/2, 1/2],
    }
}

fn main() {}
