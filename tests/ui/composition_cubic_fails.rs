// The triple jump with its weights rounded to 3 digits: sum gamma = 1 holds (the middle
// weight is 1 - 2 w1), sum gamma^3 = 0 does not.
stormer::composition! {
    pub struct RoundedJump {
        name: "rounded_jump",
        order: 4,
        gamma: [1.351, 1 - 2 * 1.351, 1.351],
    }
}

fn main() {}
