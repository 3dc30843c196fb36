// A node too many.
stormer::tableau! {
    pub struct Heun {
        name: "heun",
        order: 2,
        c: [0, 1, 1],
        a: [[], [1]],
        b: [1/2, 1/2],
    }
}

fn main() {}
