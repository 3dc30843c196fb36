//! The double-double scalar of the tests (`tests/support/double_double.rs`): exact
//! arithmetic where it must be, the elementary functions to 1e-30 against values computed
//! with mpmath at 400 bits (split into two `f64`: `hi = float(x)`, `lo = float(x - hi)`),
//! and the crate's generic code (nalgebra, the Stumpff functions, the Kepler drift) running
//! on it at its precision.

use crate::support::double_double;
use double_double::DoubleDouble as Dd;

use nalgebra::{ComplexField, Matrix3, RealField};
use num_traits::{Num, One};
use std::f64::consts::{LN_10, PI, SQRT_2};
use stormer::kepler::{stumpff, KeplerDrift};

fn dd(hi: f64, lo: f64) -> Dd {
    Dd::new(hi, lo)
}

/// `|got - want| <= tolerance max(|want|, 1)`, with a message naming `what`.
#[track_caller]
fn close(what: &str, got: Dd, want: Dd, tolerance: f64) {
    let error = ComplexField::abs(got - want).to_f64();
    let scale = ComplexField::abs(want).to_f64().max(1.0);
    assert!(error <= tolerance * scale, "{what}: {got} vs {want} (error {error:e})");
}

#[test]
#[allow(clippy::float_cmp)] // exact values
fn sums_and_products_are_exact_where_f64_loses_the_low_part() {
    let tiny = 2f64.powi(-80);
    // (1 + 2^-80) - 1: f64 gives 0
    let sum = Dd::from_f64(1.0) + Dd::from_f64(tiny);
    assert_eq!((sum.hi, sum.lo), (1.0, tiny));
    assert_eq!((sum - Dd::one()).to_f64(), tiny);
    // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60 exactly
    let x = Dd::from_f64(1.0 + 2f64.powi(-30));
    let square = x * x;
    assert_eq!((square.hi, square.lo), (1.0 + 2f64.powi(-29), 2f64.powi(-60)));
    // fl(0.1) * 10 = 1 + 2^-54 exactly
    let tenth = Dd::from_f64(0.1) * Dd::from_f64(10.0);
    assert_eq!((tenth.hi, tenth.lo), (1.0, 2f64.powi(-54)));
    // an exact quotient is exact
    let q = (square / x - x).to_f64();
    assert!(q.abs() <= 4.0 * Dd::EPSILON, "{q:e}");
}

#[test]
fn division_and_square_root_are_correct_to_about_1e_32() {
    close(
        "1/3",
        Dd::one() / Dd::from_f64(3.0),
        dd(0.3333333333333333, 1.850371707708594e-17),
        1e-31,
    );
    close(
        "3 (1/3)",
        (Dd::one() / Dd::from_f64(3.0)) * Dd::from_f64(3.0),
        Dd::one(),
        1e-31,
    );
    close(
        "sqrt 2",
        Dd::from_f64(2.0).sqrt(),
        dd(SQRT_2, -9.667293313452913e-17),
        1e-31,
    );
    let root = Dd::from_f64(2.0).sqrt();
    close("sqrt(2)^2", root * root, Dd::from_f64(2.0), 1e-31);
}

#[test]
fn sin_cos_and_exp_agree_with_mpmath_to_1e_30() {
    // (x, sin x, cos x, exp x)
    let table = [
        (
            (0.7, 1.3e-17),
            (0.644217687237691, 1.2817005227432225e-17),
            (0.7648421872844885, -4.851263427431236e-17),
            (2.0137527074704766, -1.7440365030053172e-16),
        ),
        (
            (2.5, -1.1e-16),
            (0.5984721441039565, 3.291176436933896e-17),
            (-0.8011436155469337, 4.715719314634967e-17),
            (12.182493960703471, 6.396225254563499e-16),
        ),
        (
            (-11.3, 4e-16),
            (0.9540192499020891, 1.0886615178351794e-17),
            (0.2997453432770145, 5.709166832687156e-18),
            (1.2372924261788226e-05, 2.95403741987391e-22),
        ),
        (
            (0.001, 2.2e-20),
            (0.0009999998333333417, 2.767062798973707e-20),
            (0.9999995000000417, -7.831507455394461e-18),
            (1.0010005001667084, -4.288639857848027e-17),
        ),
        (
            (40.0, 1e-15),
            (0.7451131604793482, -4.8813464072782867e-17),
            (-0.6669380616522625, -4.1268277814009096e-17),
            (2.3538526683702022e+17, -3.206833252230844),
        ),
    ];
    for ((xh, xl), (sh, sl), (ch, cl), (eh, el)) in table {
        let x = dd(xh, xl);
        close(&format!("sin {x}"), x.sin(), dd(sh, sl), 1e-30);
        close(&format!("cos {x}"), x.cos(), dd(ch, cl), 1e-30);
        // relative
        let want = dd(eh, el);
        close(&format!("exp {x}"), x.exp() / want, Dd::one(), 1e-30);
    }
}

