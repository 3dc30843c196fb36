// No weights: the error is on the struct's name.
stormer::tableau! {
    pub struct Euler {
        name: "euler",
        order: 1,
        a: [[0]],
    }
}

fn main() {}
