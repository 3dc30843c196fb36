// c_2 disagrees with the sum of row 2 of a: the error is on that node.
stormer::tableau! {
    pub struct Midpoint {
        name: "midpoint",
        order: 2,
        c: [0, 1/3],
        a: [[0, 0], [1/2, 0]],
        b: [0, 1],
    }
}

fn main() {}
