// Conditions are checked up to order 10.
stormer::tableau! {
    pub struct Euler {
        name: "euler",
        order: 11,
        a: [[0]],
        b: [1],
    }
}

fn main() {}
