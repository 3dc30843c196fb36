//! Splitting methods (drift/kick sequences), drift-first as in the catalog.
//!
//! Coefficients are transcribed from the project's `data/splitting.toml` by
//! `tools/gen_splitting_catalog.py` and checked at compile time by the `splitting!` macro.

crate::splitting! {
    /// symplectic Euler, position-first variant (adjoint of the kick-first one) (symplectic Euler
    /// (boost/OrdinaryDiffEq), symplectic Euler B (HLW naming varies)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(1) K(1)
    /// ```
    ///
    /// General splitting, order 1, 1 force evaluation per step; not symmetric.
    ///
    /// Coefficients from boostorg/odeint `include/boost/numeric/odeint/stepper/symplectic_euler.hpp
    /// (coef_a = coef_b = 1 with the base stepper: drift then kick); OrdinaryDiffEq SymplecticEuler
    /// (lib/OrdinaryDiffEqSymplecticRK/src/symplectic_perform_step.jl) is the same sequence` at
    /// efa150f.
    /// Precision: exact rationals.
    ///
    /// Note: q\_{n+1} = q_n + h T_p(p_n); p\_{n+1} = p_n - h V_q(q\_{n+1}). Explicit for separable
    /// H.
    pub struct SymplecticEulerDk {
        name: "symplectic_euler_dk",
        order: 1,
        drift: [1],
        kick: [1],
    }
}

crate::splitting! {
    /// symplectic Euler, momentum-first variant (Hairer-Lubich-Wanner eq. I.1.9 / VI.3.1 form for
    /// separable H) (symplectic Euler (SUNDIALS ARKODE_SPRK_EULER_1_1), semi-implicit Euler).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(1) D(1)
    /// ```
    ///
    /// General splitting, order 1, 1 force evaluation per step; not symmetric.
    ///
    /// Coefficients from LLNL/sundials `src/arkode/arkode_sprk.c (arkodeSymplecticEuler: a = ahat =
    /// 1, SPRKStep applies the kick first)` at c8dabce.
    /// Precision: exact rationals.
    ///
    /// Note: p\_{n+1} = p_n - h V_q(q_n); q\_{n+1} = q_n + h T_p(p\_{n+1}). The two variants are
    /// adjoints; composing one with the other (half steps) gives Stormer-Verlet.
    pub struct SymplecticEulerKd {
        name: "symplectic_euler_kd",
        order: 1,
        drift: [0, 1],
        kick: [1, 0],
    }
}

crate::splitting! {
    /// Stormer-Verlet / leapfrog, drift-kick-drift (position Verlet) (leapfrog DKD, position
    /// Verlet, PseudoVerletLeapfrog, Strang splitting (A half, B full), SABA1,
    /// LeapfrogDriftKickDrift).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(1/2) K(1) D(1/2)
    /// ```
    ///
    /// General splitting, order 2, 1 force evaluation per step; symmetric.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqSymplecticRK/src/symplectic_tableaus.jl (PseudoVerletLeapfrog: a=(1,0),
    /// b=(1/2,1/2)); also lib/OrdinaryDiffEqSymplecticRK/src/symplectic_perform_step.jl
    /// LeapfrogDriftKickDrift` at b211787.
    /// Precision: exact rationals.
    ///
    /// Note: One force evaluation per step. Consecutive end/start half drifts can be merged when no
    /// output is needed.
    pub struct StormerVerletDkd {
        name: "stormer_verlet_dkd",
        order: 2,
        drift: [1/2, 1/2],
        kick: [1, 0],
    }
}

crate::splitting! {
    /// velocity Verlet / leapfrog kick-drift-kick (leapfrog KDK, velocity Verlet, VerletLeapfrog,
    /// SBAB1, ARKODE_SPRK_LEAPFROG_2_2).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(1/2) D(1) K(1/2)
    /// ```
    ///
    /// General splitting, order 2, 1 force evaluation per step (FSAL); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp
    /// (NewtonDelambreStørmerVerletLeapfrog: a=(1,0), b=(1/2,1/2), kick first)` at 9ffb8b0.
    /// Precision: exact rationals.
    ///
    /// Note: FSAL: the closing half kick uses the force at q\_{n+1}, reused by the next step -> 1
    /// force evaluation per step.
    pub struct VelocityVerletKdk {
        name: "velocity_verlet_kdk",
        order: 2,
        drift: [0, 1],
        kick: [1/2, 1/2],
    }
}

crate::splitting! {
    /// McLachlan & Atela (1992) Nonlinearity 5:541, optimal 2-stage 2nd order (Table 2) (McAte2,
    /// ARKODE_SPRK_MCLACHLAN_2_2).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.292893218813) D(0.707106781187) K(0.707106781187) D(0.292893218813)
    /// ```
    ///
    /// General splitting, order 2, 2 force evaluations per step; not symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp
    /// (McLachlanAtela1992Order2Optimal); SUNDIALS arkodeSymplecticMcLachlan2 identical;
    /// OrdinaryDiffEq McAte2 has drift/kick roles swapped (valid: general method)` at 9ffb8b0.
    /// Precision: decimal in source, up to 19 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Closed form:
    ///
    /// ```text
    /// kick = [1 - 1/sqrt(2), 1/sqrt(2)], drift = [1/sqrt(2), 1 - 1/sqrt(2)] (kick first): a2 = 1 -
    ///     sqrt(2)/2, a1 = 1 - a2, b2 = 1/(2(1-a2)), b1 = 1 - b2 in SUNDIALS notation
    /// ```
    pub struct MclachlanAtela2 {
        name: "mclachlan_atela2",
        order: 2,
        drift: [0, 0.7071067811865475244, 0.2928932188134524756],
        kick: [0.2928932188134524756, 0.7071067811865475244, 0],
    }
}

crate::splitting! {
    /// McLachlan (1995) SIAM J. Sci. Comput. 16:151, symmetric 2-evaluation 2nd order (S2), minimal
    /// error (McLachlan S2, BAB2 optimal (b = 0.1932)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.193183327504) D(1/2) K(0.613633344992) D(1/2) K(0.193183327504)
    /// ```
    ///
    /// General splitting, order 2, 2 force evaluations per step (FSAL); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (McLachlan1995S2)` at
    /// 9ffb8b0.
    /// Precision: decimal in source, up to 20 significant digits (derived entries printed with 5
    /// guard digits).
    pub struct MclachlanS2 {
        name: "mclachlan_s2",
        order: 2,
        drift: [0, 1/2, 1/2],
        kick: [0.19318332750378357396, 0.61363334499243285207, 0.19318332750378357396],
    }
}

crate::splitting! {
    /// Ruth (1983) IEEE Trans. Nucl. Sci. 30:2669, 3rd order (Ruth3, ARKODE_SPRK_RUTH_3_3).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(7/24) K(2/3) D(3/4) K(-2/3) D(-1/24) K(1)
    /// ```
    ///
    /// General splitting, order 3, 3 force evaluations per step; not symmetric.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqSymplecticRK/src/symplectic_tableaus.jl (Ruth3: a = (2/3,-2/3,1), b =
    /// (7/24,3/4,-1/24)); Principia Ruth1983 and SUNDIALS arkodeSymplecticRuth3 have the same
    /// numbers but kick-first (roles swapped; both valid, general method)` at b211787.
    /// Precision: exact rationals.
    pub struct Ruth3 {
        name: "ruth3",
        order: 3,
        drift: [7/24, 3/4, -1/24],
        kick: [2/3, -2/3, 1],
    }
}

