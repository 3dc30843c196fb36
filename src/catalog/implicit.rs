//! Implicit Runge-Kutta methods (collocation and related).
//!
//! Coefficients are transcribed from the project's `data/butcher.toml` by
//! `tools/gen_butcher_catalog.py` and checked at compile time by the `tableau!` macro.

crate::tableau! {
    /// Backward Euler (implicit Euler, Radau IIA(1)) — the first-order implicit one-stage method.
    ///
    /// ```text
    ///  1 | 1
    /// ---+---
    ///    | 1
    /// ```
    ///
    /// Order 1, 1 stage; implicit.
    /// Reference: implicit Euler (Radau IIA, s=1).
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (ImplicitEuler)` at b211787.
    pub struct BackwardEuler {
        name: "backward_euler",
        order: 1,
        c: [1],
        a: [
            [1],
        ],
        b: [1],
    }
}

crate::tableau! {
    /// Implicit midpoint rule (GL2, Gauss-Legendre 1-stage) — the one-stage Gauss-Legendre method.
    ///
    /// ```text
    ///  1/2 | 1/2
    /// -----+-----
    ///      |  1
    /// ```
    ///
    /// Order 2, 1 stage; implicit; symplectic; symmetric.
    /// Reference: implicit midpoint rule = Gauss-Legendre s=1.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (MidpointRule; GL2 identical)` at
    /// b211787.
    pub struct ImplicitMidpoint {
        name: "implicit_midpoint",
        order: 2,
        c: [1/2],
        a: [
            [1/2],
        ],
        b: [1],
    }
}

crate::tableau! {
    /// Trapezoidal rule (Crank-Nicolson, Lobatto IIIA(2)) — two-stage Lobatto IIIA method, embedded
    /// Euler step.
    ///
    /// ```text
    ///    0   |  0    0
    ///    1   | 1/2  1/2
    /// -------+----------
    ///    b   | 1/2  1/2
    ///  b_hat |  1    0
    /// ```
    ///
    /// Order 2 (embedded 1), 2 stages; implicit; symmetric.
    /// Reference: trapezoidal rule / Crank-Nicolson = Lobatto IIIA s=2.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (TrapezoidalRule)` at b211787.
    pub struct Trapezoidal {
        name: "trapezoidal",
        order: 2,
        c: [0, 1],
        a: [
            [0, 0],
            [1/2, 1/2],
        ],
        b: [1/2, 1/2],
        b_hat: [1, 0],
        embedded_order: 1,
    }
}

crate::tableau! {
    /// Gauss-Legendre, 2 stages (GL4, Gauss 2-stage) — fourth-order collocation method.
    ///
    /// ```text
    ///  0.211324865405 |       1/4         -0.0386751345948
    ///  0.788675134595 |  0.538675134595         1/4
    /// ----------------+------------------------------------
    ///                 |       1/2               1/2
    /// ```
    ///
    /// (coefficients abbreviated here; the declaration below is exact)
    ///
    /// Order 4, 2 stages; implicit; symplectic; symmetric.
    /// Reference: Gauss-Legendre collocation s=2 (Hammer & Hollingsworth 1955).
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (GL4)` at b211787.
    ///
    /// Closed form:
    ///
    /// ```text
    /// c = [(3-sqrt(3))/6, (3+sqrt(3))/6]
    /// A = [[1/4, (3-2*sqrt(3))/12], [(3+2*sqrt(3))/12, 1/4]]
    /// b = [1/2, 1/2]
    /// ```
    pub struct GaussLegendre4 {
        name: "gauss_legendre4",
        order: 4,
        c: [0.2113248654051871177454256097490212721762, 0.7886751345948128822545743902509787278238],
        a: [
            [1/4, -0.0386751345948128822545743902509787278238],
            [0.5386751345948128822545743902509787278238, 1/4],
        ],
        b: [1/2, 1/2],
    }
}

