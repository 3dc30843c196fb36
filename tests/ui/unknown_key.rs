// A misspelt key.
stormer::tableau! {
    pub struct Euler {
        name: "euler",
        order: 1,
        a: [[0]],
        b: [1],
        bhat: [1],
    }
}

fn main() {}
