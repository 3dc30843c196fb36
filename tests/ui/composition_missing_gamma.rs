stormer::composition! {
    pub struct Empty {
        name: "empty",
        order: 2,
    }
}

fn main() {}
