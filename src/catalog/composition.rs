//! Composition methods: weights over a symmetric second-order base.
//!
//! Coefficients are transcribed from the project's `data/splitting.toml` by
//! `tools/gen_splitting_catalog.py` and checked at compile time by the `composition!` macro.

crate::composition! {
    /// Yoshida (1990) Phys. Lett. A 150:262; Forest & Ruth (1990); Creutz & Gocksch (1989); Suzuki
    /// (1990) - the 3-stage "triple jump" (Yoshida 4, Forest-Ruth, triple jump).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 1.35120719196, -1.70241438392, 1.35120719196
    /// ```
    ///
    /// Composition of order 4 over a symmetric second-order base, 3 base steps (3 force evaluations
    /// with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqSymplecticRK/src/symplectic_tableaus.jl (CandyRoz4 closed form: 1/(2 -
    /// 2^(1/3)), 1/(1 - 2^(2/3))); Principia CandyRozmus1991ForestRuth1990 and SUNDIALS
    /// arkodeSymplecticCandyRozmus4 agree` at b211787.
    /// Precision: exact closed form; irrational entries as 40-digit decimals.
    ///
    /// Closed form:
    ///
    /// ```text
    /// gamma = [w1, w0, w1], w1 = 1/(2 - 2^(1/3)), w0 = -2^(1/3)/(2 - 2^(1/3)) = 1/(1 - 2^(2/3))
    /// ```
    pub struct TripleJump4 {
        name: "triple_jump4",
        order: 4,
        gamma: [
            1.351207191959657634047687808971460826922, -1.702414383919315268095375617942921653844,
            1.351207191959657634047687808971460826922,
        ],
    }
}

crate::composition! {
    /// Suzuki (1990) Phys. Lett. A 146:319, 5-stage fractal (Suzuki 4, Suzuki fractal).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.414490771794, 0.414490771794, -0.657963087178, 0.414490771794, 0.414490771794
    /// ```
    ///
    /// Composition of order 4 over a symmetric second-order base, 5 base steps (5 force evaluations
    /// with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (鈴木1990: a = gamma)` at
    /// 9ffb8b0.
    /// Precision: exact closed form; irrational entries as 40-digit decimals.
    ///
    /// Closed form:
    ///
    /// ```text
    /// gamma = [p, p, 1-4p, p, p], p = 1/(4 - 4^(1/3))
    /// ```
    pub struct SuzukiFractal4 {
        name: "suzuki_fractal4",
        order: 4,
        gamma: [
            0.4144907717943757371423540628607614957118, 0.4144907717943757371423540628607614957118,
            -0.6579630871775029485694162514430459828471, 0.4144907717943757371423540628607614957118,
            0.4144907717943757371423540628607614957118,
        ],
    }
}

crate::composition! {
    /// McLachlan (1995), SS5 (s=5, order 4, w1 = 0.28 chosen) (SS5).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 7/25, 0.625466428468, -0.810932856935, 0.625466428468, 7/25
    /// ```
    ///
    /// Composition of order 4 over a symmetric second-order base, 5 base steps (5 force evaluations
    /// with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (McLachlan1995SS5)` at
    /// 9ffb8b0.
    /// Precision: decimal in source, up to 19 significant digits.
    ///
    /// Closed form:
    ///
    /// ```text
    /// gamma = [w1, w2, 1-2(w1+w2), w2, w1], w1 = 0.28 (fixed), w2 = 0.6254664284676700450 (solves
    ///     sum gamma^3 = 0)
    /// ```
    pub struct MclachlanSs5 {
        name: "mclachlan_ss5",
        order: 4,
        gamma: [7/25, 0.6254664284676700450, -0.8109328569353400900, 0.6254664284676700450, 7/25],
    }
}

