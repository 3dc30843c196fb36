// The keys of `tableau!`: every error is on the key (or the struct) it is about.

// A misspelt key.
stormer::tableau! {
    pub struct Misspelt {
        name: "misspelt",
        order: 1,
        a: [[0]],
        b: [1],
        bhat: [1],
    }
}

// A key given twice: the error is on the second one.
stormer::tableau! {
    pub struct Twice {
        name: "twice",
        order: 1,
        a: [[0]],
        b: [1],
        order: 2,
    }
}

// No weights: the error is on the struct's name.
stormer::tableau! {
    pub struct NoWeights {
        name: "no_weights",
        order: 1,
        a: [[0]],
    }
}

// The order is an integer literal.
stormer::tableau! {
    pub struct HalfOrder {
        name: "half_order",
        order: 1.5,
        a: [[0]],
        b: [1],
    }
}

fn main() {}
