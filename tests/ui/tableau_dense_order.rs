// A dense output declared at a higher order than its coefficients have: the midpoint
// rule's interpolant b(theta) = (theta - theta^2, theta^2) is of order 2, not 3.
stormer::tableau! {
    pub struct MidpointDense {
        name: "midpoint_dense",
        order: 2,
        a: [[], [1/2]],
        b: [0, 1],
        dense: [[1, -1], [0, 1]],
        dense_order: 3,
    }
}

fn main() {}