crate::composition! {
    /// Yoshida (1990), 6th order solution A (s=7) (Yoshida6, Yoshida 6A, ARKODE_SPRK_YOSHIDA_6_8).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.784513610478, 0.235573213359, -1.17767998418, 1.31518632068, -1.17767998418,
    /// 0.235573213359, 0.784513610478
    /// ```
    ///
    /// Composition of order 6 over a symmetric second-order base, 7 base steps (7 force evaluations
    /// with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from LLNL/sundials `src/arkode/arkode_sprk.c (arkodeSymplecticYoshida6, 40
    /// digits); Principia 吉田1990Order6A (20 digits) and OrdinaryDiffEq Yoshida6 (14 digits) agree`
    /// at c8dabce.
    /// Precision: decimal in source, up to 40 significant digits.
    pub struct Yoshida6a {
        name: "yoshida6a",
        order: 6,
        gamma: [
            0.7845136104775572638194976338663498757768, 0.2355732133593581336847931829785346016865,
            -1.177679984178871006946415680964315734639, 1.315186320683911218884249728238862514352,
            -1.177679984178871006946415680964315734639, 0.2355732133593581336847931829785346016865,
            0.7845136104775572638194976338663498757768,
        ],
    }
}

crate::composition! {
    /// Yoshida (1990), 6th order solution B (s=7) (Yoshida 6B).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 1.43984816798, 0.00426068187079, -2.132285222, 2.37635274431, -2.132285222,
    /// 0.00426068187079, 1.43984816798
    /// ```
    ///
    /// Composition of order 6 over a symmetric second-order base, 7 base steps (7 force evaluations
    /// with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (吉田1990Order6B)` at
    /// 9ffb8b0.
    /// Precision: decimal in source, up to 21 significant digits.
    pub struct Yoshida6b {
        name: "yoshida6b",
        order: 6,
        gamma: [
            1.43984816797678309102, 0.00426068187079201616, -2.13228522200145152088,
            2.37635274430775282740, -2.13228522200145152088, 0.00426068187079201616,
            1.43984816797678309102,
        ],
    }
}

crate::composition! {
    /// Yoshida (1990), 6th order solution C (s=7) (Yoshida 6C).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 1.4477825624, -2.14403531631, 0.00152886228425, 2.38944778324, 0.00152886228425,
    /// -2.14403531631, 1.4477825624
    /// ```
    ///
    /// Composition of order 6 over a symmetric second-order base, 7 base steps (7 force evaluations
    /// with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (吉田1990Order6C)` at
    /// 9ffb8b0.
    /// Precision: decimal in source, up to 21 significant digits.
    pub struct Yoshida6c {
        name: "yoshida6c",
        order: 6,
        gamma: [
            1.44778256239929793290, -2.14403531630538931060, 0.00152886228424927025338,
            2.38944778324368421490, 0.00152886228424927025338, -2.14403531630538931060,
            1.44778256239929793290,
        ],
    }
}

crate::composition! {
    /// Yoshida (1990) / Suzuki (1990) recursive triple jump: triple_jump4 composed with weights
    /// (z1, z0, z1), z1 = 1/(2 - 2^(1/5)) (Yoshida 6 (recursive), triple jump of triple jump).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 1.58722492772, -1.99977809736, 1.58722492772, -1.82324266348, 2.29714181079, -1.82324266348,
    /// 1.58722492772, -1.99977809736, 1.58722492772
    /// ```
    ///
    /// Composition of order 6 over a symmetric second-order base, 9 base steps (9 force evaluations
    /// with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from closed form `derived: product of triple_jump4 gammas and the order-6
    /// triple-jump weights`.
    /// Precision: exact closed form; irrational entries as 40-digit decimals.
    ///
    /// Note: Large error constant; listed because it is the textbook construction, not because it
    /// is competitive.
    ///
    /// Closed form:
    ///
    /// ```text
    /// gamma = [th*z1, (1-2th)*z1, th*z1, th*z0, (1-2th)*z0, th*z0, th*z1, (1-2th)*z1, th*z1], th =
    ///     1/(2-2^(1/3)), z1 = 1/(2-2^(1/5)), z0 = 1-2*z1
    /// ```
    pub struct TripleJump6 {
        name: "triple_jump6",
        order: 6,
        gamma: [
            1.587224927722242945892512075255039459075, -1.999778097355122507289954713952933454049,
            1.587224927722242945892512075255039459075, -1.823242663484828257737336341538618091228,
            2.297141810790929746484533809962945254255, -1.823242663484828257737336341538618091228,
            1.587224927722242945892512075255039459075, -1.999778097355122507289954713952933454049,
            1.587224927722242945892512075255039459075,
        ],
    }
}

