// The triple jump's weights in closed form are accepted (`2^(1/3)`, `cbrt(2)`); a
// fractional power of a negative base is not a real number, and is reported on its
// expression.
stormer::composition! {
    pub struct ClosedFormJump {
        name: "closed_form_jump",
        order: 4,
        gamma: [1 / (2 - 2^(1/3)), 1 - 2 / (2 - cbrt(2)), 1 / (2 - 2^(1/3))],
    }
}

stormer::composition! {
    pub struct NegativeRoot {
        name: "negative_root",
        order: 4,
        gamma: [1 / (2 - (-2)^(1/3)), 1 - 2 / (2 - (-2)^(1/3)), 1 / (2 - (-2)^(1/3))],
    }
}

fn main() {}
