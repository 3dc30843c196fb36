// McLachlan-Atela 4 as OrdinaryDiffEq.jl's `McAte4` applies it: the catalog's numbers with
// the roles of drift and kick swapped (docs/anchors.md, the pitfall). Even with a
// quadratic kinetic energy it is of order 3: an order-4 condition of that class fails.
stormer::splitting! {
    pub struct McAte4Swapped {
        name: "mcate4_swapped",
        order: 4,
        drift: [0.134496199277431089, -0.224819803079420806, 0.756320000515668291, 0.334003603286321425],
        kick: [0.515352837431122936, -0.085782019412973646, 0.441583023616466524, 0.128846158365384185],
        quadratic_kinetic: true,
    }
}

fn main() {}
