//! Explicit Runge-Kutta methods without an embedded error estimator.
//!
//! Coefficients are transcribed from the project's `data/butcher.toml` by
//! `tools/gen_butcher_catalog.py` and checked at compile time by the `tableau!` macro.

crate::tableau! {
    /// Forward Euler (forward Euler, explicit Euler) — the first-order explicit one-step method.
    ///
    /// ```text
    ///  0 |
    /// ---+---
    ///    | 1
    /// ```
    ///
    /// Order 1, 1 stage; explicit.
    /// Reference: Euler (1768).
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqExplicitTableaus/src/tableaus_low_order.jl (Euler)` at b211787.
    pub struct Euler {
        name: "euler",
        order: 1,
        c: [0],
        a: [
            [0],
        ],
        b: [1],
    }
}

crate::tableau! {
    /// Ralston's second-order method (Ralston) — two-stage method with minimal error bound.
    ///
    /// ```text
    ///   0  |
    ///  2/3 | 2/3
    /// -----+----------
    ///      | 1/4  3/4
    /// ```
    ///
    /// Order 2, 2 stages; explicit.
    /// Reference: Ralston (1962), minimum error bound 2nd order.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqExplicitTableaus/src/tableaus_low_order.jl (Ralston)` at b211787.
    pub struct Ralston2 {
        name: "ralston2",
        order: 2,
        c: [0, 2/3],
        a: [
            [0, 0],
            [2/3, 0],
        ],
        b: [1/4, 3/4],
    }
}

crate::tableau! {
    /// Kutta's third-order method (RK3, Kutta's third-order) — the classic three-stage third-order
    /// method.
    ///
    /// ```text
    ///   0  |
    ///  1/2 | 1/2
    ///   1  |  -1   2
    /// -----+---------------
    ///      | 1/6  2/3  1/6
    /// ```
    ///
    /// Order 3, 3 stages; explicit.
    /// Reference: Kutta (1901) 3rd order.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqExplicitTableaus/src/tableaus_low_order.jl (Kutta3)` at b211787.
    pub struct Kutta3 {
        name: "kutta3",
        order: 3,
        c: [0, 1/2, 1],
        a: [
            [0, 0, 0],
            [1/2, 0, 0],
            [-1, 2, 0],
        ],
        b: [1/6, 2/3, 1/6],
    }
}

crate::tableau! {
    /// SSPRK(3,3) (SSPRK3, Shu-Osher RK3, TVD-RK3) — three-stage third-order
    /// strong-stability-preserving method.
    ///
    /// ```text
    ///   0  |
    ///   1  |  1
    ///  1/2 | 1/4  1/4
    /// -----+---------------
    ///      | 1/6  1/6  2/3
    /// ```
    ///
    /// Order 3, 3 stages; explicit.
    /// Reference: Shu & Osher (1988) SSP(3,3).
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqExplicitTableaus/src/tableaus_low_order.jl (SSPRK33)` at b211787.
    ///
    /// Note: SSP coefficient 1.
    pub struct Ssprk33 {
        name: "ssprk33",
        order: 3,
        c: [0, 1, 1/2],
        a: [
            [0, 0, 0],
            [1, 0, 0],
            [1/4, 1/4, 0],
        ],
        b: [1/6, 1/6, 2/3],
    }
}

crate::tableau! {
    /// SSPRK(4,3) (SSPRK43) — four-stage third-order strong-stability-preserving method.
    ///
    /// ```text
    ///   0  |
    ///  1/2 | 1/2
    ///   1  | 1/2  1/2
    ///  1/2 | 1/6  1/6  1/6
    /// -----+--------------------
    ///      | 1/6  1/6  1/6  1/2
    /// ```
    ///
    /// Order 3, 4 stages; explicit.
    /// Reference: Kraaijevanger (1991) / Spiteri & Ruuth (2002) SSP(4,3).
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqExplicitTableaus/src/tableaus_low_order.jl (SSPRK43)` at b211787.
    ///
    /// Note: SSP coefficient 2 (effective 1/2).
    pub struct Ssprk43 {
        name: "ssprk43",
        order: 3,
        c: [0, 1/2, 1, 1/2],
        a: [
            [0, 0, 0, 0],
            [1/2, 0, 0, 0],
            [1/2, 1/2, 0, 0],
            [1/6, 1/6, 1/6, 0],
        ],
        b: [1/6, 1/6, 1/6, 1/2],
    }
}

crate::tableau! {
    /// Classic Runge-Kutta (classic RK4, RK4) — the four-stage fourth-order method of Kutta.
    ///
    /// ```text
    ///   0  |
    ///  1/2 | 1/2
    ///  1/2 |  0   1/2
    ///   1  |  0    0    1
    /// -----+--------------------
    ///      | 1/6  1/3  1/3  1/6
    /// ```
    ///
    /// Order 4, 4 stages; explicit.
    /// Reference: Kutta (1901) classic RK4.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqExplicitTableaus/src/tableaus_low_order.jl (RK4)` at b211787.
    pub struct Rk4 {
        name: "rk4",
        order: 4,
        c: [0, 1/2, 1/2, 1],
        a: [
            [0, 0, 0, 0],
            [1/2, 0, 0, 0],
            [0, 1/2, 0, 0],
            [0, 0, 1, 0],
        ],
        b: [1/6, 1/3, 1/3, 1/6],
    }
}

