// Forest-Ruth with its kick weights moved in the 8th digit, (theta + d, 1 - 2 theta - 2 d,
// theta + d) with d = 1e-8: still consistent and palindromic (so of even order), but the
// order-3 conditions that a symmetric method needs for order 4 fail by about 1e-7.
stormer::splitting! {
    pub struct ForestRuthPerturbed {
        name: "forest_ruth_perturbed",
        order: 4,
        drift: [
            0.675603595979828817023843904485730413461, -0.175603595979828817023843904485730413461,
            -0.175603595979828817023843904485730413461, 0.675603595979828817023843904485730413461,
        ],
        kick: [
            1.351207191959657634047687808971460826922 + 0.00000001,
            -1.702414383919315268095375617942921653844 - 0.00000002,
            1.351207191959657634047687808971460826922 + 0.00000001,
            0,
        ],
    }
}

fn main() {}
