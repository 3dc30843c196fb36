stormer::splitting! {
    pub struct Both {
        name: "both",
        order: 2,
        drift: [0, 1],
        kick: [1/2, 1/2],
        word: [kick(1/2), drift(1), kick(1/2)],
    }
}

fn main() {}
