//! The whole verification of one method on the test problems: what `stormer verify`
//! prints and the crate's own tests assert.

use super::problems::{kepler_planets, HenonHeiles, Pendulum, QuarticKinetic, KEPLER_PLANETS_STATES};
use super::{
    defect_bound, jacobian_dual, jacobian_fd, measure_global_order, measure_order, reversibility_defect, step_once,
    symplectic_defect, Canonical, GlobalOrderOptions, OrderMeasurement, OrderOptions, Precision,
};
use crate::method::MethodInfo;
use crate::real::lit;
use crate::stepper::ImplicitOptions;
use crate::{Error, Method, Problem};
use num_dual::Dual64;
use stormer_order::stability::Interval;

/// A step is symplectic to round-off when `max |J^T S J - S| <= SYMPLECTIC_FACTOR eps
/// max(1, |J|)^2` ([`defect_bound`]), `J` computed on dual numbers.
///
/// Measured by [`report`] on the whole catalog (`docs/verification.md`): the symplectic
/// methods stay below `6 eps |J|^2` (the largest is the 35-stage `sofroniou_spaletta10`),
/// the least non-symplectic one, `verner9`, is at `1e6 eps |J|^2`. 100 leaves a factor
/// 15 of headroom on one side and `1e4` on the other.
pub const SYMPLECTIC_FACTOR: f64 = 100.0;

/// A method is reversible to round-off when the distance after a step of `h` and one of
/// `-h` is at most `REVERSIBLE_FACTOR eps max(1, |y|)`. Measured on the catalog: the
/// symmetric methods stay below `26 eps` (`lobatto_iiib4`; the splittings below `3 eps`),
/// the non-symmetric ones are above `1e5 eps` (`verner9`).
pub const REVERSIBLE_FACTOR: f64 = 100.0;

/// Where a check was worst: a test problem, a state and a step.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// `"pendulum"`, `"henon_heiles"`, `"quartic_kinetic"` or (splittings and
    /// compositions) `"kepler_planets"`.
    pub problem: &'static str,
    /// The state `(q, p)` stepped from.
    pub state: Vec<f64>,
    /// The step.
    pub h: f64,
}

/// A numerical check: its largest defect relative to its bound, over all cases.
#[derive(Debug, Clone, PartialEq)]
pub struct Check {
    /// The defect of the worst case (the largest `defect / bound`).
    pub defect: f64,
    /// That case's bound.
    pub bound: f64,
    /// Every case is within its bound.
    pub holds: bool,
    /// The worst case.
    pub case: Case,
}

/// Which error an order was measured from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OrderError {
    /// The centred local error of [`measure_order`] (splittings and compositions).
    CentredLocal,
    /// The global error at `t = 1` from `t = -1` of [`measure_global_order`] on the tree
    /// system (Butcher tableaus).
    Global,
}

/// What the verification suite measured on a method.
#[derive(Debug, Clone)]
pub struct Report {
    /// The method.
    pub info: MethodInfo,
    /// The measured order, or why it could not be measured.
    pub order: Result<OrderMeasurement, Error>,
    /// The problem the order was measured on: `"tree_system"` for a Butcher tableau
    /// ([`TreeSystem::for_order`](super::problems::TreeSystem::for_order) of the declared
    /// order), `"quartic_kinetic"` for a general splitting or composition,
    /// `"henon_heiles"` for one that needs a quadratic kinetic energy.
    pub order_problem: &'static str,
    /// Which error [`Report::order`] was measured from.
    pub order_error: OrderError,
    /// For a tableau with an embedded solution, its order measured like the main one
    /// (on the tree system of the embedded order).
    pub embedded_order: Option<Result<OrderMeasurement, Error>>,
    /// The linear stability interval on the imaginary axis, from the coefficients
    /// ([`Method::stability_interval`]): the largest `h omega` at which a step does not
    /// grow on the harmonic oscillator `q'' = -omega^2 q`.
    pub stability: Interval,
    /// `max |J^T S J - S|` with the exact (dual-number) Jacobian.
    pub symplectic: Check,
    /// The largest `max |J^T S J - S|` with the central-difference Jacobian (accurate to
    /// `~eps^(2/3)`: an independent check of the dual numbers, not a verdict).
    pub symplectic_defect_central: f64,
    /// A step of `h` then `-h`.
    pub reversible: Check,
    /// For a Butcher tableau, the residual of `b_i a_ij + b_j a_ji = b_i b_j`.
    pub symplectic_condition_residual: Option<f64>,
}

