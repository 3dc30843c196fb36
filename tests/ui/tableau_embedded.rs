// Embedded weights `b_hat` come with their order and are checked as `b` is.

// Embedded weights whose order is not declared.
stormer::tableau! {
    pub struct NoEmbeddedOrder {
        name: "no_embedded_order",
        order: 2,
        a: [[], [1]],
        b: [1/2, 1/2],
        b_hat: [1, 0],
    }
}

// An embedded order with no embedded weights.
stormer::tableau! {
    pub struct NoEmbeddedWeights {
        name: "no_embedded_weights",
        order: 2,
        a: [[], [1]],
        b: [1/2, 1/2],
        embedded_order: 1,
    }
}

// Embedded weights of the wrong length.
stormer::tableau! {
    pub struct LongEmbeddedWeights {
        name: "long_embedded_weights",
        order: 2,
        a: [[], [1]],
        b: [1/2, 1/2],
        b_hat: [1, 0, 0],
        embedded_order: 1,
    }
}

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
