// Blanes-Moan S10 with a_1 moved by 1e-3 and a_4, a_5, b_5, b_6 solved back onto every
// condition up to order 4 (order/tests/conditions/splittings.rs, blanes_moan_s10_perturbed), written as
// its word: palindromic and consistent, of order 4 exactly; declared 6, an order-5
// condition fails.
stormer::splitting! {
    pub struct BlanesMoanS10Perturbed {
        name: "blanes_moan_s10_perturbed",
        order: 6,
        word: [
            kick(0.0502627644003922), drift(0.149816447901042), kick(0.413514300428344),
            drift(-0.132385865767784), kick(0.0450798897943977), drift(0.067307604692185),
            kick(-0.188054853819569), drift(0.44067614894044055), kick(0.5001700179301716),
            drift(-0.025414335765883533), kick(-0.6419442374674729), drift(-0.025414335765883533),
            kick(0.5001700179301716), drift(0.44067614894044055), kick(-0.188054853819569),
            drift(0.067307604692185), kick(0.0450798897943977), drift(-0.132385865767784),
            kick(0.413514300428344), drift(0.149816447901042), kick(0.0502627644003922),
        ],
    }
}

fn main() {}
