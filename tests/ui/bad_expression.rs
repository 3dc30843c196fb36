// Coefficients that do not evaluate: every one is reported, each on its expression.
stormer::tableau! {
    pub struct Broken {
        name: "broken",
        order: 1,
        a: [[0, 0, 0], [1/0], [cos(1), 0]],
        b: [x, 0, 0],
    }
}

fn main() {}