crate::tableau! {
    /// Gauss-Legendre, 3 stages (GL6, Gauss 3-stage) — sixth-order collocation method.
    ///
    /// ```text
    ///  0.112701665379 |       5/36        -0.0359766675249  0.00978944401531
    ///       1/2       |  0.300263194981         2/9         -0.0224854172031
    ///  0.887298334621 |  0.267988333762    0.480421111969         5/36
    /// ----------------+------------------------------------------------------
    ///                 |       5/18              4/9               5/18
    /// ```
    ///
    /// (coefficients abbreviated here; the declaration below is exact)
    ///
    /// Order 6, 3 stages; implicit; symplectic; symmetric.
    /// Reference: Gauss-Legendre collocation s=3 (Kuntzmann 1961, Butcher 1964).
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (GL6)` at b211787.
    ///
    /// Closed form:
    ///
    /// ```text
    /// c = [(5-sqrt(15))/10, 1/2, (5+sqrt(15))/10]
    /// A = [[5/36, (10-3*sqrt(15))/45, (25-6*sqrt(15))/180], [(10+3*sqrt(15))/72, 2/9,
    ///     (10-3*sqrt(15))/72], [(25+6*sqrt(15))/180, (10+3*sqrt(15))/45, 5/36]]
    /// b = [5/18, 4/9, 5/18]
    /// ```
    pub struct GaussLegendre6 {
        name: "gauss_legendre6",
        order: 6,
        c: [
            0.1127016653792583114820734600217600389167, 1/2,
            0.8872983346207416885179265399782399610833,
        ],
        a: [
            [
                5/36, -0.03597666752493890345639547109660441849997,
                0.009789444015308326049580042229475568527791,
            ],
            [
                0.3002631949808645924380249472131555393403, 2/9,
                -0.02248541720308681466024716943537776156248,
            ],
            [
                0.26798833376246945172819773554830220925,
                0.4804211119693833479008399155410488629444, 5/36,
            ],
        ],
        b: [5/18, 4/9, 5/18],
    }
}

crate::tableau! {
    /// Radau IIA, 2 stages (RadauIIA3) — third-order stiffly accurate collocation method.
    ///
    /// ```text
    ///  1/3 |  5/12  -1/12
    ///   1  |  3/4    1/4
    /// -----+--------------
    ///      |  3/4    1/4
    /// ```
    ///
    /// Order 3, 2 stages; implicit.
    /// Reference: Radau IIA s=2 (Ehle 1969).
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (RadauIIA3)` at b211787.
    pub struct RadauIia3 {
        name: "radau_iia3",
        order: 3,
        c: [1/3, 1],
        a: [
            [5/12, -1/12],
            [3/4, 1/4],
        ],
        b: [3/4, 1/4],
    }
}

crate::tableau! {
    /// Radau IIA, 3 stages (RadauIIA5, RADAU5) — fifth-order stiffly accurate collocation method.
    ///
    /// ```text
    ///  0.155051025722 |  0.196815477224   -0.0655354258502  0.0237709743482
    ///  0.644948974278 |  0.394424314739    0.292073411665   -0.041548752126
    ///        1        |   0.3764030627     0.512485826188         1/9
    /// ----------------+------------------------------------------------------
    ///                 |   0.3764030627     0.512485826188         1/9
    /// ```
    ///
    /// (coefficients abbreviated here; the declaration below is exact)
    ///
    /// Order 5, 3 stages; implicit.
    /// Reference: Radau IIA s=3 (Ehle 1969; Hairer-Wanner RADAU5).
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (RadauIIA5)` at b211787.
    ///
    /// Note: Production RADAU5 codes use the transformed (eigen-decomposed) form; OrdinaryDiffEq
    /// lib/OrdinaryDiffEqFIRK/src/firk_tableaus.jl holds those T/TI matrices.
    ///
    /// Closed form:
    ///
    /// ```text
    /// s6 = sqrt(6)
    /// c = [2/5 - s6/10, 2/5 + s6/10, 1]
    /// A = [[11/45 - 7*s6/360, 37/225 - 169*s6/1800, -2/225 + s6/75], [37/225 + 169*s6/1800, 11/45
    ///     + 7*s6/360, -2/225 - s6/75], [4/9 - s6/36, 4/9 + s6/36, 1/9]]
    /// b = last row of A
    /// ```
    pub struct RadauIia5 {
        name: "radau_iia5",
        order: 5,
        c: [
            0.1550510257216821901802715925294108608034, 0.6449489742783178098197284074705891391966,
            1,
        ],
        a: [
            [
                0.1968154772236604258683861429918298896007,
                -0.06553542585019838810852278256960869180125,
                0.02377097434822015242040823210718966300399,
            ],
            [
                0.3944243147390872769974116714584975806901,
                0.2920734116652284630205027458970589992882,
                -0.04154875212599793019818600988496744078177,
            ],
            [
                0.3764030627004672750500754423692807946676,
                0.5124858261884216138388134465196080942213, 1/9,
            ],
        ],
        b: [
            0.3764030627004672750500754423692807946676, 0.5124858261884216138388134465196080942213,
            1/9,
        ],
    }
}