/// The state and step grid of the symplecticity and reversibility checks.
const STEPS: [f64; 2] = [0.1, 0.4];
const PENDULUM_STATES: [[f64; 2]; 2] = [[1.0, 0.5], [-2.0, 0.8]];
const PLANAR_STATES: [[f64; 4]; 2] = [[0.1, -0.2, 0.3, 0.2], [-0.2, 0.25, 0.1, -0.35]];

/// Runs every check on `method` (implicit tableaus with [`ImplicitOptions::newton`]): the measured order (for a Butcher tableau, of the main
/// and the embedded solution from the global error on the tree system,
/// [`measure_global_order`]; for a splitting or composition, from the centred local error,
/// [`measure_order`], on [`QuarticKinetic`] for a general method, [`HenonHeiles`] for one
/// that needs a quadratic kinetic energy), the stability interval, symplecticity
/// (exact and central-difference Jacobians) and reversibility on [`Pendulum`],
/// [`HenonHeiles`], (general methods) [`QuarticKinetic`] and (splittings and
/// compositions) [`KeplerPlanets`](super::problems::KeplerPlanets), whose drift is the
/// exact Kepler flow, at two states each and `h = 0.1, 0.4`.
///
/// ```
/// use stormer::Method;
/// use stormer::verify::report;
/// let r = report(&Method::named("rk4").unwrap()).unwrap();
/// assert!((r.order.unwrap().order - 4.0).abs() < 0.2);
/// assert!(!r.symplectic.holds && !r.reversible.holds);
/// ```
pub fn report(method: &Method) -> Result<Report, Error> {
    let general = !method.requires_quadratic_kinetic();
    let mut cases: Vec<Outcome> = Vec::new();
    let pendulum = (Pendulum::<f64>::new(), Pendulum::<Dual64>::new());
    for y in PENDULUM_STATES {
        for h in STEPS {
            cases.push(case(method, "pendulum", (&pendulum.0, &pendulum.1), y, h)?);
        }
    }
    let henon_heiles = (HenonHeiles::<f64>::new(), HenonHeiles::<Dual64>::new());
    let quartic_kinetic = (QuarticKinetic::<f64>::new(), QuarticKinetic::<Dual64>::new());
    for y in PLANAR_STATES {
        for h in STEPS {
            cases.push(case(method, "henon_heiles", (&henon_heiles.0, &henon_heiles.1), y, h)?);
            if general {
                let problems = (&quartic_kinetic.0, &quartic_kinetic.1);
                cases.push(case(method, "quartic_kinetic", problems, y, h)?);
            }
        }
    }
    if method.splitting_source().is_some() {
        // through the exact Kepler drift (a splitting's drift is its sub-flow)
        let planets = (kepler_planets::<f64>(), kepler_planets::<Dual64>());
        for y in KEPLER_PLANETS_STATES {
            for h in STEPS {
                cases.push(case(method, "kepler_planets", (&planets.0, &planets.1), y, h)?);
            }
        }
    }
    let worst = |pick: fn(&Outcome) -> (f64, f64)| {
        let (mut best, mut ratio) = (0, f64::NEG_INFINITY);
        for (i, c) in cases.iter().enumerate() {
            let (d, b) = pick(c);
            // NaN counts as the worst
            let r = if (d / b).is_nan() { f64::INFINITY } else { d / b };
            if r > ratio {
                (best, ratio) = (i, r);
            }
        }
        let (defect, bound) = pick(&cases[best]);
        Check {
            defect,
            bound,
            holds: ratio <= 1.0,
            case: cases[best].case.clone(),
        }
    };
    let symplectic = worst(|c| (c.symplectic, c.symplectic_bound));
    let reversible = worst(|c| (c.reversibility, c.reversibility_bound));
    let symplectic_defect_central = cases.iter().map(|c| c.central).fold(0.0, f64::max);
    let tableau = method.tableau().transpose()?;
    let global = |method: &Method, order: usize| {
        measure_global_order(method, order, Precision::F64, &GlobalOrderOptions::default())
    };
    let (order, order_problem, order_error) = if tableau.is_some() {
        (global(method, method.info().order), "tree_system", OrderError::Global)
    } else if general {
        let y = QuarticKinetic::<f64>::initial();
        let mut stepper = method.stepper_for(&QuarticKinetic::new(), &y, &ImplicitOptions::newton())?;
        let m = measure_order(&mut stepper, &QuarticKinetic::new(), 0.0, &y, &OrderOptions::default());
        (m, "quartic_kinetic", OrderError::CentredLocal)
    } else {
        let y = HenonHeiles::<f64>::initial();
        let mut stepper = method.stepper_for(&HenonHeiles::new(), &y, &ImplicitOptions::newton())?;
        let m = measure_order(&mut stepper, &HenonHeiles::new(), 0.0, &y, &OrderOptions::default());
        (m, "henon_heiles", OrderError::CentredLocal)
    };
    let embedded_order = match tableau.as_ref().and_then(|t| t.embedded_as_main()) {
        Some(embedded) => {
            let embedded = embedded?;
            let order = embedded.order();
            Some(global(&Method::from(embedded), order))
        }
        None => None,
    };
    let symplectic_condition_residual = tableau
        .as_ref()
        .map(|t| stormer_order::tableau::symplectic_residual(t.a(), t.b()));
    Ok(Report {
        info: method.info(),
        order,
        order_problem,
        order_error,
        embedded_order,
        stability: method.stability_interval(),
        symplectic,
        symplectic_defect_central,
        reversible,
        symplectic_condition_residual,
    })
}