#[test]
fn the_other_functions_agree_with_mpmath_to_1e_30() {
    // (x, sqrt x, ln x, cbrt x, ln(1 + x), exp(x) - 1), all relative
    let table = [
        (
            (0.7, 1.3e-17),
            [
                (0.8366600265340756, -3.345754199517694e-17),
                (-0.35667494393873245, 2.3396992370805194e-17),
                (0.8879040017426006, 4.92303056723374e-17),
                (0.5306282510621704, 2.570517648312936e-18),
                (1.0137527074704764, 4.7640954624499587e-17),
            ],
        ),
        (
            (2.5, -1.1e-16),
            [
                (1.5811388300841895, 9.186546580959613e-17),
                (0.916290731874155, 2.5610348772396023e-17),
                (1.3572088082974532, 1.0386933468376227e-16),
                (1.252762968495368, -9.240547995050101e-17),
                (11.182493960703471, 6.396225254563499e-16),
            ],
        ),
        (
            (0.001, 2.2e-20),
            [
                (0.03162277660168379, 2.6548900694139752e-18),
                (-6.907755278982137, -1.941348709737287e-16),
                (0.1, -4.123892399401726e-18),
                (0.0009995003330835331, 6.09490479663166e-20),
                (0.0010005001667083417, 4.800745194570507e-20),
            ],
        ),
        (
            (3e-07, 1e-24),
            [
                (0.0005477225575051661, -6.270806335692738e-21),
                (-15.01948336229021, -6.115036151485029e-16),
                (0.0066943295008216955, -3.5249804609146123e-19),
                (2.99999955000009e-07, 5.6914542352748706e-24),
                (3.000000450000045e-07, -3.2807386001819725e-24),
            ],
        ),
    ];
    for ((xh, xl), want) in table {
        let x = dd(xh, xl);
        let got = [x.sqrt(), x.ln(), x.cbrt(), x.ln_1p(), x.exp_m1()];
        for (name, (got, (h, l))) in ["sqrt", "ln", "cbrt", "ln_1p", "exp_m1"]
            .iter()
            .zip(got.into_iter().zip(want))
        {
            close(&format!("{name} {x}"), got / dd(h, l), Dd::one(), 1e-30);
        }
    }
    let f = Dd::from_f64;
    close(
        "atan2",
        f(0.3).atan2(f(-0.8)),
        dd(2.782821983319221, 1.2199441343392863e-16),
        1e-30,
    );
    close(
        "asin",
        f(0.6).asin(),
        dd(0.6435011087932844, -1.1920790564184627e-17),
        1e-30,
    );
    close(
        "sinh",
        f(1e-3).sinh() / dd(0.001000000166666675, -3.571742859983052e-20),
        Dd::one(),
        1e-30,
    );
    close(
        "tanh",
        f(0.5).tanh(),
        dd(0.46211715726000974, 2.1916603238260928e-17),
        1e-30,
    );
    close("ln 10", Dd::ln_10(), dd(LN_10, -2.1707562233822494e-16), 1e-30);
    close("pi", Dd::pi(), dd(PI, 1.2246467991473532e-16), 1e-32);
    // sin(pi) is pi - fl_dd(pi), about 2.99e-33
    assert!(ComplexField::abs(Dd::pi().sin()).to_f64() < 1e-32);
}

/// The functions no measurement uses are correct too (none falls back to `f64`).
#[test]
fn the_remaining_functions_agree_with_mpmath_to_1e_30() {
    let f = Dd::from_f64;
    let x = f(0.7);
    let table = [
        ("tan", x.tan(), (0.8422883804630794, -3.9128846706146343e-17)),
        ("acos", x.acos(), (0.7953988301841436, 2.7282065511033407e-17)),
        ("atan", x.atan(), (0.6107259643892086, 2.2418914462967458e-17)),
        ("asinh", x.asinh(), (0.6526665660823557, 1.3538893500858175e-17)),
        ("atanh", x.atanh(), (0.8673005276940531, 2.6798989803716658e-17)),
        ("acosh", f(1.5).acosh(), (0.9624236501192069, -4.651563402692547e-17)),
        ("cosh", x.cosh(), (1.255169005630943, -3.986629140481058e-17)),
        ("exp2", x.exp2(), (1.624504792712471, 4.8844282126282756e-17)),
        ("log2", x.log2(), (-0.5145731728297583, 8.76352077439819e-18)),
        ("log10", x.log10(), (-0.1549019599857432, -9.586393079652633e-18)),
        ("powf", x.powf(f(2.5)), (0.409963413001697, -2.1147976179140544e-17)),
        ("hypot", f(0.3).hypot(f(0.4)), (0.5, 1.1102230246251566e-17)),
        ("cbrt", f(-0.7).cbrt(), (-0.8879040017426006, -4.3733757090121296e-17)),
    ];
    for (name, got, (h, l)) in table {
        close(name, got / dd(h, l), Dd::one(), 1e-30);
    }
    close("powi", x.powi(-3) * x.powi(3), Dd::one(), 1e-31);
    close("powf of a negative base", f(-2.0).powf(f(3.0)), f(-8.0), 0.0);
}