crate::tableau! {
    /// Lobatto IIIA, 3 stages (LobattoIIIA4) — fourth-order collocation method.
    ///
    /// ```text
    ///    0   |   0      0      0
    ///   1/2  |  5/24   1/3   -1/24
    ///    1   |  1/6    2/3    1/6
    /// -------+---------------------
    ///    b   |  1/6    2/3    1/6
    ///  b_hat |  -1/2    2     -1/2
    /// ```
    ///
    /// Order 4 (embedded 2), 3 stages; implicit; symmetric.
    /// Reference: Lobatto IIIA s=3.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (LobattoIIIA4)` at b211787.
    ///
    /// Note: Pairs with lobatto_iiib4 as the partitioned Lobatto IIIA-IIIB method (order 4,
    /// symplectic for separable H; s=2 pair = Stormer-Verlet). b_hat as in source (αEEst).
    pub struct LobattoIiia4 {
        name: "lobatto_iiia4",
        order: 4,
        c: [0, 1/2, 1],
        a: [
            [0, 0, 0],
            [5/24, 1/3, -1/24],
            [1/6, 2/3, 1/6],
        ],
        b: [1/6, 2/3, 1/6],
        b_hat: [-1/2, 2, -1/2],
        embedded_order: 2,
    }
}

crate::tableau! {
    /// Lobatto IIIB, 3 stages (LobattoIIIB4) — fourth-order partner of Lobatto IIIA.
    ///
    /// ```text
    ///   0  | 1/6   -1/6   0
    ///  1/2 | 1/6   1/3    0
    ///   1  | 1/6   5/6    0
    /// -----+------------------
    ///      | 1/6   2/3   1/6
    /// ```
    ///
    /// Order 4, 3 stages; implicit; symmetric.
    /// Reference: Lobatto IIIB s=3.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (LobattoIIIB4)` at b211787.
    ///
    /// Note: Embedded pair dropped: the source's b_hat = \[-1/2, 2, -1/2\] (order 2) gives b -
    /// b_hat = 2/3 (1, -2, 1), and the rows of A satisfy a_1 - 2 a_2 + a_3 = 0, so the error
    /// estimate h sum (b_i - b_hat_i) k_i is exactly zero on every linear problem (y' = lambda y,
    /// the harmonic oscillator) and adaptive steps would grow without limit. Fixed steps only.
    pub struct LobattoIiib4 {
        name: "lobatto_iiib4",
        order: 4,
        c: [0, 1/2, 1],
        a: [
            [1/6, -1/6, 0],
            [1/6, 1/3, 0],
            [1/6, 5/6, 0],
        ],
        b: [1/6, 2/3, 1/6],
    }
}

crate::tableau! {
    /// Lobatto IIIC, 3 stages (LobattoIIIC4) — fourth-order L-stable method.
    ///
    /// ```text
    ///    0   |  1/6    -1/3   1/6
    ///   1/2  |  1/6    5/12  -1/12
    ///    1   |  1/6    2/3    1/6
    /// -------+---------------------
    ///    b   |  1/6    2/3    1/6
    ///  b_hat |  -1/2    2     -1/2
    /// ```
    ///
    /// Order 4 (embedded 2), 3 stages; implicit.
    /// Reference: Lobatto IIIC s=3 (Chipman 1971), L-stable.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqImplicitTableaus/src/ode_tableaus.jl (LobattoIIIC4)` at b211787.
    pub struct LobattoIiic4 {
        name: "lobatto_iiic4",
        order: 4,
        c: [0, 1/2, 1],
        a: [
            [1/6, -1/3, 1/6],
            [1/6, 5/12, -1/12],
            [1/6, 2/3, 1/6],
        ],
        b: [1/6, 2/3, 1/6],
        b_hat: [-1/2, 2, -1/2],
        embedded_order: 2,
    }
}
