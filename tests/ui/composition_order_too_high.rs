stormer::composition! {
    pub struct Twelve {
        name: "twelve",
        order: 12,
        gamma: [1],
    }
}

fn main() {}