#[test]
#[allow(clippy::float_cmp)] // exact values
fn rounding_and_integers_are_exact() {
    let f = Dd::from_f64;
    // 4 - 2^-60 (hi = 4, lo < 0): floor 3, ceil 4, round 4, trunc 3
    let x = f(4.0) - f(2f64.powi(-60));
    assert_eq!(
        (
            x.floor().to_f64(),
            x.ceil().to_f64(),
            x.round().to_f64(),
            x.trunc().to_f64()
        ),
        (3.0, 4.0, 4.0, 3.0)
    );
    assert_eq!(
        ((f(3.0) + f(0.5)).round().to_f64(), (f(-2.5)).round().to_f64()),
        (4.0, -3.0)
    );
    assert_eq!(((-x).trunc().to_f64(), (-x).floor().to_f64()), (-3.0, -4.0));
    close("fract", x.fract(), f(1.0) - f(2f64.powi(-60)), 0.0);
    close("rem", f(7.5) % f(2.0), f(1.5), 0.0);
    // i64 and u64 beyond 2^53, exactly
    let big = <Dd as num_traits::FromPrimitive>::from_i64(i64::MAX).unwrap();
    assert_eq!((big.hi, big.lo), (9223372036854775808.0, -1.0));
    let big = <Dd as num_traits::FromPrimitive>::from_u64((1 << 60) + 1).unwrap();
    assert_eq!((big.hi, big.lo), (2f64.powi(60), 1.0));
}

#[test]
fn decimals_are_read_to_the_last_digit() {
    let x = Dd::from_str_radix("0.0711334264982231177779387300061549964174", 10).unwrap();
    close("parsed", x, dd(0.07113342649822312, 2.6359775707815623e-18), 1e-31);
    let y = Dd::from_str_radix("-25.5e-1", 10).unwrap();
    close("parsed", y, Dd::from_f64(-2.55) + (y - Dd::from_f64(-2.55)), 0.0);
    assert!((y.to_f64() + 2.55).abs() < 1e-15);
    assert!(Dd::from_str_radix("1.2.3", 10).is_err() && Dd::from_str_radix("12", 16).is_err());
}

#[test]
fn non_finite_values_behave_as_in_f64() {
    let (zero, one) = (Dd::from_f64(0.0), Dd::one());
    let inf = one / zero;
    assert!(inf.hi == f64::INFINITY && inf > Dd::from_f64(f64::MAX) && !inf.is_finite());
    assert!((inf - inf).hi.is_nan() && (zero / zero).hi.is_nan() && (one / inf).hi == 0.0);
    assert!((inf * zero).hi.is_nan() && Dd::from_f64(-1.0).sqrt().hi.is_nan());
    assert!(Dd::from_f64(800.0).exp().hi == f64::INFINITY);
    let nan = zero / zero;
    assert!(nan.partial_cmp(&one).is_none() && nan != nan);
}

/// nalgebra's generic linear algebra and the crate's own generic code run on it, at its
/// precision: a matrix inverse, the Stumpff functions (`c0(x^2) = cos x`), and the Kepler
/// drift (`drift(a) o drift(b) = drift(a + b)`, energy conserved) to ~1e-30.
#[test]
fn generic_code_runs_at_double_double_precision() {
    let f = Dd::from_f64;
    let m = Matrix3::new(f(4.0), f(1.0), f(0.5), f(1.0), f(3.0), f(0.2), f(0.5), f(0.2), f(2.0));
    let product = m * m.try_inverse().unwrap();
    assert!((product - Matrix3::identity())
        .iter()
        .all(|e| ComplexField::abs(*e).to_f64() < 1e-30));

    let x = dd(2.5, -1.1e-16);
    let [c0, c1, c2, c3] = stumpff(x * x);
    close("c0", c0, x.cos(), 1e-30);
    close("c1", c1, x.sin() / x, 1e-30);
    close("c2", c2, (Dd::one() - x.cos()) / (x * x), 1e-30);
    close("c3", c3, (x - x.sin()) / (x * x * x), 1e-30);
    // the series side (|z| <= 1, no quartering)
    let x = f(0.75);
    let [c0, c1, c2, c3] = stumpff(x * x);
    close("c0", c0, x.cos(), 1e-31);
    close("c1", c1, x.sin() / x, 1e-31);
    close("c2", c2, (Dd::one() - x.cos()) / (x * x), 1e-31);
    close("c3", c3, (x - x.sin()) / (x * x * x), 1e-31);

    let kepler = KeplerDrift::new(Dd::one());
    let (q0, v0) = ([f(1.0), f(0.1), f(0.0)], [f(0.05), f(1.1), f(0.2)]);
    let (mut q, mut v) = (q0, v0);
    kepler.apply(f(0.75), &mut q, &mut v);
    kepler.apply(f(1.875), &mut q, &mut v);
    let (mut q1, mut v1) = (q0, v0);
    kepler.apply(f(2.625), &mut q1, &mut v1);
    for i in 0..3 {
        close("q", q[i], q1[i], 1e-30);
        close("v", v[i], v1[i], 1e-30);
    }
    close("energy", kepler.energy(&q, &v), kepler.energy(&q0, &v0), 1e-30);
    assert!(<Dd as RealField>::max(f(1.0), f(2.0)) == f(2.0));
}
