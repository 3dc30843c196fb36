// Calvo-Sanz-Serna 4 as OrdinaryDiffEq.jl's `CalvoSanz4` applies it (its 14-digit values,
// `b` as drifts and `a` as kicks): of order 3 with a quadratic kinetic energy.
stormer::splitting! {
    pub struct CalvoSanz4Swapped {
        name: "calvo_sanz4_swapped",
        order: 4,
        drift: [0.061758858135626, 0.33897802655364, 0.61479130717558, -0.14054801465937, 0.12501982279453],
        kick: [0.205177661542290, 0.403021281604210, -0.12092087633891, 0.512721933192410, 0],
        quadratic_kinetic: true,
    }
}

fn main() {}