crate::splitting! {
    /// McLachlan & Atela (1992), optimal 3-stage 3rd order (McAte3, ARKODE_SPRK_MCLACHLAN_3_3).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.268330095782) D(0.919661523017) K(-0.187991618799) D(-0.187991618799) K(0.919661523017)
    /// D(0.268330095782)
    /// ```
    ///
    /// General splitting, order 3, 3 force evaluations per step; not symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp
    /// (McLachlanAtela1992Order3Optimal); SUNDIALS arkodeSymplecticMcLachlan3 computes the same
    /// values in closed form; OrdinaryDiffEq McAte3 swaps roles and uses a 16-digit a1` at 9ffb8b0.
    /// Precision: decimal in source, up to 19 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Closed form:
    ///
    /// ```text
    /// z = -cbrt(2/27 - 1/(9*sqrt(3)))
    /// w = -2/3 + 1/(9*z) + z
    /// y = (1 + w^2)/4
    /// a1 = sqrt(1/(9*y) - w/2 + sqrt(y)) - 1/(3*sqrt(y))
    /// a2 = 1/(4*a1) - a1/2
    /// a3 = 1 - a1 - a2
    /// drift = (a1,a2,a3), kick = (a3,a2,a1), kick first (SUNDIALS arkodeSymplecticMcLachlan3)
    /// ```
    pub struct MclachlanAtela3 {
        name: "mclachlan_atela3",
        order: 3,
        drift: [0, 0.9196615230173998571, -0.1879916187991597820, 0.2683300957817599250],
        kick: [0.2683300957817599250, -0.1879916187991597820, 0.9196615230173998571, 0],
    }
}

crate::splitting! {
    /// Forest & Ruth (1990) Physica D 43:105, eq. 4.8; Candy & Rozmus (1991) J. Comput. Phys.
    /// 92:230; = Yoshida (1990) triple jump of the DKD leapfrog (Forest-Ruth, Candy-Rozmus,
    /// CandyRoz4, FR4, ARKODE_SPRK_CANDY_ROZMUS_4_4, Yoshida 4th order (splitting form)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.67560359598) K(1.35120719196) D(-0.17560359598) K(-1.70241438392) D(-0.17560359598)
    /// K(1.35120719196) D(0.67560359598)
    /// ```
    ///
    /// General splitting, order 4, 3 force evaluations per step; symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp
    /// (CandyRozmus1991ForestRuth1990, kick-first form); OrdinaryDiffEq CandyRoz4 and SUNDIALS
    /// arkodeSymplecticCandyRozmus4 give the closed forms` at 9ffb8b0.
    /// Precision: exact closed form; irrational entries as 40-digit decimals.
    ///
    /// Note: Given here in position (DKD) form; Principia lists the velocity (KDK) form (swap D and
    /// K) - both are 4th order for any splitting.
    ///
    /// Closed form:
    ///
    /// ```text
    /// theta = 1/(2 - 2^(1/3))
    /// drift = [theta/2, (1-theta)/2, (1-theta)/2, theta/2]
    /// kick = [theta, 1-2*theta, theta, 0]
    /// ```
    pub struct ForestRuth4 {
        name: "forest_ruth4",
        order: 4,
        drift: [
            0.675603595979828817023843904485730413461, -0.175603595979828817023843904485730413461,
            -0.175603595979828817023843904485730413461, 0.675603595979828817023843904485730413461,
        ],
        kick: [
            1.351207191959657634047687808971460826922, -1.702414383919315268095375617942921653844,
            1.351207191959657634047687808971460826922, 0,
        ],
    }
}

crate::splitting! {
    /// Omelyan, Mryglod & Folk (2002) Comput. Phys. Commun. 146:188, position-extended
    /// Forest-Ruth-like (PEFRL), eq. (20) (PEFRL, Omelyan 4th order position-extended).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.178617895845) K(0.712341831063) D(-0.0662645826698) K(-0.212341831063) D(0.77529337365)
    /// K(-0.212341831063) D(-0.0662645826698) K(0.712341831063) D(0.178617895845)
    /// ```
    ///
    /// General splitting, order 4, 4 force evaluations per step; symmetric.
    ///
    /// Coefficients from TJUJackeyLove/PEFRL-SEM `setup/PEFRLconstants.h (xi, lambda, chi; ALPHA =
    /// drift (xi, chi, 1-2(chi+xi), chi), BETA = kick (1/2-lambda, lambda, lambda, 1/2-lambda))`.
    /// Precision: decimal in source, up to 16 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Only 16 significant digits are published/common; 4 force evaluations per step.
    pub struct Pefrl {
        name: "pefrl",
        order: 4,
        drift: [
            0.1786178958448091, -0.06626458266981849, 0.77529337365001878, -0.06626458266981849,
            0.1786178958448091,
        ],
        kick: [0.7123418310626054, -0.2123418310626054, -0.2123418310626054, 0.7123418310626054, 0],
    }
}

crate::splitting! {
    /// McLachlan & Atela (1992), optimal 4-stage 4th order for T quadratic in p (RKN) (McAte4,
    /// ARKODE_SPRK_MCLACHLAN_4_4).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.134496199277) D(0.515352837431) K(-0.224819803079) D(-0.085782019413) K(0.756320000516)
    /// D(0.441583023616) K(0.334003603286) D(0.128846158365)
    /// ```
    ///
    /// Built for quadratic kinetic energy (Runge-Kutta-Nystrom problems), order 4 (measured 3 for a
    /// general kinetic energy, 4 for a quadratic one), 4 force evaluations per step; not symmetric.
    /// Accepts only problems with a quadratic kinetic energy (`QuadraticKinetic`).
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp
    /// (McLachlanAtela1992Order4Optimal, composition BA); SUNDIALS arkodeSymplecticMcLachlan4 (18
    /// digits) identical` at 9ffb8b0.
    /// Precision: decimal in source, up to 19 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Requires quadratic kinetic energy. WARNING: OrdinaryDiffEq McAte4 stores the same
    /// numbers with the drift/kick roles swapped (drift 0.1345 first, kick 0.5154); measured with
    /// the same test (T = |p|^2/2, nonlinear V) that variant gives local slopes -> 4.0, i.e. global
    /// order 3 (its own convergence test uses the linear harmonic oscillator, which cannot see
    /// this).
    pub struct MclachlanAtela4 {
        name: "mclachlan_atela4",
        order: 4,
        drift: [
            0, 0.5153528374311229364, -0.085782019412973646, 0.4415830236164665242,
            0.1288461583653841854,
        ],
        kick: [
            0.1344961992774310892, -0.2248198030794208058, 0.7563200005156682911,
            0.3340036032863214255, 0,
        ],
        quadratic_kinetic: true,
    }
}