crate::composition! {
    /// McLachlan (1995), SS9 (s=9, order 6, w1 = 0.1867 chosen) (SS9, REBOUND LF6).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 1867/10000, 0.555497023712, 0.129466948913, -0.843265623388, 0.943203301524,
    /// -0.843265623388, 0.129466948913, 0.555497023712, 1867/10000
    /// ```
    ///
    /// Composition of order 6 over a symmetric second-order base, 9 base steps (9 force evaluations
    /// with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (McLachlan1995SS9);
    /// REBOUND src/integrator_leapfrog.c reb_integrator_leapfrog_lf6_a (LF6) agrees to 16 digits`
    /// at 9ffb8b0.
    /// Precision: decimal in source, up to 20 significant digits.
    pub struct MclachlanSs9 {
        name: "mclachlan_ss9",
        order: 6,
        gamma: [
            1867/10000, 0.55549702371247839916, 0.12946694891347535806, -0.84326562338773460855,
            0.9432033015235617027, -0.84326562338773460855, 0.12946694891347535806,
            0.55549702371247839916, 1867/10000,
        ],
    }
}

crate::composition! {
    /// Kahan & Li (1997) Math. Comp. 66:1089, s=9 order 6 (HLW eq. V.3.12) (KahanLi6, p6s9).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.392161444007, 0.332599136789, -0.706246172558, 0.0822135962936, 0.798543990935,
    /// 0.0822135962936, -0.706246172558, 0.332599136789, 0.392161444007
    /// ```
    ///
    /// Composition of order 6 over a symmetric second-order base, 9 base steps (9 force evaluations
    /// with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqSymplecticRK/src/symplectic_tableaus.jl (KahanLi6: a1..a9 = gamma)` at
    /// b211787.
    /// Precision: decimal in source, up to 26 significant digits.
    pub struct KahanLi6 {
        name: "kahan_li6",
        order: 6,
        gamma: [
            0.39216144400731413927925056, 0.33259913678935943859974864,
            -0.70624617255763935980996482, 0.08221359629355080023149045,
            0.79854399093482996339895035, 0.08221359629355080023149045,
            -0.70624617255763935980996482, 0.33259913678935943859974864,
            0.39216144400731413927925056,
        ],
    }
}

crate::composition! {
    /// symmetric composition, order 6, s=11 (AMUSE/Huayno "SS_M11"; by its form and the m=35
    /// companion presumably Sofroniou & Spaletta 2005 - attribution not stated in the source)
    /// (SPLIT_6TH_SS_M11).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.213755839459, 0.183293814074, 0.176928194731, -0.443290826812, 0.117285604329,
    /// 0.504054748438, 0.117285604329, -0.443290826812, 0.176928194731, 0.183293814074,
    /// 0.213755839459
    /// ```
    ///
    /// Composition of order 6 over a symmetric second-order base, 11 base steps (11 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from amusecode/amuse `src/amuse_huayno/src/integrators_shared.h
    /// (SPLIT_6TH_SS_M11; also src/amuse/ext/composition_methods.py)` at 8dd292c.
    /// Precision: decimal in source, up to 32 significant digits.
    pub struct SofroniouSpaletta6S11 {
        name: "sofroniou_spaletta6_s11",
        order: 6,
        gamma: [
            0.21375583945878254555518066964857, 0.18329381407425713911385974425217,
            0.17692819473098943794898811709929, -0.44329082681170215849622829626258,
            0.11728560432865935385403585669136, 0.50405474843802736404832781714239,
            0.11728560432865935385403585669136, -0.44329082681170215849622829626258,
            0.17692819473098943794898811709929, 0.18329381407425713911385974425217,
            0.21375583945878254555518066964857,
        ],
    }
}

crate::composition! {
    /// symmetric composition, order 6, s=13 (AMUSE/Huayno "SS_M13"; presumably Sofroniou & Spaletta 2005)
    /// (SPLIT_6TH_SS_M13).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.138619308541, 0.133465628511, 0.130705310114, 0.129618937569, -0.350003248939,
    /// 0.11805530653, 0.399077515349, 0.11805530653, -0.350003248939, 0.129618937569,
    /// 0.130705310114, 0.133465628511, 0.138619308541
    /// ```
    ///
    /// Composition of order 6 over a symmetric second-order base, 13 base steps (13 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from amusecode/amuse `src/amuse_huayno/src/integrators_shared.h
    /// (SPLIT_6TH_SS_M13)` at 8dd292c.
    /// Precision: decimal in source, up to 32 significant digits.
    pub struct SofroniouSpaletta6S13 {
        name: "sofroniou_spaletta6_s13",
        order: 6,
        gamma: [
            0.13861930854051695245808013042625, 0.13346562851074760407046858832209,
            0.13070531011449225190542755785015, 0.12961893756907034772505366537091,
            -0.35000324893920896516170830911323, 0.11805530653002387170273438954049,
            0.39907751534871587459988795520665, 0.11805530653002387170273438954049,
            -0.35000324893920896516170830911323, 0.12961893756907034772505366537091,
            0.13070531011449225190542755785015, 0.13346562851074760407046858832209,
            0.13861930854051695245808013042625,
        ],
    }
}

