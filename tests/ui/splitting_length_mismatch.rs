stormer::splitting! {
    pub struct Uneven {
        name: "uneven",
        order: 1,
        drift: [1/2, 1/2],
        kick: [1],
    }
}

fn main() {}