crate::splitting! {
    /// McLachlan & Atela (1992), optimal 6-stage 5th order for T quadratic in p (RKN) (McAte5,
    /// ARKODE_SPRK_MCLACHLAN_5_6).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.119390029288) D(0.339839625839) K(0.698927370382) D(-0.088601336903) K(-0.171312358272)
    /// D(0.585856476826) K(0.401269502251) D(-0.603039356536) K(0.0107050818482) D(0.323580796555)
    /// K(-0.058979625498) D(0.44236379422)
    /// ```
    ///
    /// Built for quadratic kinetic energy (Runge-Kutta-Nystrom problems), order 5 (measured 3 for a
    /// general kinetic energy, 5 for a quadratic one), 6 force evaluations per step; not symmetric.
    /// Accepts only problems with a quadratic kinetic energy (`QuadraticKinetic`).
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp
    /// (McLachlanAtela1992Order5Optimal, composition BA); SUNDIALS arkodeSymplecticMcLachlan5
    /// identical` at 9ffb8b0.
    /// Precision: decimal in source, up to 19 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Requires quadratic kinetic energy. OrdinaryDiffEq McAte5 applies these numbers with
    /// drift/kick roles swapped; measured: global order 3 on the nonlinear RKN test (cf. open issue
    /// SciML/OrdinaryDiffEq.jl#2066 McAte5 wrong results).
    pub struct MclachlanAtela5 {
        name: "mclachlan_atela5",
        order: 5,
        drift: [
            0, 0.339839625839110000, -0.088601336903027329, 0.5858564768259621188,
            -0.603039356536491888, 0.3235807965546976394, 0.4423637942197494587,
        ],
        kick: [
            0.1193900292875672758, 0.6989273703824752308, -0.1713123582716007754,
            0.4012695022513534480, 0.0107050818482359840, -0.0589796254980311632, 0,
        ],
        quadratic_kinetic: true,
    }
}

crate::splitting! {
    /// Calvo & Sanz-Serna (1993) SIAM J. Sci. Comput. 14:936, 5-stage 4th-order SRKN (b_i weights,
    /// gamma_i nodes) (CalvoSanz4).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.0617588581356) D(0.205177661542) K(0.338978026554) D(0.403021281604) K(0.614791307176)
    /// D(-0.120920876339) K(-0.140548014659) D(0.512721933192) K(0.125019822795)
    /// ```
    ///
    /// Built for quadratic kinetic energy (Runge-Kutta-Nystrom problems), order 4 (measured 3 for a
    /// general kinetic energy, 4 for a quadratic one), 4 force evaluations per step (FSAL); not
    /// symmetric. Accepts only problems with a quadratic kinetic energy (`QuadraticKinetic`).
    ///
    /// Coefficients from MooVI/Numerical-Methods `RKNMethods.h (class Calvo4: b1..b5 and nodes
    /// g2..g5; drift a_i = g_{i+1} - g_i; kick first)` at eed8dc6.
    /// Precision: decimal in source, up to 19 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: OrdinaryDiffEq CalvoSanz4 (14-digit values a = (0.20517766154229, 0.40302128160421, -0.12092087633891, 0.51272193319241, 0),
    /// b = (0.061758858135626, ...)) applies b as drift and a as kick, i.e. roles swapped relative
    /// to this RKN method; measured: that variant is only order 3 on the nonlinear RKN test.
    pub struct CalvoSanzSerna4 {
        name: "calvo_sanz_serna4",
        order: 4,
        drift: [
            0, 0.2051776615422863869, 0.403021281604214587, -0.1209208763389140082,
            0.5127219331924130343,
        ],
        kick: [
            0.061758858135626325, 0.3389780265536433551, 0.614791307175577662,
            -0.1405480146593733802, 0.1250198227945261338,
        ],
        quadratic_kinetic: true,
    }
}

crate::splitting! {
    /// McLachlan (1995) S4: symmetric 4-evaluation 4th order (McLachlan S4, SPLIT_4TH_S_M4).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.169139279922) D(0.545454545455) K(-0.299186203904) D(-0.0454545454545) K(1.26009384796)
    /// D(-0.0454545454545) K(-0.299186203904) D(0.545454545455) K(0.169139279922)
    /// ```
    ///
    /// General splitting, order 4, 4 force evaluations per step (FSAL); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (McLachlan1995S4);
    /// closed forms in amusecode/amuse src/amuse_huayno/src/integrators_shared.h SPLIT_4TH_S_M4` at
    /// 9ffb8b0.
    /// Precision: decimal in source, up to 20 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Closed form:
    ///
    /// ```text
    /// kick b = [(642+sqrt(471))/3924, 121*(12-sqrt(471))/3924, 1-2*(b1+b2), b2, b1]
    /// drift a = [6/11, 1/2-6/11, 1/2-6/11, 6/11] (kick first)
    /// ```
    pub struct MclachlanS4 {
        name: "mclachlan_s4",
        order: 4,
        drift: [
            0, 0.54545454545454545455, -0.045454545454545454545, -0.045454545454545454545,
            0.54545454545454545455,
        ],
        kick: [
            0.16913927992207204518, -0.29918620390405079951, 1.2600938479639575087,
            -0.29918620390405079951, 0.16913927992207204518,
        ],
    }
}

crate::splitting! {
    /// McLachlan (1995) S5: symmetric 5-evaluation 4th order (McLachlan S5, SPLIT_4TH_S_M5).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.0892694542265) D(2/5) K(-0.0973360426369) D(-1/10) K(0.50806658841) D(2/5)
    /// K(0.50806658841) D(-1/10) K(-0.0973360426369) D(2/5) K(0.0892694542265)
    /// ```
    ///
    /// General splitting, order 4, 5 force evaluations per step (FSAL); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (McLachlan1995S5);
    /// closed forms in amusecode/amuse src/amuse_huayno/src/integrators_shared.h SPLIT_4TH_S_M5` at
    /// 9ffb8b0.
    /// Precision: decimal in source, up to 20 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Closed form:
    ///
    /// ```text
    /// kick b = [(14-sqrt(19))/108, (20-7*sqrt(19))/108, 1/2-(b1+b2), b3, b2, b1]
    /// drift a = [2/5, -1/10, 2/5, -1/10, 2/5] (kick first)
    /// ```
    pub struct MclachlanS5 {
        name: "mclachlan_s5",
        order: 4,
        drift: [0, 2/5, -1/10, 2/5, -1/10, 2/5],
        kick: [
            0.089269454226475244887, -0.097336042636895508015, 0.50806658841042026313,
            0.50806658841042026313, -0.097336042636895508015, 0.089269454226475244887,
        ],
    }
}

crate::splitting! {
    /// McLachlan (1995) SB3A, 4 evaluations (RKN, \[B,\[B,\[B,A\]\]\]=0)
    /// (symplectic_rkn_sb3a_m4_mclachlan, SB3A4).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.188195217769) K(1) D(-0.0215285511022) K(-1/2) D(0.666666666667) K(-1/2)
    /// D(-0.0215285511022) K(1) D(0.188195217769)
    /// ```
    ///
    /// Built for quadratic kinetic energy (Runge-Kutta-Nystrom problems), order 4, 4 force
    /// evaluations per step; symmetric.
    ///
    /// Coefficients from boostorg/odeint
    /// `include/boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp (a = drift, b =
    /// kick, drift first); Principia McLachlan1995SB3A4 identical` at efa150f.
    /// Precision: decimal in source, up to 20 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Closed form:
    ///
    /// ```text
    /// z = sqrt(7/8)/3
    /// drift = [1/2 - z, -1/3 + z, 2/3, -1/3 + z, 1/2 - z]
    /// kick = [1, -1/2, -1/2, 1, 0]
    /// ```
    pub struct MclachlanSb3a4 {
        name: "mclachlan_sb3a4",
        order: 4,
        drift: [
            0.18819521776883821787, -0.021528551102171551201, 0.66666666666666666667,
            -0.021528551102171551201, 0.18819521776883821787,
        ],
        kick: [1, -1/2, -1/2, 1, 0],
    }
}

