stormer::composition! {
    pub struct Mixed {
        name: "mixed",
        order: 2,
        gamma: [1],
        drift: [1],
    }
}

fn main() {}
