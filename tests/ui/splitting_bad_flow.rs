// A word names its flows `drift(..)` and `kick(..)`.
stormer::splitting! {
    pub struct Typo {
        name: "typo",
        order: 2,
        word: [kick(1/2), drfit(1), kick(1/2)],
    }
}

fn main() {}