crate::tableau! {
    /// Kutta's 3/8 rule (3/8 rule, RK438) — four-stage fourth-order variant of the classic method.
    ///
    /// ```text
    ///   0  |
    ///  1/3 | 1/3
    ///  2/3 | -1/3   1
    ///   1  |  1     -1    1
    /// -----+------------------------
    ///      | 1/8   3/8   3/8   1/8
    /// ```
    ///
    /// Order 4, 4 stages; explicit.
    /// Reference: Kutta (1901) 3/8-rule.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqExplicitTableaus/src/tableaus_low_order.jl (RK438Rule)` at b211787.
    pub struct Rk4ThreeEighths {
        name: "rk4_38",
        order: 4,
        c: [0, 1/3, 2/3, 1],
        a: [
            [0, 0, 0, 0],
            [1/3, 0, 0, 0],
            [-1/3, 1, 0, 0],
            [1, -1, 1, 0],
        ],
        b: [1/8, 3/8, 3/8, 1/8],
    }
}

crate::tableau! {
    /// Ralston's fourth-order method (Ralston4) — four-stage method, minimal truncation error.
    ///
    /// ```text
    ///        0        |
    ///       2/5       |       2/5
    ///  0.455737254219 |  0.296977609248   0.158759644971
    ///        1        |  0.218100388226   -3.05096514869   3.83286476047
    /// ----------------+--------------------------------------------------------------------
    ///                 |  0.174760282263  -0.551480662879    1.2055355994    0.17118478122
    /// ```
    ///
    /// (coefficients abbreviated here; the declaration below is exact)
    ///
    /// Order 4, 4 stages; explicit.
    /// Reference: Ralston (1962) 4th order minimum truncation error.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqExplicitTableaus/src/tableaus_low_order.jl (Ralston4)` at b211787.
    ///
    /// Closed form:
    ///
    /// ```text
    /// sqrt5 = sqrt(5)
    /// c = [0, 2/5, (14-3*sqrt5)/16, 1]
    /// a21 = 2/5
    /// a31 = (-2889+1428*sqrt5)/1024
    /// a32 = (3785-1620*sqrt5)/1024
    /// a41 = (-3365+2094*sqrt5)/6040
    /// a42 = (-975-3046*sqrt5)/2552
    /// a43 = (467040+203968*sqrt5)/240845
    /// b = [(263+24*sqrt5)/1812, (125-1000*sqrt5)/3828, 1024*(3346+1623*sqrt5)/5924787,
    ///     (30-4*sqrt5)/123]
    /// ```
    pub struct Ralston4 {
        name: "ralston4",
        order: 4,
        c: [0, 2/5, 0.4557372542187894319232799371128857058549, 1],
        a: [
            [0, 0, 0, 0],
            [2/5, 0, 0, 0],
            [
                0.2969776092477536000706054677229125627043,
                0.1587596449710358318526744693899731431506, 0, 0,
            ],
            [
                0.2181003882259204675961605401197504034789,
                -3.05096514869293080535358267827408597694,
                3.832864760467010337757422138154335573462, 0,
            ],
        ],
        b: [
            0.1747602822626903712548676424114517823679, -0.5514806628787329405457611464815246174087,
            1.205535599396523535027777200614179379283, 0.171184781219519034263116303455893455758,
        ],
    }
}
