// Embedded weights of the wrong length.
stormer::tableau! {
    pub struct HeunEuler {
        name: "heun_euler",
        order: 2,
        a: [[], [1]],
        b: [1/2, 1/2],
        b_hat: [1, 0, 0],
        embedded_order: 1,
    }
}

fn main() {}
