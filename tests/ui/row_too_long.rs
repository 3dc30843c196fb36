// A row of a with more entries than there are stages: the error is on that row.
stormer::tableau! {
    pub struct Heun {
        name: "heun",
        order: 2,
        a: [[0, 0], [1, 0, 0]],
        b: [1/2, 1/2],
    }
}

fn main() {}
