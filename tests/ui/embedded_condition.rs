// Bogacki-Shampine with a wrong b_hat (still summing to 1): the error is on b_hat.
stormer::tableau! {
    pub struct BadBs3 {
        name: "bad_bs3",
        order: 3,
        embedded_order: 2,
        a: [[], [1/2], [0, 3/4], [2/9, 1/3, 4/9]],
        b: [2/9, 1/3, 4/9, 0],
        b_hat: [1/3, 1/4, 1/3, 1/12],
    }
}

fn main() {}
