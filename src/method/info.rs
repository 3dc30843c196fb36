//! Static description of a method: its coefficients and what is derived from them.

pub use stormer_order::Flags;

/// The coefficients of a Butcher tableau as compiled into the binary by [`crate::tableau!`].
///
/// Values are the `f64` nearest to each declared expression; `a` is row-major `s x s`.
#[derive(Debug, Clone, Copy)]
pub struct TableauData {
    /// Catalog name, e.g. `"rk4"`.
    pub name: &'static str,
    /// Declared (and verified) order of `b`.
    pub order: usize,
    /// Declared (and verified) order of `b_hat`.
    pub embedded_order: Option<usize>,
    /// Number of stages `s`.
    pub stages: usize,
    /// Stage matrix, row-major.
    pub a: &'static [f64],
    /// Weights.
    pub b: &'static [f64],
    /// Nodes.
    pub c: &'static [f64],
    /// Embedded weights (error estimate `h sum (b_i - b_hat_i) k_i`).
    pub b_hat: Option<&'static [f64]>,
    /// DOP853's second, third-order embedded weights.
    pub b_hat3: Option<&'static [f64]>,
    /// The tolerance factor of the order-condition checks, when the declaration set one.
    pub tolerance: Option<f64>,
    /// The method's own dense output, when the declaration gives one.
    pub dense: Option<DenseData>,
    /// Flags derived from the data at compile time.
    pub flags: Flags,
}

/// A method's own dense output as compiled in: `y(t + theta h) = y + h sum_i b_i(theta) k_i`
/// with `b_i(theta) = sum_k d[i][k - 1] theta^k`, checked against the continuous order
/// conditions up to `order` (`stormer_order::dense`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DenseData {
    /// Its order between steps.
    pub order: usize,
    /// The highest power of theta, `m`.
    pub powers: usize,
    /// The coefficients, `(s + e) x m` row-major: stage `i`'s at `i * m ..`.
    pub d: &'static [f64],
    /// Nodes of the `e` stages the dense output adds after the step (none for most).
    pub c: &'static [f64],
    /// Their rows of the stage matrix, `e x (s + e)` row-major.
    pub a: &'static [f64],
}

/// One row of the method table (`stormer methods`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MethodInfo {
    /// Catalog name.
    pub name: String,
    /// `"butcher"`, later `"splitting"` or `"composition"`.
    pub family: &'static str,
    /// Order.
    pub order: usize,
    /// Stages (right-hand-side evaluations of one step, before FSAL reuse).
    pub stages: usize,
    /// Embedded order, if the method estimates its error.
    pub embedded_order: Option<usize>,
    /// Order of the method's own dense output, if it has one (else the driver's cubic
    /// Hermite interpolant serves, order [`crate::driver::hermite_order`] of the method's order).
    pub dense_order: Option<usize>,
    /// Derived flags.
    pub flags: Flags,
}

impl TableauData {
    /// The table row of this method.
    pub fn info(&self) -> MethodInfo {
        MethodInfo {
            name: self.name.to_string(),
            family: "butcher",
            order: self.order,
            stages: self.stages,
            embedded_order: self.embedded_order,
            dense_order: self.dense.map(|d| d.order),
            flags: self.flags,
        }
    }
}
