// Symplectic Euler declared as second order: the sums hold, the order-2 condition does not.
stormer::splitting! {
    pub struct NotSecondOrder {
        name: "not_second_order",
        order: 2,
        drift: [1],
        kick: [1],
    }
}

fn main() {}
