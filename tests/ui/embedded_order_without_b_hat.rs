// An embedded order with no embedded weights.
stormer::tableau! {
    pub struct Heun {
        name: "heun",
        order: 2,
        a: [[], [1]],
        b: [1/2, 1/2],
        embedded_order: 1,
    }
}

fn main() {}