/// The checks at one problem, state and step.
struct Outcome {
    case: Case,
    symplectic: f64,
    symplectic_bound: f64,
    central: f64,
    reversibility: f64,
    reversibility_bound: f64,
}

/// The checks at one problem (named `problem`; `p` in `f64`, `d` the same on dual numbers),
/// state and step. Building the steppers can fail (an RKN method on a general problem is
/// not asked for); a step that fails (non-finite state, an implicit solver that does not
/// converge) makes that check fail with an infinite defect, so that an unstable user
/// method still gets its report.
fn case<P, D, const N: usize>(
    method: &Method,
    problem: &'static str,
    (p, d): (&P, &D),
    y: [f64; N],
    h: f64,
) -> Result<Outcome, Error>
where
    P: Problem<Scalar = f64, State = [f64; N]> + 'static,
    D: Problem<Scalar = Dual64, State = [Dual64; N]> + 'static,
{
    let yd: [Dual64; N] = y.map(lit);
    let newton = ImplicitOptions::newton();
    let mut exact = method.stepper_for(d, &yd, &newton)?;
    let mut plain = method.stepper_for(p, &y, &newton)?;
    let mut y1 = y;
    let stepped = step_once(&mut plain, p, 0.0, h, &y, &mut y1).is_ok();
    let failed = (f64::INFINITY, SYMPLECTIC_FACTOR * f64::EPSILON);
    let (symplectic, symplectic_bound) = match jacobian_dual(&mut exact, d, 0.0, h, &yd) {
        Ok(j) if stepped => (
            symplectic_defect(&j, &Canonical, y.as_slice(), y1.as_slice()),
            defect_bound(&j, SYMPLECTIC_FACTOR),
        ),
        _ => failed,
    };
    let central = match jacobian_fd(&mut plain, p, 0.0, h, &y) {
        Ok(j) if stepped => symplectic_defect(&j, &Canonical, y.as_slice(), y1.as_slice()),
        _ => f64::INFINITY,
    };
    let scale = y.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    Ok(Outcome {
        case: Case {
            problem,
            state: y.to_vec(),
            h,
        },
        symplectic,
        symplectic_bound,
        central,
        reversibility: reversibility_defect(&mut plain, p, 0.0, h, &y).unwrap_or(f64::INFINITY),
        reversibility_bound: REVERSIBLE_FACTOR * f64::EPSILON * scale,
    })
}