crate::composition! {
    /// Yoshida (1990), 8th order solution A (s=15) (Yoshida 8A).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 1.0424262087, 1.82020630971, 0.157739928124, 2.44002732617, -0.0071698941971, -2.4469918237,
    /// -1.6158237415, -1.78082862659, -1.6158237415, -2.4469918237, -0.0071698941971,
    /// 2.44002732617, 0.157739928124, 1.82020630971, 1.0424262087
    /// ```
    ///
    /// Composition of order 8 over a symmetric second-order base, 15 base steps (15 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (吉田1990Order8A; derived
    /// from Yoshida eqs. 5.4-5.17 to ~21 digits)` at 9ffb8b0.
    /// Precision: decimal in source, up to 21 significant digits.
    pub struct Yoshida8a {
        name: "yoshida8a",
        order: 8,
        gamma: [
            1.04242620869970426435, 1.82020630970698006933, 0.157739928123708321343,
            2.44002732616634406382, -0.00716989419709533209981, -2.44699182370424588929,
            -1.61582374150065378479, -1.7808286265894834253, -1.61582374150065378479,
            -2.44699182370424588929, -0.00716989419709533209981, 2.44002732616634406382,
            0.157739928123708321343, 1.82020630970698006933, 1.04242620869970426435,
        ],
    }
}

crate::composition! {
    /// Yoshida (1990), 8th order solution B (s=15) (Yoshida 8B).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 1.48819229203, -2.33864815101, 2.89105148972, -2.8968825033, 0.00378039588363,
    /// 2.89195744316, -0.00169248587772, -3.0755169612, -0.00169248587772, 2.89195744316,
    /// 0.00378039588363, -2.8968825033, 2.89105148972, -2.33864815101, 1.48819229203
    /// ```
    ///
    /// Composition of order 8 over a symmetric second-order base, 15 base steps (15 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (吉田1990Order8B; derived
    /// from Yoshida eqs. 5.4-5.17 to ~21 digits)` at 9ffb8b0.
    /// Precision: decimal in source, up to 21 significant digits.
    pub struct Yoshida8b {
        name: "yoshida8b",
        order: 8,
        gamma: [
            1.48819229202921310080, -2.33864815101041943098, 2.89105148972198900311,
            -2.89688250330423987105, 0.00378039588362668223674, 2.89195744315817391244,
            -0.00169248587771706559145, -3.0755169612012526619, -0.00169248587771706559145,
            2.89195744315817391244, 0.00378039588362668223674, -2.89688250330423987105,
            2.89105148972198900311, -2.33864815101041943098, 1.48819229202921310080,
        ],
    }
}

crate::composition! {
    /// Yoshida (1990), 8th order solution C (s=15) (Yoshida 8C).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.62903065021, 1.36934946417, -1.06458714789, 1.66335809963, -1.6789692826, -1.55946803821,
    /// 0.311790812418, 1.65899088454, 0.311790812418, -1.55946803821, -1.6789692826, 1.66335809963,
    /// -1.06458714789, 1.36934946417, 0.62903065021
    /// ```
    ///
    /// Composition of order 8 over a symmetric second-order base, 15 base steps (15 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (吉田1990Order8C; derived
    /// from Yoshida eqs. 5.4-5.17 to ~21 digits)` at 9ffb8b0.
    /// Precision: decimal in source, up to 21 significant digits.
    pub struct Yoshida8c {
        name: "yoshida8c",
        order: 8,
        gamma: [
            0.629030650210427818049, 1.36934946416874222370, -1.06458714789183904181,
            1.66335809963311356298, -1.67896928259637402925, -1.55946803821449795876,
            0.311790812418431890510, 1.6589908845439910692, 0.311790812418431890510,
            -1.55946803821449795876, -1.67896928259637402925, 1.66335809963311356298,
            -1.06458714789183904181, 1.36934946416874222370, 0.629030650210427818049,
        ],
    }
}