crate::splitting! {
    /// McLachlan (1995) SB3A, 5 evaluations (RKN) (symplectic_rkn_sb3a_mclachlan, SB3A5, McAte42
    /// (OrdinaryDiffEq, BROKEN transcription)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.405188618395) K(-0.041095890411) D(-0.287144040817) K(0.28813559322) D(0.381955422421)
    /// K(0.505920594381) D(0.381955422421) K(0.28813559322) D(-0.287144040817) K(-0.041095890411)
    /// D(0.405188618395)
    /// ```
    ///
    /// Built for quadratic kinetic energy (Runge-Kutta-Nystrom problems), order 4, 5 force
    /// evaluations per step; symmetric.
    ///
    /// Coefficients from boostorg/odeint
    /// `include/boost/numeric/odeint/stepper/symplectic_rkn_sb3a_mclachlan.hpp (a = drift, b =
    /// kick, drift first); Principia McLachlan1995SB3A5 identical` at efa150f.
    /// Precision: decimal in source, up to 20 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: OrdinaryDiffEq McAte42 uses these numbers as a 5-entry a/b pair with a3 = 1-2a1-2a2
    /// and a non-zero final kick: that is not this method (issue SciML/OrdinaryDiffEq.jl#85, marked
    /// BROKEN).
    ///
    /// Closed form:
    ///
    /// ```text
    /// drift = [a1, a2, a3, a3, a2, a1] with a1 = 0.40518861839525227722, a2 =
    ///     -0.28714404081652408900, a3 = 1/2 - (a1+a2)
    /// kick = [-3/73, 17/59, 1 - 2*(-3/73 + 17/59), 17/59, -3/73, 0]
    /// ```
    pub struct MclachlanSb3a5 {
        name: "mclachlan_sb3a5",
        order: 4,
        drift: [
            0.4051886183952522772, -0.2871440408165240890, 0.3819554224212718118,
            0.3819554224212718118, -0.2871440408165240890, 0.4051886183952522772,
        ],
        kick: [
            -0.041095890410958904110, 0.28813559322033898305, 0.50592059438123984212,
            0.28813559322033898305, -0.041095890410958904110, 0,
        ],
    }
}

crate::splitting! {
    /// Blanes & Moan (2002) J. Comput. Appl. Math. 142:313, Table 2, S6 (general PRK, 6
    /// evaluations) (S6, BM4 general, SPLIT_4TH_S_M6, PRKS6).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.0792036964312) D(0.209515106613) K(0.35317290605) D(-0.14385177318) K(-0.0420650803577)
    /// D(0.434336666566) K(0.219376955753) D(0.434336666566) K(-0.0420650803577) D(-0.14385177318)
    /// K(0.35317290605) D(0.209515106613) K(0.0792036964312)
    /// ```
    ///
    /// General splitting, order 4, 6 force evaluations per step (FSAL); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (BlanesMoan2002S6)` at
    /// 9ffb8b0.
    /// Precision: decimal in source, up to 17 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Central coefficients recomputed from the consistency conditions as defined in the
    /// paper (Principia prints them rounded to \~17 digits). General method: A and B
    /// interchangeable. Principia (and Leimkuhler-Reich Table 6.1, AMUSE dkd4_S_m6) put 0.0792...
    /// on the kick; Blanes-Moan print a_i = 0.0792... on the first flow.
    pub struct BlanesMoanS6 {
        name: "blanes_moan_s6",
        order: 4,
        drift: [
            0, 0.20951510661336200, -0.14385177317981800, 0.434336666566456, 0.434336666566456,
            -0.14385177317981800, 0.20951510661336200,
        ],
        kick: [
            0.079203696431195700, 0.35317290604977400, -0.042065080357719500, 0.2193769557534996,
            -0.042065080357719500, 0.35317290604977400, 0.079203696431195700,
        ],
    }
}

crate::splitting! {
    /// Blanes & Moan (2002), Table 2, S10 (general PRK, 10 evaluations) (S10).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.0502627644004) D(0.148816447901) K(0.413514300428) D(-0.132385865768) K(0.0450798897944)
    /// D(0.0673076046922) K(-0.18805485382) D(0.432666402578) K(0.541960678451) D(-0.0164045894036)
    /// K(-0.725525558509) D(-0.0164045894036) K(0.541960678451) D(0.432666402578) K(-0.18805485382)
    /// D(0.0673076046922) K(0.0450798897944) D(-0.132385865768) K(0.413514300428) D(0.148816447901)
    /// K(0.0502627644004)
    /// ```
    ///
    /// General splitting, order 6, 10 force evaluations per step (FSAL); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (BlanesMoan2002S10)` at
    /// 9ffb8b0.
    /// Precision: decimal in source, up to 17 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Central coefficients recomputed from the consistency conditions as defined in the
    /// paper.
    pub struct BlanesMoanS10 {
        name: "blanes_moan_s10",
        order: 6,
        drift: [
            0, 0.14881644790104200, -0.13238586576778400, 0.067307604692185000, 0.43266640257817500,
            -0.016404589403618, -0.016404589403618, 0.43266640257817500, 0.067307604692185000,
            -0.13238586576778400, 0.14881644790104200,
        ],
        kick: [
            0.050262764400392200, 0.41351430042834400, 0.045079889794397700, -0.18805485381956900,
            0.54196067845078000, -0.7255255585086898, 0.54196067845078000, -0.18805485381956900,
            0.045079889794397700, 0.41351430042834400, 0.050262764400392200,
        ],
    }
}

crate::splitting! {
    /// Blanes & Moan (2002), Table 3, SRKN_6^b (RKN, 6 evaluations, BAB) (SRKN6b, BM4 RKN, BM42).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.0829844064174) D(0.245298957184) K(0.396309801498) D(0.604872665711) K(-0.0390563049223)
    /// D(-0.350171622895) K(0.119524194013) D(-0.350171622895) K(-0.0390563049223)
    /// D(0.604872665711) K(0.396309801498) D(0.245298957184) K(0.0829844064174)
    /// ```
    ///
    /// Built for quadratic kinetic energy (Runge-Kutta-Nystrom problems), order 4, 6 force
    /// evaluations per step (FSAL); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (BlanesMoan2002SRKN6B,
    /// composition BAB)` at 9ffb8b0.
    /// Precision: decimal in source, up to 17 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Central coefficients recomputed from the consistency conditions as defined in the
    /// paper (b4 = 1 - 2(b1+b2+b3), a3 = 1/2 - (a1+a2)). Optimized for RKN problems but measured
    /// order 4 also for general splittings.
    pub struct BlanesMoanSrkn6b {
        name: "blanes_moan_srkn6b",
        order: 4,
        drift: [
            0, 0.24529895718427100, 0.60487266571108000, -0.350171622895351, -0.350171622895351,
            0.60487266571108000, 0.24529895718427100,
        ],
        kick: [
            0.082984406417405200, 0.39630980149836800, -0.039056304922348600, 0.1195241940131508,
            -0.039056304922348600, 0.39630980149836800, 0.082984406417405200,
        ],
    }
}

