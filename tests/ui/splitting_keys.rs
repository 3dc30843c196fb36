// The keys of `splitting!` and `composition!`: each family refuses the other's, and a
// splitting gives its flows one way.

// A word and arrays at once: the error is on the word.
stormer::splitting! {
    pub struct Both {
        name: "both",
        order: 2,
        drift: [0, 1],
        kick: [1/2, 1/2],
        word: [kick(1/2), drift(1), kick(1/2)],
    }
}

// A word names its flows `drift(..)` and `kick(..)`.
stormer::splitting! {
    pub struct Typo {
        name: "typo",
        order: 2,
        word: [kick(1/2), drfit(1), kick(1/2)],
    }
}

// Weights belong to `composition!`.
stormer::splitting! {
    pub struct Weights {
        name: "weights",
        order: 4,
        gamma: [1],
    }
}

// Drifts belong to `splitting!`.
stormer::composition! {
    pub struct Mixed {
        name: "mixed",
        order: 2,
        gamma: [1],
        drift: [1],
    }
}

// A composition without its weights: the error is on the struct's name.
stormer::composition! {
    pub struct Empty {
        name: "empty",
        order: 2,
    }
}

fn main() {}
