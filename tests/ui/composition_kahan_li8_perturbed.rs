// Kahan-Li 8 with gamma_1 = gamma_17 moved by 1e-3 and gamma_6 .. gamma_12 solved back onto
// every condition up to order 6 (order/tests/conditions/splittings.rs, kahan_li8_perturbed):
// palindromic and consistent, of order 6 exactly; declared 8, an order-7 condition fails.
stormer::composition! {
    pub struct KahanLi8Perturbed {
        name: "kahan_li8_perturbed",
        order: 8,
        gamma: [
            0.13120248308889007, 0.5611629817751084, -0.38947496264484727, 0.1588419065551556,
            -0.39590389413323757, 0.18438962077367674, 0.2550273565699243, 0.2975468439041746,
            -0.6055846717776898, 0.2975468439041746, 0.2550273565699243, 0.18438962077367674,
            -0.39590389413323757, 0.1588419065551556, -0.38947496264484727, 0.5611629817751084,
            0.13120248308889007,
        ],
    }
}

fn main() {}