crate::splitting! {
    /// Blanes & Moan (2002), Table 3, SRKN_11^b (RKN, 11 evaluations, BAB) (SRKN11b, BM6 RKN).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(0.0414649985183) D(0.123229775946) K(0.198128671918) D(0.2905537978) K(-0.0400061921042)
    /// D(-0.127049212625) K(0.0752539843016) D(-0.246331761062) K(-0.0115113874207)
    /// D(0.357208872796) K(0.236669924787) D(0.204777054291) K(0.236669924787) D(0.357208872796)
    /// K(-0.0115113874207) D(-0.246331761062) K(0.0752539843016) D(-0.127049212625)
    /// K(-0.0400061921042) D(0.2905537978) K(0.198128671918) D(0.123229775946) K(0.0414649985183)
    /// ```
    ///
    /// Built for quadratic kinetic energy (Runge-Kutta-Nystrom problems), order 6 (measured 4 for a
    /// general kinetic energy, 6 for a quadratic one), 11 force evaluations per step (FSAL);
    /// symmetric. Accepts only problems with a quadratic kinetic energy (`QuadraticKinetic`).
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (BlanesMoan2002SRKN11B,
    /// composition BAB)` at 9ffb8b0.
    /// Precision: decimal in source, up to 17 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Central coefficients recomputed from the consistency conditions as defined in the
    /// paper. Only 4th order if T is not quadratic.
    pub struct BlanesMoanSrkn11b {
        name: "blanes_moan_srkn11b",
        order: 6,
        drift: [
            0, 0.12322977594627100, 0.29055379779955800, -0.12704921262541700, -0.24633176106207500,
            0.35720887279592800, 0.20477705429147, 0.35720887279592800, -0.24633176106207500,
            -0.12704921262541700, 0.29055379779955800, 0.12322977594627100,
        ],
        kick: [
            0.041464998518262400, 0.19812867191806700, -0.040006192104153300, 0.075253984301580700,
            -0.011511387420687900, 0.2366699247869311, 0.2366699247869311, -0.011511387420687900,
            0.075253984301580700, -0.040006192104153300, 0.19812867191806700, 0.041464998518262400,
        ],
        quadratic_kinetic: true,
    }
}

crate::splitting! {
    /// Blanes & Moan (2002), Table 3, SRKN_14^a (RKN, 14 evaluations, ABA) (SRKN14a).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.0378593198406) K(0.0917191526245) D(0.102635633102) K(0.183983170005)
    /// D(-0.0258678882666) K(-0.0565343658329) D(0.314241403071) K(0.00491468877471)
    /// D(-0.130144459517) K(0.143761127168) D(0.10641770037) K(0.328567693747) D(-0.00879424312851)
    /// K(-0.196411466486) D(0.207305069057) K(-0.196411466486) D(-0.00879424312851)
    /// K(0.328567693747) D(0.10641770037) K(0.143761127168) D(-0.130144459517) K(0.00491468877471)
    /// D(0.314241403071) K(-0.0565343658329) D(-0.0258678882666) K(0.183983170005)
    /// D(0.102635633102) K(0.0917191526245) D(0.0378593198406)
    /// ```
    ///
    /// Built for quadratic kinetic energy (Runge-Kutta-Nystrom problems), order 6 (measured 4 for a
    /// general kinetic energy, 6 for a quadratic one), 14 force evaluations per step; symmetric.
    /// Accepts only problems with a quadratic kinetic energy (`QuadraticKinetic`).
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (BlanesMoan2002SRKN14A,
    /// composition ABA)` at 9ffb8b0.
    /// Precision: decimal in source, up to 17 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Central coefficients recomputed from consistency. Its error constant is so small that
    /// with \~16-digit coefficients the RKN slopes (9.1, 8.4, 7.7) hit the coefficient-precision
    /// floor before reaching the asymptotic value 7; consistent with order 6 but not a clean
    /// measurement.
    pub struct BlanesMoanSrkn14a {
        name: "blanes_moan_srkn14a",
        order: 6,
        drift: [
            0.037859319840611600, 0.10263563310243500, -0.025867888266558700, 0.31424140307144700,
            -0.13014445951741500, 0.10641770036954300, -0.0087942431285105800, 0.20730506905689536,
            -0.0087942431285105800, 0.10641770036954300, -0.13014445951741500, 0.31424140307144700,
            -0.025867888266558700, 0.10263563310243500, 0.037859319840611600,
        ],
        kick: [
            0.091719152624461650, 0.18398317000500600, -0.056534365832888270, 0.0049146887747128540,
            0.14376112716835800, 0.32856769374680400, -0.196411466486454234, -0.196411466486454234,
            0.32856769374680400, 0.14376112716835800, 0.0049146887747128540, -0.056534365832888270,
            0.18398317000500600, 0.091719152624461650, 0,
        ],
        quadratic_kinetic: true,
    }
}

crate::splitting! {
    /// Okunbor & Skeel (1994) Math. Comp. 59:439, order 6 method 13 (RKN, 7 evaluations);
    /// coefficients as reprinted by McLachlan (1995) (OS6).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(-1.01308797892) K(0.0001660069265) D(1.18742957373) K(-0.379624214264) D(-0.0183358520965)
    /// K(0.689137411852) D(0.343994257281) K(0.380641590971) D(0.343994257281) K(0.689137411852)
    /// D(-0.0183358520965) K(-0.379624214264) D(1.18742957373) K(0.0001660069265) D(-1.01308797892)
    /// ```
    ///
    /// Built for quadratic kinetic energy (Runge-Kutta-Nystrom problems), order 6 (measured 4 for a
    /// general kinetic energy, 6 for a quadratic one), 7 force evaluations per step; symmetric.
    /// Accepts only problems with a quadratic kinetic energy (`QuadraticKinetic`).
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp
    /// (OkunborSkeel1994Order6Method13, composition ABA)` at 9ffb8b0.
    /// Precision: decimal in source, up to 20 significant digits (derived entries printed with 5
    /// guard digits).
    pub struct OkunborSkeel6 {
        name: "okunbor_skeel6",
        order: 6,
        drift: [
            -1.0130879789171747298, 1.1874295737325427070, -0.018335852096460590340,
            0.34399425728109261313, 0.34399425728109261313, -0.018335852096460590340,
            1.1874295737325427070, -1.0130879789171747298,
        ],
        kick: [
            0.00016600692650009894, -0.37962421426377360608, 0.68913741185181063674,
            0.38064159097092574080, 0.68913741185181063674, -0.37962421426377360608,
            0.00016600692650009894, 0,
        ],
        quadratic_kinetic: true,
    }
}

crate::splitting! {
    /// Laskar & Robutel (2001) Celest. Mech. Dyn. Astron. 80:39, SABA_1 (drift nodes =
    /// Gauss-Legendre, kick weights = Gauss weights) (SABA1, SABAC1 with corrector).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(1/2) K(1) D(1/2)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 2, 1 force evaluation per step;
    /// symmetric. Generalized order (2, 2) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step) (row
    /// SABA1)` at 6c44115.
    /// Precision: exact rationals.
    ///
    /// Note: Generalized order: error O(eps h^(2n) + eps^2 h^2); symmetric; n kick evaluations.
    ///
    /// Closed form:
    ///
    /// ```text
    /// drift = [1/2, 1/2]
    /// kick = [1]
    /// ```
    pub struct Saba1 {
        name: "saba1",
        order: 2,
        drift: [1/2, 1/2],
        kick: [1, 0],
    }
}

crate::splitting! {
    /// Laskar & Robutel (2001) Celest. Mech. Dyn. Astron. 80:39, SABA_2 (drift nodes =
    /// Gauss-Legendre, kick weights = Gauss weights) (SABA2, SABAC2 with corrector).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.211324865405) K(1/2) D(0.57735026919) K(1/2) D(0.211324865405)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 2, 2 force evaluations per step;
    /// symmetric. Generalized order (4, 2) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step) (row
    /// SABA2)` at 6c44115.
    /// Precision: decimal in source, up to 40 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Generalized order: error O(eps h^(2n) + eps^2 h^2); symmetric; n kick evaluations.
    ///
    /// Closed form:
    ///
    /// ```text
    /// drift = [1/2 - sqrt(3)/6, sqrt(3)/3, 1/2 - sqrt(3)/6]
    /// kick = [1/2, 1/2]
    /// ```
    pub struct Saba2 {
        name: "saba2",
        order: 2,
        drift: [
            0.2113248654051871177454256097490212721762, 0.5773502691896257645091487805019574556476,
            0.2113248654051871177454256097490212721762,
        ],
        kick: [1/2, 1/2, 0],
    }
}

crate::splitting! {
    /// Laskar & Robutel (2001) Celest. Mech. Dyn. Astron. 80:39, SABA_3 (drift nodes =
    /// Gauss-Legendre, kick weights = Gauss weights) (SABA3, SABAC3 with corrector).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.112701665379) K(0.277777777778) D(0.387298334621) K(0.444444444444) D(0.387298334621)
    /// K(0.277777777778) D(0.112701665379)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 2, 3 force evaluations per step;
    /// symmetric. Generalized order (6, 2) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step) (row
    /// SABA3)` at 6c44115.
    /// Precision: decimal in source, up to 40 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Generalized order: error O(eps h^(2n) + eps^2 h^2); symmetric; n kick evaluations.
    ///
    /// Closed form:
    ///
    /// ```text
    /// drift = [1/2 - sqrt(15)/10, sqrt(15)/10, sqrt(15)/10, 1/2 - sqrt(15)/10]
    /// kick = [5/18, 4/9, 5/18]
    /// ```
    pub struct Saba3 {
        name: "saba3",
        order: 2,
        drift: [
            0.1127016653792583114820734600217600389167, 0.3872983346207416885179265399782399610833,
            0.3872983346207416885179265399782399610833, 0.1127016653792583114820734600217600389167,
        ],
        kick: [
            0.2777777777777777777777777777777777777778, 0.4444444444444444444444444444444444444444,
            0.2777777777777777777777777777777777777778, 0,
        ],
    }
}

crate::splitting! {
    /// Laskar & Robutel (2001) Celest. Mech. Dyn. Astron. 80:39, SABA_4 (drift nodes =
    /// Gauss-Legendre, kick weights = Gauss weights) (SABA4, SABAC4 with corrector).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.069431844203) K(0.173927422569) D(0.260577634005) K(0.326072577431) D(0.339981043585)
    /// K(0.326072577431) D(0.260577634005) K(0.173927422569) D(0.069431844203)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 2, 4 force evaluations per step;
    /// symmetric. Generalized order (8, 2) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step) (row
    /// SABA4)` at 6c44115.
    /// Precision: decimal in source, up to 40 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: Generalized order: error O(eps h^(2n) + eps^2 h^2); symmetric; n kick evaluations.
    ///
    /// Closed form:
    ///
    /// ```text
    /// drift = [1/2 - sqrt(525+70*sqrt(30))/70, (sqrt(525+70*sqrt(30)) - sqrt(525-70*sqrt(30)))/70,
    ///     sqrt(525-70*sqrt(30))/35, ...mirror]
    /// kick = [1/4 - sqrt(30)/72, 1/4 + sqrt(30)/72, 1/4 + sqrt(30)/72, 1/4 - sqrt(30)/72]
    /// ```
    pub struct Saba4 {
        name: "saba4",
        order: 2,
        drift: [
            0.06943184420297371238802675555359524745214, 0.2605776340045981552106403648947824089476,
            0.3399810435848562648026657591032446872006, 0.2605776340045981552106403648947824089476,
            0.06943184420297371238802675555359524745214,
        ],
        kick: [
            0.1739274225687269286865319746109997036177, 0.3260725774312730713134680253890002963823,
            0.3260725774312730713134680253890002963823, 0.1739274225687269286865319746109997036177,
            0,
        ],
    }
}

crate::splitting! {
    /// Laskar & Robutel (2001), SBAB_1 (kick weights/drift gaps = Gauss-Lobatto quadrature with 2
    /// nodes) (SBAB1).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(1/2) D(1) K(1/2)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 2, 1 force evaluation per step (FSAL);
    /// symmetric. Generalized order (2, 2) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from closed form `not implemented in the fetched anchors (REBOUND implements
    /// SABA only); coefficients from the Gauss-Lobatto closed forms in Laskar & Robutel (2001)`.
    /// Precision: exact rationals.
    ///
    /// Note: Generalized order O(eps h^(2n) + eps^2 h^2); FSAL (starts and ends with a kick); n+1
    /// kicks, n with FSAL.
    ///
    /// Closed form:
    ///
    /// ```text
    /// kick = [1/2, 1/2], drift = [1]
    /// ```
    pub struct Sbab1 {
        name: "sbab1",
        order: 2,
        drift: [0, 1],
        kick: [1/2, 1/2],
    }
}

crate::splitting! {
    /// Laskar & Robutel (2001), SBAB_2 (kick weights/drift gaps = Gauss-Lobatto quadrature with 3
    /// nodes) (SBAB2).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(1/6) D(1/2) K(2/3) D(1/2) K(1/6)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 2, 2 force evaluations per step (FSAL);
    /// symmetric. Generalized order (4, 2) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from closed form `not implemented in the fetched anchors (REBOUND implements
    /// SABA only); coefficients from the Gauss-Lobatto closed forms in Laskar & Robutel (2001)`.
    /// Precision: exact rationals.
    ///
    /// Note: Generalized order O(eps h^(2n) + eps^2 h^2); FSAL (starts and ends with a kick); n+1
    /// kicks, n with FSAL.
    ///
    /// Closed form:
    ///
    /// ```text
    /// kick = [1/6, 2/3, 1/6], drift = [1/2, 1/2]
    /// ```
    pub struct Sbab2 {
        name: "sbab2",
        order: 2,
        drift: [0, 1/2, 1/2],
        kick: [1/6, 2/3, 1/6],
    }
}

crate::splitting! {
    /// Laskar & Robutel (2001), SBAB_3 (kick weights/drift gaps = Gauss-Lobatto quadrature with 4
    /// nodes) (SBAB3).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(1/12) D(0.27639320225) K(5/12) D(0.4472135955) K(5/12) D(0.27639320225) K(1/12)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 2, 3 force evaluations per step (FSAL);
    /// symmetric. Generalized order (6, 2) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from closed form `not implemented in the fetched anchors (REBOUND implements
    /// SABA only); coefficients from the Gauss-Lobatto closed forms in Laskar & Robutel (2001)`.
    /// Precision: exact closed form; irrational entries as 40-digit decimals.
    ///
    /// Note: Generalized order O(eps h^(2n) + eps^2 h^2); FSAL (starts and ends with a kick); n+1
    /// kicks, n with FSAL.
    ///
    /// Closed form:
    ///
    /// ```text
    /// kick = [1/12, 5/12, 5/12, 1/12], drift = [1/2 - sqrt(5)/10, sqrt(5)/5, 1/2 - sqrt(5)/10]
    /// ```
    pub struct Sbab3 {
        name: "sbab3",
        order: 2,
        drift: [
            0, 0.2763932022500210303590826331268723764559,
            0.4472135954999579392818347337462552470881, 0.2763932022500210303590826331268723764559,
        ],
        kick: [1/12, 5/12, 5/12, 1/12],
    }
}

crate::splitting! {
    /// Laskar & Robutel (2001), SBAB_4 (kick weights/drift gaps = Gauss-Lobatto quadrature with 5
    /// nodes) (SBAB4).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// K(1/20) D(0.172673164646) K(49/180) D(0.327326835354) K(16/45) D(0.327326835354) K(49/180)
    /// D(0.172673164646) K(1/20)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 2, 4 force evaluations per step (FSAL);
    /// symmetric. Generalized order (8, 2) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from closed form `not implemented in the fetched anchors (REBOUND implements
    /// SABA only); coefficients from the Gauss-Lobatto closed forms in Laskar & Robutel (2001)`.
    /// Precision: exact closed form; irrational entries as 40-digit decimals.
    ///
    /// Note: Generalized order O(eps h^(2n) + eps^2 h^2); FSAL (starts and ends with a kick); n+1
    /// kicks, n with FSAL.
    ///
    /// Closed form:
    ///
    /// ```text
    /// kick = [1/20, 49/180, 16/45, 49/180, 1/20], drift = [1/2 - sqrt(21)/14, sqrt(21)/14,
    ///     sqrt(21)/14, 1/2 - sqrt(21)/14] (Gauss-Lobatto nodes/weights)
    /// ```
    pub struct Sbab4 {
        name: "sbab4",
        order: 2,
        drift: [
            0, 0.1726731646460114281008537718765708222154,
            0.3273268353539885718991462281234291777846, 0.3273268353539885718991462281234291777846,
            0.1726731646460114281008537718765708222154,
        ],
        kick: [1/20, 49/180, 16/45, 49/180, 1/20],
    }
}

crate::splitting! {
    /// Blanes, Casas, Farres, Laskar, Makazaga & Murua (2013) Appl. Numer. Math. 68:58, ABA(10,4)
    /// (ABA(10,4), SABA(10,4)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.047067100646) K(0.118881917368) D(0.184756935417) K(0.241050460552) D(0.28270600568)
    /// K(-0.273286666705) D(-0.0145300417429) K(0.826708577571) D(-0.0145300417429)
    /// K(-0.273286666705) D(0.28270600568) K(0.241050460552) D(0.184756935417) K(0.118881917368)
    /// D(0.047067100646)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 4, 7 force evaluations per step;
    /// symmetric. Generalized order (10, 4) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step)
    /// (ABA(10,4))` at 6c44115.
    /// Precision: decimal in source, up to 40 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: 7 kick evaluations; generalized order (10, 4): error O(eps^1 h^10 + eps^2 h^4).
    pub struct Aba1004 {
        name: "aba1004",
        order: 4,
        drift: [
            0.04706710064597250612947887637243678556564, 0.1847569354170881069247376193702560968574,
            0.2827060056798362053243616565541452479160,
            -0.01453004174289681837857815229683813033908,
            -0.01453004174289681837857815229683813033908,
            0.2827060056798362053243616565541452479160, 0.1847569354170881069247376193702560968574,
            0.04706710064597250612947887637243678556564,
        ],
        kick: [
            0.1188819173681970199453503950853885936957, 0.2410504605515015657441667865901651105675,
            -0.2732866667053238060543113981664559460630, 0.8267085775712504407295884329818044835997,
            -0.2732866667053238060543113981664559460630, 0.2410504605515015657441667865901651105675,
            0.1188819173681970199453503950853885936957, 0,
        ],
    }
}

crate::splitting! {
    /// Blanes, Casas, Farres, Laskar, Makazaga & Murua (2013) Appl. Numer. Math. 68:58, ABA(8,6,4)
    /// (ABA(8,6,4), SABA(8,6,4)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.0711334264982) K(0.183083687472) D(0.241153427957) K(0.310782859899) D(0.521411761773)
    /// K(-0.026564618512) D(-0.333698616228) K(0.0653961422824) D(-0.333698616228)
    /// K(-0.026564618512) D(0.521411761773) K(0.310782859899) D(0.241153427957) K(0.183083687472)
    /// D(0.0711334264982)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 4, 7 force evaluations per step;
    /// symmetric. Generalized order (8, 6, 4) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step)
    /// (ABA(8,6,4)); also src/integrator_eos.c lf8_6_4 for ABA(8,6,4)` at 6c44115.
    /// Precision: decimal in source, up to 39 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: 7 kick evaluations; generalized order (8, 6, 4): error O(eps^1 h^8 + eps^2 h^6 + eps^3
    /// h^4).
    pub struct Aba864 {
        name: "aba864",
        order: 4,
        drift: [
            0.0711334264982231177779387300061549964174, 0.241153427956640098736487795326289649618,
            0.521411761772814789212136078067994229991, -0.333698616227678005726562603400438876027,
            -0.333698616227678005726562603400438876027, 0.521411761772814789212136078067994229991,
            0.241153427956640098736487795326289649618, 0.0711334264982231177779387300061549964174,
        ],
        kick: [
            0.183083687472197221961703757166430291072, 0.310782859898574869507522291054262796375,
            -0.0265646185119588006972121379164987592663, 0.0653961422823734184559721793911134363710,
            -0.0265646185119588006972121379164987592663, 0.310782859898574869507522291054262796375,
            0.183083687472197221961703757166430291072, 0,
        ],
    }
}

crate::splitting! {
    /// Blanes, Casas, Farres, Laskar, Makazaga & Murua (2013) Appl. Numer. Math. 68:58, ABA(10,6,4)
    /// (ABA(10,6,4), SABA(10,6,4)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.0380944974224) K(0.0958588808371) D(0.145298716117) K(0.204446153143) D(0.207627695726)
    /// K(0.217070347979) D(0.435909703652) K(-0.0173753819591) D(-0.653861225833)
    /// K(-0.0173753819591) D(0.435909703652) K(0.217070347979) D(0.207627695726) K(0.204446153143)
    /// D(0.145298716117) K(0.0958588808371) D(0.0380944974224)
    /// ```
    ///
    /// Near-integrable splitting (`H = A + eps B`), order 4, 8 force evaluations per step;
    /// symmetric. Generalized order (10, 6, 4) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step)
    /// (ABA(10,6,4))` at 6c44115.
    /// Precision: decimal in source, up to 40 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: 8 kick evaluations; generalized order (10, 6, 4): error O(eps^1 h^10 + eps^2 h^6 +
    /// eps^3 h^4).
    pub struct Aba1064 {
        name: "aba1064",
        order: 4,
        drift: [
            0.03809449742241219545697532230863756534060, 0.1452987161169137492940200726606637497442,
            0.2076276957255412507162056113249882065158, 0.4359097036515261592231548624010651844006,
            -0.6538612258327867093807117373907094120024, 0.4359097036515261592231548624010651844006,
            0.2076276957255412507162056113249882065158, 0.1452987161169137492940200726606637497442,
            0.03809449742241219545697532230863756534060,
        ],
        kick: [
            0.09585888083707521061077150377145884776921, 0.2044461531429987806805077839164344779763,
            0.2170703479789911017143385924306336714532,
            -0.01737538195906509300561788011852699719871,
            -0.01737538195906509300561788011852699719871,
            0.2170703479789911017143385924306336714532, 0.2044461531429987806805077839164344779763,
            0.09585888083707521061077150377145884776921, 0,
        ],
    }
}

crate::splitting! {
    /// Blanes, Casas, Farres, Laskar, Makazaga & Murua (2013) Appl. Numer. Math. 68:58, ABAH(8,4,4)
    /// (requires \[B,\[B,\[B,A\]\]\]=0, e.g. perturbation depending on positions only and A
    /// quadratic in momenta) (ABAH(8,4,4), SABA(8,4,4)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.274140268943) K(0.640885795163) D(-0.10756843844) K(-0.858575448957) D(-0.0480185025906)
    /// K(0.717689653794) D(0.762893344175) K(0.717689653794) D(-0.0480185025906) K(-0.858575448957)
    /// D(-0.10756843844) K(0.640885795163) D(0.274140268943)
    /// ```
    ///
    /// Near-integrable splitting with `[B,[B,[B,A]]] = 0`, order 4, 6 force evaluations per step;
    /// symmetric. Generalized order (8, 4, 4) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step)
    /// (ABAH(8,4,4))` at 6c44115.
    /// Precision: decimal in source, up to 40 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: 6 kick evaluations; generalized order (8, 4, 4): error O(eps^1 h^8 + eps^2 h^4 + eps^3
    /// h^4).
    pub struct Abah844 {
        name: "abah844",
        order: 4,
        drift: [
            0.2741402689434018761640565440378637101205, -0.1075684384401642306251105297063236526845,
            -0.0480185025906016926911954171508475065370, 0.7628933441747280943044988056386148982021,
            -0.0480185025906016926911954171508475065370,
            -0.1075684384401642306251105297063236526845, 0.2741402689434018761640565440378637101205,
        ],
        kick: [
            0.6408857951625127177322491164716010349386, -0.8585754489567828565881283246356000103664,
            0.7176896537942701388558792081639989754277, 0.7176896537942701388558792081639989754277,
            -0.8585754489567828565881283246356000103664, 0.6408857951625127177322491164716010349386,
            0,
        ],
    }
}

crate::splitting! {
    /// Blanes, Casas, Farres, Laskar, Makazaga & Murua (2013) Appl. Numer. Math. 68:58, ABAH(8,6,4)
    /// (requires \[B,\[B,\[B,A\]\]\]=0, e.g. perturbation depending on positions only and A
    /// quadratic in momenta) (ABAH(8,6,4), SABA(8,6,4)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.0681023565166) K(0.168443259362) D(0.251136038722) K(0.424317717374) D(-0.0750726495722)
    /// K(-0.585810969468) D(-0.00954471970175) K(0.493049992732) D(0.53075794807) K(0.493049992732)
    /// D(-0.00954471970175) K(-0.585810969468) D(-0.0750726495722) K(0.424317717374)
    /// D(0.251136038722) K(0.168443259362) D(0.0681023565166)
    /// ```
    ///
    /// Near-integrable splitting with `[B,[B,[B,A]]] = 0`, order 4, 8 force evaluations per step;
    /// symmetric. Generalized order (8, 6, 4) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step)
    /// (ABAH(8,6,4))` at 6c44115.
    /// Precision: decimal in source, up to 40 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: 8 kick evaluations; generalized order (8, 6, 4): error O(eps^1 h^8 + eps^2 h^6 + eps^3
    /// h^4).
    pub struct Abah864 {
        name: "abah864",
        order: 4,
        drift: [
            0.06810235651658372084723976682061164571212, 0.2511360387221033233072829580455350680082,
            -0.07507264957216562516006821767601620052338,
            -0.009544719701745007811488218957217113269121,
            0.5307579480704471776340674235341732001443,
            -0.009544719701745007811488218957217113269121,
            -0.07507264957216562516006821767601620052338,
            0.2511360387221033233072829580455350680082, 0.06810235651658372084723976682061164571212,
        ],
        kick: [
            0.1684432593618954534310382697756917558148, 0.4243177173742677224300351657407231801453,
            -0.5858109694681756812309015355404036521923, 0.4930499927320125053698281000239887162321,
            0.4930499927320125053698281000239887162321, -0.5858109694681756812309015355404036521923,
            0.4243177173742677224300351657407231801453, 0.1684432593618954534310382697756917558148,
            0,
        ],
    }
}

crate::splitting! {
    /// Blanes, Casas, Farres, Laskar, Makazaga & Murua (2013) Appl. Numer. Math. 68:58,
    /// ABAH(10,6,4) (requires \[B,\[B,\[B,A\]\]\]=0, e.g. perturbation depending on positions only
    /// and A quadratic in momenta) (ABAH(10,6,4), SABA(10,6,4)).
    ///
    /// One step of size `h` applies, left to right (drift-first fractions of `h`):
    ///
    /// ```text
    /// D(0.0473190869765) K(0.119688462459) D(0.265110523575) K(0.375295585538)
    /// D(-0.00997652288381) K(-0.468459341833) D(-0.0599291997349) K(0.335139734276)
    /// D(0.257476112067) K(0.276671119121) D(0.257476112067) K(0.335139734276) D(-0.0599291997349)
    /// K(-0.468459341833) D(-0.00997652288381) K(0.375295585538) D(0.265110523575)
    /// K(0.119688462459) D(0.0473190869765)
    /// ```
    ///
    /// Near-integrable splitting with `[B,[B,[B,A]]] = 0`, order 4, 9 force evaluations per step;
    /// symmetric. Generalized order (10, 6, 4) in (eps, eps^2, eps^3).
    ///
    /// Coefficients from hannorein/rebound `src/integrator_saba.c (reb_saba_c = drift
    /// half-sequence, reb_saba_d = kick half-sequence, expanded by reb_integrator_saba_step)
    /// (ABAH(10,6,4))` at 6c44115.
    /// Precision: decimal in source, up to 40 significant digits (derived entries printed with 5
    /// guard digits).
    ///
    /// Note: 9 kick evaluations; generalized order (10, 6, 4): error O(eps^1 h^10 + eps^2 h^6 +
    /// eps^3 h^4).
    pub struct Abah1064 {
        name: "abah1064",
        order: 4,
        drift: [
            0.04731908697653382270404371796320813250988, 0.2651105235748785159539480036185693201078,
            -0.009976522883811240843267468164812380613143,
            -0.05992919973494155126395247987729676004016,
            0.2574761120673404534492282264603316880356, 0.2574761120673404534492282264603316880356,
            -0.05992919973494155126395247987729676004016,
            -0.009976522883811240843267468164812380613143,
            0.2651105235748785159539480036185693201078, 0.04731908697653382270404371796320813250988,
        ],
        kick: [
            0.1196884624585322035312864297489892143852, 0.3752955855379374250420128537687503199451,
            -0.4684593418325993783650820409805381740605, 0.3351397342755897010393098942949569049275,
            0.2766711191210800975049457263356834696055, 0.3351397342755897010393098942949569049275,
            -0.4684593418325993783650820409805381740605, 0.3752955855379374250420128537687503199451,
            0.1196884624585322035312864297489892143852, 0,
        ],
    }
}
