// Embedded weights whose order is not declared.
stormer::tableau! {
    pub struct HeunEuler {
        name: "heun_euler",
        order: 2,
        a: [[], [1]],
        b: [1/2, 1/2],
        b_hat: [1, 0],
    }
}

fn main() {}
