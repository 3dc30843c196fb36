//! The catalog's generated steppers, chosen at run time: opt-in, because it compiles every
//! catalog method for the caller's problem type.
//!
//! [`Method::stepper_for`] builds a catalog method's stepper from its data (the run-time
//! steppers, bitwise equal to the generated ones: tests/methods/compiled_vs_runtime.rs), which
//! compiles three stepper types per problem type. The functions here dispatch a catalog
//! method to its generated, unrolled stepper instead (the explicit Runge-Kutta methods run
//! up to 1.6x faster, docs/benchmarks.md), at the price of compiling all of them for `P`:
//! about ten seconds of release build per problem type (docs/build-shape.md). A method is
//! the catalog's only when it is the catalog's own entry ([`Method::named`]): a tableau
//! declared elsewhere under a catalog name runs its own coefficients.

use crate::catalog::{BUTCHER, SPLITTING};
use crate::flows::{QuadraticKinetic, Splittable};
use crate::method::{ButcherMethod, SplittingMethod, StepperResult, TableauData};
use crate::method::{SplittingData, SplittingSource};
use crate::stepper::{ImplicitOptions, SplittingStepper};
use crate::{catalog, Method, Problem};

/// The index of `data` in `table` when it is that table's own entry (the same address,
/// not merely the same name).
fn catalog_entry<T>(table: &'static [T], data: &T) -> Option<usize> {
    table.iter().position(|entry| std::ptr::eq(entry, data))
}

macro_rules! tableau_dispatch {
    ($($method:ident),* $(,)?) => {
        /// The generated stepper of catalog entry `index` of [`BUTCHER`].
        fn generated_tableau<P>(index: usize, y0: &P::State, implicit: &ImplicitOptions) -> StepperResult<P>
        where
            P: Problem + 'static,
        {
            let name = BUTCHER[index].name;
            $(
                if name == <catalog::$method as ButcherMethod>::DATA.name {
                    return Ok(<catalog::$method as ButcherMethod>::dyn_stepper::<P>(y0, implicit));
                }
            )*
            unreachable!("every entry of BUTCHER is a catalog type")
        }
    };
}

macro_rules! splitting_dispatch {
    (general: [$($g:ident),* $(,)?], quadratic: [$($r:ident),* $(,)?] $(,)?) => {
        /// The generated stepper of the general splitting at `index` of [`SPLITTING`];
        /// `None` for a Runge-Kutta-Nystrom one.
        fn generated_general_splitting<P>(index: usize, y0: &P::State) -> Option<StepperResult<P>>
        where
            P: Splittable + 'static,
        {
            let name = SPLITTING[index].name;
            $(
                if name == <catalog::$g as SplittingMethod>::DATA.name {
                    return Some(SplittingStepper::<catalog::$g, P::State, P::FlowCache>::boxed::<P>(y0));
                }
            )*
            None
        }

        /// The generated stepper of any splitting at `index` of [`SPLITTING`], on a
        /// quadratic kinetic energy.
        fn generated_splitting<P>(index: usize, y0: &P::State) -> StepperResult<P>
        where
            P: QuadraticKinetic + 'static,
        {
            let name = SPLITTING[index].name;
            $(
                if name == <catalog::$r as SplittingMethod>::DATA.name {
                    return SplittingStepper::<catalog::$r, P::State, P::FlowCache>::boxed::<P>(y0);
                }
            )*
            match generated_general_splitting::<P>(index, y0) {
                Some(stepper) => stepper,
                None => unreachable!("every entry of SPLITTING is a catalog type"),
            }
        }
    };
}

catalog::for_each_butcher_method!(tableau_dispatch);
catalog::for_each_splitting_method!(splitting_dispatch);

/// The catalog entry of a compiled tableau, when it is one.
fn tableau_entry(method: &Method) -> Option<usize> {
    match method {
        Method::Tableau(data) => catalog_entry::<TableauData>(BUTCHER, data),
        _ => None,
    }
}

/// A catalog splitting's data and its entry, when `method` is one.
fn splitting_entry(method: &Method) -> Option<(&'static SplittingData, usize)> {
    match method {
        Method::Splitting(data) => Some((*data, catalog_entry::<SplittingData>(SPLITTING, data)?)),
        _ => None,
    }
}

impl Method {
    /// [`Method::stepper_for`], with a catalog tableau run by its generated, unrolled
    /// stepper. Compiles every catalog tableau for `P`: call it where the step's speed
    /// matters more than the build's (see the module's documentation).
    ///
    /// ```
    /// use stormer::{Method, Problem};
    ///
    /// struct Decay; // y' = -y
    /// impl Problem for Decay {
    ///     type Scalar = f64;
    ///     type State = [f64; 1];
    ///     fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) { dy[0] = -y[0]; }
    /// }
    /// let rk4 = Method::named("rk4").unwrap();
    /// let mut generated = rk4.compiled_stepper_for(&Decay, &[1.0], &Default::default()).unwrap();
    /// let mut from_data = rk4.stepper_for(&Decay, &[1.0], &Default::default()).unwrap();
    /// let (mut a, mut b) = ([0.0], [0.0]);
    /// generated.step(&Decay, 0.0, 0.1, &[1.0], &mut a).unwrap();
    /// from_data.step(&Decay, 0.0, 0.1, &[1.0], &mut b).unwrap();
    /// assert_eq!(a[0].to_bits(), b[0].to_bits());
    /// ```
    pub fn compiled_stepper_for<P>(&self, problem: &P, y0: &P::State, implicit: &ImplicitOptions) -> StepperResult<P>
    where
        P: Problem + 'static,
    {
        match tableau_entry(self) {
            Some(index) => generated_tableau::<P>(index, y0, implicit),
            None => self.stepper_for(problem, y0, implicit),
        }
    }