crate::composition! {
    /// Yoshida (1990), 8th order solution D (s=15) (Yoshida 8D).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.91484424623, 0.253693336566, -1.44485223686, -0.158240635369, 1.93813913762,
    /// -1.96061023298, 0.102799849392, 1.70845307079, 0.102799849392, -1.96061023298,
    /// 1.93813913762, -0.158240635369, -1.44485223686, 0.253693336566, 0.91484424623
    /// ```
    ///
    /// Composition of order 8 over a symmetric second-order base, 15 base steps (15 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (吉田1990Order8D; derived
    /// from Yoshida eqs. 5.4-5.17 to ~21 digits)` at 9ffb8b0.
    /// Precision: decimal in source, up to 21 significant digits.
    pub struct Yoshida8d {
        name: "yoshida8d",
        order: 8,
        gamma: [
            0.914844246229642658287, 0.253693336566286009974, -1.44485223686030647660,
            -0.158240635368502468458, 1.93813913762291232471, -1.96061023297558163691,
            0.102799849392219431139, 1.7084530707866603157, 0.102799849392219431139,
            -1.96061023297558163691, 1.93813913762291232471, -0.158240635368502468458,
            -1.44485223686030647660, 0.253693336566286009974, 0.914844246229642658287,
        ],
    }
}

crate::composition! {
    /// Yoshida (1990), 8th order solution E (s=15) (Yoshida 8E).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 1.30300165758, 0.107990467718, -2.04809795883, 0.00536018921375, -0.0719180053651,
    /// 2.52778927318, 0.0227738840126, -2.693799015, 0.0227738840126, 2.52778927318,
    /// -0.0719180053651, 0.00536018921375, -2.04809795883, 0.107990467718, 1.30300165758
    /// ```
    ///
    /// Composition of order 8 over a symmetric second-order base, 15 base steps (15 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (吉田1990Order8E; derived
    /// from Yoshida eqs. 5.4-5.17 to ~21 digits)` at 9ffb8b0.
    /// Precision: decimal in source, up to 21 significant digits.
    pub struct Yoshida8e {
        name: "yoshida8e",
        order: 8,
        gamma: [
            1.30300165757516838484, 0.107990467718098279648, -2.04809795883490205633,
            0.00536018921375238082832, -0.0719180053650705075005, 2.52778927318028339169,
            0.0227738840126312259937, -2.6937990149999221983, 0.0227738840126312259937,
            2.52778927318028339169, -0.0719180053650705075005, 0.00536018921375238082832,
            -2.04809795883490205633, 0.107990467718098279648, 1.30300165757516838484,
        ],
    }
}

crate::composition! {
    /// McLachlan (1995) s=15 order 8 (also attributed to Suzuki & Umeno 1993) (McAte8, SS15,
    /// Suzuki-Umeno 8, ARKODE_SPRK_SUZUKI_UMENO_8_16).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.741670364351, -0.4091008258, 0.190754710296, -0.573862471116, 0.299064181304,
    /// 0.334624918245, 0.315293092397, -0.796887939353, 0.315293092397, 0.334624918245,
    /// 0.299064181304, -0.573862471116, 0.190754710296, -0.4091008258, 0.741670364351
    /// ```
    ///
    /// Composition of order 8 over a symmetric second-order base, 15 base steps (15 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from LLNL/sundials `src/arkode/arkode_sprk.c (arkodeSymplecticSuzukiUmeno816,
    /// 40 digits); OrdinaryDiffEq McAte8 (26 digits) and Principia McLachlan1995SS15 (20 digits)
    /// agree` at c8dabce.
    /// Precision: decimal in source, up to 40 significant digits.
    pub struct MclachlanSs15 {
        name: "mclachlan_ss15",
        order: 8,
        gamma: [
            0.7416703643506129534482278017838063156035, -0.4091008258000315939973000958935634173099,
            0.1907547102962383799538762564503716627355, -0.5738624711160822666563877266355357421595,
            0.2990641813036559238444635406886029882258, 0.3346249182452981837849579798821822886337,
            0.3152930923967665966320566638110024309941, -0.7968879393529163540197888401737330534463,
            0.3152930923967665966320566638110024309941, 0.3346249182452981837849579798821822886337,
            0.2990641813036559238444635406886029882258, -0.5738624711160822666563877266355357421595,
            0.1907547102962383799538762564503716627355, -0.4091008258000315939973000958935634173099,
            0.7416703643506129534482278017838063156035,
        ],
    }
}

