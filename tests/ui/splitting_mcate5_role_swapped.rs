// McLachlan-Atela 5 as OrdinaryDiffEq.jl's `McAte5` applies it, drift and kick swapped:
// of order 3 with a quadratic kinetic energy, refused at its nominal order 5.
stormer::splitting! {
    pub struct McAte5Swapped {
        name: "mcate5_swapped",
        order: 5,
        drift: [
            0.1193900292875672758, 0.6989273703824752308, -0.1713123582716007754,
            0.4012695022513534480, 0.0107050818482359840, -0.0589796254980311632,
        ],
        kick: [
            0.339839625839110000, -0.088601336903027329, 0.5858564768259621188,
            -0.603039356536491888, 0.3235807965546976394, 0.4423637942197494587,
        ],
        quadratic_kinetic: true,
    }
}

fn main() {}