    /// [`Method::compiled_stepper_for`] on a splittable problem: a catalog splitting or
    /// composition the problem admits runs by its generated stepper too. Compiles every
    /// general catalog splitting for `P`.
    pub fn compiled_stepper_for_splittable<P>(
        &self,
        problem: &P,
        y0: &P::State,
        implicit: &ImplicitOptions,
    ) -> StepperResult<P>
    where
        P: Splittable + 'static,
    {
        self.compiled_splitting_or_tableau(problem, y0, implicit, generated_general_splitting::<P>)
    }

    /// [`Method::compiled_stepper_for`] on a problem with a quadratic kinetic energy: every
    /// catalog splitting and composition, Runge-Kutta-Nystrom ones included, runs by its
    /// generated stepper. Compiles every catalog method for `P`.
    pub fn compiled_stepper_for_quadratic<P>(
        &self,
        problem: &P,
        y0: &P::State,
        implicit: &ImplicitOptions,
    ) -> StepperResult<P>
    where
        P: QuadraticKinetic + 'static,
    {
        self.compiled_splitting_or_tableau(problem, y0, implicit, |index, y0| {
            Some(generated_splitting::<P>(index, y0))
        })
    }

    /// A catalog splitting or composition the problem admits, run by `generated` (its
    /// generated stepper for catalog entry `index`, `None` where there is none for `P`);
    /// anything else as [`Method::compiled_stepper_for`].
    fn compiled_splitting_or_tableau<P>(
        &self,
        problem: &P,
        y0: &P::State,
        implicit: &ImplicitOptions,
        generated: fn(usize, &P::State) -> Option<StepperResult<P>>,
    ) -> StepperResult<P>
    where
        P: Splittable + 'static,
    {
        if let Some((data, index)) = splitting_entry(self) {
            problem.families().admit_splitting(SplittingSource::Compiled(data))?;
            if let Some(stepper) = generated(index, y0) {
                return stepper;
            }
        }
        self.compiled_stepper_for(problem, y0, implicit)
    }
}

#[cfg(test)]
mod tests {
    use crate::{Method, Problem};

    crate::tableau! {
        /// Heun's third-order method, declared under the catalog's name "rk4".
        struct NamedLikeRk4 {
            name: "rk4",
            order: 3,
            c: [0, 1/3, 2/3],
            a: [[0, 0, 0], [1/3, 0, 0], [0, 2/3, 0]],
            b: [1/4, 0, 3/4],
        }
    }

    /// y' = y t: not linear in t, so third- and fourth-order methods differ in one step.
    struct Growth;
    impl Problem for Growth {
        type Scalar = f64;
        type State = [f64; 1];
        fn rhs(&self, t: f64, y: &[f64; 1], dy: &mut [f64; 1]) {
            dy[0] = y[0] * t * t;
        }
    }

    fn one_step(method: &Method, compiled: bool) -> f64 {
        let options = Default::default();
        let mut stepper = if compiled {
            method.compiled_stepper_for(&Growth, &[1.0], &options).unwrap()
        } else {
            method.stepper_for(&Growth, &[1.0], &options).unwrap()
        };
        let mut y = [0.0];
        stepper.step(&Growth, 0.5, 0.5, &[1.0], &mut y).unwrap();
        y[0]
    }

    /// A user's tableau named like a catalog method runs its own coefficients on both
    /// routes: the compiled dispatch recognises the catalog's entries by address, not by
    /// name.
    #[test]
    fn a_tableau_named_like_a_catalog_method_runs_its_own_coefficients() {
        use crate::method::ButcherMethod;
        let users = Method::Tableau(&<NamedLikeRk4 as ButcherMethod>::DATA);
        let catalog = Method::named("rk4").unwrap();
        let (own, catalog_rk4) = (one_step(&users, false), one_step(&catalog, false));
        assert_ne!(
            own.to_bits(),
            catalog_rk4.to_bits(),
            "the two methods differ on this step"
        );
        assert_eq!(one_step(&users, true).to_bits(), own.to_bits());
        assert_eq!(one_step(&catalog, true).to_bits(), catalog_rk4.to_bits());
        // Heun 3 by hand: k1 = f(t, y), k2 = f(t + h/3, y + h k1/3), k3 = f(t + 2h/3, y + 2h k2/3)
        let (t, h, y) = (0.5f64, 0.5f64, 1.0f64);
        let f = |t: f64, y: f64| y * t * t;
        let k1 = f(t, y);
        let k2 = f(t + h / 3.0, y + h * k1 / 3.0);
        let k3 = f(t + 2.0 * h / 3.0, y + 2.0 * h * k2 / 3.0);
        let heun3 = y + h * (k1 / 4.0 + 3.0 * k3 / 4.0);
        assert!((own - heun3).abs() < 1e-15, "{own} against {heun3}");
    }
}
