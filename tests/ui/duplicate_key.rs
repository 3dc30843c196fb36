// A key given twice: the error is on the second one.
stormer::tableau! {
    pub struct Euler {
        name: "euler",
        order: 1,
        a: [[0]],
        b: [1],
        order: 2,
    }
}

fn main() {}
