// The order is an integer literal.
stormer::tableau! {
    pub struct Euler {
        name: "euler",
        order: 1.5,
        a: [[0]],
        b: [1],
    }
}

fn main() {}