crate::composition! {
    /// McLachlan (1995), SS17 (s=17, order 8, w1 = 25/194) (SS17, REBOUND LF8).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.128865979381, 0.581514087105, -0.41017537147, 0.185146935717, -0.409552343421,
    /// 0.14440594108, 0.278335500394, 0.314956683916, -0.626994825405, 0.314956683916,
    /// 0.278335500394, 0.14440594108, -0.409552343421, 0.185146935717, -0.41017537147,
    /// 0.581514087105, 0.128865979381
    /// ```
    ///
    /// Composition of order 8 over a symmetric second-order base, 17 base steps (17 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from mockingbirdnest/Principia `integrators/methods.hpp (McLachlan1995SS17);
    /// REBOUND src/integrator_leapfrog.c lf8_a (LF8) agrees to 15 digits` at 9ffb8b0.
    /// Precision: decimal in source, up to 20 significant digits.
    pub struct MclachlanSs17 {
        name: "mclachlan_ss17",
        order: 8,
        gamma: [
            0.12886597938144329897, 0.5815140871052509624, -0.41017537146985013753,
            0.1851469357165877327, -0.40955234342085141934, 0.14440594108001204106,
            0.27833550039367965131, 0.31495668391629485789, -0.626994825405133975,
            0.31495668391629485789, 0.27833550039367965131, 0.14440594108001204106,
            -0.40955234342085141934, 0.1851469357165877327, -0.41017537146985013753,
            0.5815140871052509624, 0.12886597938144329897,
        ],
    }
}

crate::composition! {
    /// Kahan & Li (1997), s=17 order 8 (HLW eq. V.3.13) (KahanLi8, p8s17).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.130202483089, 0.561162981775, -0.389474962645, 0.158841906555, -0.395903894133,
    /// 0.184539640978, 0.258374387686, 0.295011723609, -0.60550853383, 0.295011723609,
    /// 0.258374387686, 0.184539640978, -0.395903894133, 0.158841906555, -0.389474962645,
    /// 0.561162981775, 0.130202483089
    /// ```
    ///
    /// Composition of order 8 over a symmetric second-order base, 17 base steps (17 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from SciML/OrdinaryDiffEq.jl
    /// `lib/OrdinaryDiffEqSymplecticRK/src/symplectic_tableaus.jl (KahanLi8: a1..a17 = gamma)` at
    /// b211787.
    /// Precision: decimal in source, up to 26 significant digits.
    pub struct KahanLi8 {
        name: "kahan_li8",
        order: 8,
        gamma: [
            0.13020248308889008087881763, 0.56116298177510838456196441,
            -0.38947496264484728640807860, 0.15884190655515560089621075,
            -0.39590389413323757733623154, 0.18453964097831570709183254,
            0.25837438768632204729397911, 0.29501172360931029887096624,
            -0.60550853383003451169892108, 0.29501172360931029887096624,
            0.25837438768632204729397911, 0.18453964097831570709183254,
            -0.39590389413323757733623154, 0.15884190655515560089621075,
            -0.38947496264484728640807860, 0.56116298177510838456196441,
            0.13020248308889008087881763,
        ],
    }
}

