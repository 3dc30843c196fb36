// Laskar-Robutel SABA2 claiming the generalized order (6, 2) of SABA3: its error for
// H = A + eps B is O(eps h^5 + eps^2 h^3), so an order-5 condition of the eps^1 term fails.
stormer::splitting! {
    pub struct Saba2AsSaba3 {
        name: "saba2_as_saba3",
        order: 2,
        drift: [
            0.2113248654051871177454256097490212721762,
            0.5773502691896257645091487805019574556476,
            0.2113248654051871177454256097490212721762,
        ],
        kick: [1/2, 1/2, 0],
        generalized_order: [6, 2],
    }
}

fn main() {}