crate::composition! {
    /// symmetric composition, order 8, s=21 (AMUSE/Huayno "SS_M21"; presumably Sofroniou & Spaletta 2005)
    /// (SPLIT_8TH_SS_M21).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.106477289846, 0.108374086458, 0.353378210527, -0.233414140232, -0.244452667915,
    /// 0.113178484358, 0.11892905625, 0.126039123218, 0.125817187362, 0.116991350192,
    /// -0.382635960126, 0.116991350192, 0.125817187362, 0.126039123218, 0.11892905625,
    /// 0.113178484358, -0.244452667915, -0.233414140232, 0.353378210527, 0.108374086458,
    /// 0.106477289846
    /// ```
    ///
    /// Composition of order 8 over a symmetric second-order base, 21 base steps (21 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from amusecode/amuse `src/amuse_huayno/src/integrators_shared.h
    /// (SPLIT_8TH_SS_M21)` at 8dd292c.
    /// Precision: decimal in source, up to 32 significant digits.
    pub struct SofroniouSpaletta8S21 {
        name: "sofroniou_spaletta8_s21",
        order: 8,
        gamma: [
            0.10647728984550031823931967854896, 0.10837408645835726397433410591546,
            0.35337821052654342419534541324080, -0.23341414023165082198780281128319,
            -0.24445266791528841269462171413216, 0.11317848435755633314700952515599,
            0.11892905625000350062692972283951, 0.12603912321825988140305670268365,
            0.12581718736176041804392391641587, 0.11699135019217642180722881433533,
            -0.38263596012643665350944670744040, 0.11699135019217642180722881433533,
            0.12581718736176041804392391641587, 0.12603912321825988140305670268365,
            0.11892905625000350062692972283951, 0.11317848435755633314700952515599,
            -0.24445266791528841269462171413216, -0.23341414023165082198780281128319,
            0.35337821052654342419534541324080, 0.10837408645835726397433410591546,
            0.10647728984550031823931967854896,
        ],
    }
}

crate::composition! {
    /// Sofroniou & Spaletta (2005) Optim. Methods Softw. 20:597, s=35 order 10 (HLW eq. V.3.14)
    /// (SofSpa10, p10s35, ARKODE_SPRK_SOFRONIOU_10_36).
    ///
    /// Weights `gamma` of `S(gamma_s h) o ... o S(gamma_1 h)`:
    ///
    /// ```text
    /// 0.0787957225217, 0.313096103415, 0.0279183832351, -0.229592841594, 0.130962061077,
    /// -0.269733405655, 0.0749733431559, 0.111993424, 0.366133449546, -0.399105630136,
    /// 0.103087398527, 0.411430873956, -0.00486636058314, -0.392033353709, 0.0519425029624,
    /// 0.0506650907599, 0.0496743706397, 0.0493177357596, 0.0496743706397, 0.0506650907599,
    /// 0.0519425029624, -0.392033353709, -0.00486636058314, 0.411430873956, 0.103087398527,
    /// -0.399105630136, 0.366133449546, 0.111993424, 0.0749733431559, -0.269733405655,
    /// 0.130962061077, -0.229592841594, 0.0279183832351, 0.313096103415, 0.0787957225217
    /// ```
    ///
    /// Composition of order 10 over a symmetric second-order base, 35 base steps (35 force
    /// evaluations with Stormer-Verlet); symmetric.
    ///
    /// Coefficients from LLNL/sundials `src/arkode/arkode_sprk.c (arkodeSymplecticSofroniou10, 32
    /// digits); OrdinaryDiffEq SofSpa10 (26 digits) and AMUSE SPLIT_10TH_SS_M35 agree` at c8dabce.
    /// Precision: decimal in source, up to 32 significant digits.
    pub struct SofroniouSpaletta10 {
        name: "sofroniou_spaletta10",
        order: 10,
        gamma: [
            0.078795722521686419263907679337684, 0.31309610341510852776481247192647,
            0.027918383235078066109520273275299, -0.22959284159390709415121339679655,
            0.13096206107716486317465685927961, -0.26973340565451071434460973222411,
            0.074973343155891435666137105641410, 0.11199342399981020488957508073640,
            0.36613344954622675119314812353150, -0.39910563013603589787862981058340,
            0.10308739852747107731580277001372, 0.41143087395589023782070411897608,
            -0.0048663605831352617621956593099771, -0.39203335370863990644808193642610,
            0.051942502962449647037182904015976, 0.050665090759924496335874344156866,
            0.049674370639729879054568800279461, 0.049317735759594537917680008339338,
            0.049674370639729879054568800279461, 0.050665090759924496335874344156866,
            0.051942502962449647037182904015976, -0.39203335370863990644808193642610,
            -0.0048663605831352617621956593099771, 0.41143087395589023782070411897608,
            0.10308739852747107731580277001372, -0.39910563013603589787862981058340,
            0.36613344954622675119314812353150, 0.11199342399981020488957508073640,
            0.074973343155891435666137105641410, -0.26973340565451071434460973222411,
            0.13096206107716486317465685927961, -0.22959284159390709415121339679655,
            0.027918383235078066109520273275299, 0.31309610341510852776481247192647,
            0.078795722521686419263907679337684,
        ],
    }
}
