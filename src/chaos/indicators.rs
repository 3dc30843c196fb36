//! MEGNO, its running mean, the maximal Lyapunov exponent and the fast Lyapunov indicator,
//! from the growth of a variation step by step.

/// The chaos indicators of one orbit, updated after every step from the variation's
/// growth over that step.
///
/// With `l(t) = ln(|delta(t)| / |delta(0)|)` known at the ends of each step, `t` the time
/// since the start and `h` the step:
///
/// - **MEGNO** (Cincotta & Simo 2000) `Y(t) = (2/t) int_0^t s dl(s)`, summed as
///   `sum 2 t_mid (l_k - l_{k-1})` (exact when `l` is linear over each step; REBOUND sums
///   `2 t (delta' . delta / delta^2) h` instead, the same integral);
/// - its **running mean** `<Y>(t) = (1/t) int_0^t Y(s) ds`, summed as `sum Y(t_k) h`. The
///   verdict: `<Y>` tends to 0 for a stable periodic orbit (a harmonic oscillator), to 2 for
///   a quasi-periodic one (a Kepler orbit, an island of Henon-Heiles), and grows like
///   `lambda t / 2` for a chaotic one; REBOUND's MEGNO maps call below 2.5 regular;
/// - the **maximal Lyapunov exponent** `lambda(t) = l(t) / t`: it tends to 0 for a regular
///   orbit (like `ln t / t`) and to the exponent for a chaotic one; read it over time, the
///   estimate converges slowly;
/// - the **fast Lyapunov indicator** (Froeschle, Lega & Gonczi 1997) `FLI(t) = max_{s <= t}
///   log10 |delta(s)| / |delta(0)|`: linear in `log t` for a regular orbit, linear in `t`
///   for a chaotic one.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Indicators {
    /// Time since the start.
    elapsed: f64,
    /// `l(t)`, the natural log of the variation's growth since the start.
    log_growth: f64,
    /// `int_0^t 2 s dl(s)`.
    megno_integral: f64,
    /// `int_0^t Y(s) ds`.
    megno_mean_integral: f64,
    /// `max_{s <= t} l(s)`.
    max_log_growth: f64,
    steps: u64,
}

impl Indicators {
    /// Nothing measured yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// One step, ending `elapsed` after the start (given, not summed from the steps, so
    /// that no rounding accumulates), after which the variation's growth since the start
    /// is `exp(log_growth)`.
    pub fn record(&mut self, elapsed: f64, log_growth: f64) {
        let h = elapsed - self.elapsed;
        let mid = self.elapsed + 0.5 * h;
        self.megno_integral += 2.0 * mid * (log_growth - self.log_growth);
        self.elapsed = elapsed;
        self.megno_mean_integral += self.megno_integral / self.elapsed * h;
        self.log_growth = log_growth;
        self.max_log_growth = self.max_log_growth.max(log_growth);
        self.steps += 1;
    }

    /// [`Indicators::record`] with MEGNO summed as REBOUND sums it: `2 h t rate` for a step
    /// of length `h` ending at `t = elapsed`, `rate` the variation's growth rate
    /// `(delta . delta') / |delta|^2` there.
    pub fn record_with_rate(&mut self, elapsed: f64, log_growth: f64, rate: f64) {
        let h = elapsed - self.elapsed;
        self.megno_integral += 2.0 * h * elapsed * rate;
        self.elapsed = elapsed;
        self.megno_mean_integral += self.megno_integral / self.elapsed * h;
        self.log_growth = log_growth;
        self.max_log_growth = self.max_log_growth.max(log_growth);
        self.steps += 1;
    }

    /// `Y(t)`, MEGNO at the last step (0 before the first).
    pub fn megno(&self) -> f64 {
        self.per_time(self.megno_integral)
    }

    /// `<Y>(t)`, the running mean of MEGNO: the number a MEGNO map shows.
    pub fn mean_megno(&self) -> f64 {
        self.per_time(self.megno_mean_integral)
    }

    /// `l(t) / t`, the estimate of the maximal Lyapunov exponent at the last step.
    pub fn lyapunov(&self) -> f64 {
        self.per_time(self.log_growth)
    }

    /// `max log10` of the variation's growth so far: the fast Lyapunov indicator.
    pub fn fli(&self) -> f64 {
        self.max_log_growth / core::f64::consts::LN_10
    }

    /// `ln(|delta(t)| / |delta(0)|)`.
    pub fn log_growth(&self) -> f64 {
        self.log_growth
    }

    /// Time since the start.
    pub fn elapsed(&self) -> f64 {
        self.elapsed
    }

    /// Steps recorded.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    fn per_time(&self, x: f64) -> f64 {
        if self.elapsed > 0.0 {
            x / self.elapsed
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Indicators;

    /// Growth like t (a regular orbit's shear): Y tends to 2 and so does its mean; growth
    /// like exp(lambda t): Y and its mean grow like lambda t and lambda t / 2.
    #[test]
    fn linear_growth_gives_two_and_exponential_growth_grows() {
        let (h, n) = (0.01, 1_000_000);
        let mut linear = Indicators::new();
        let mut exponential = Indicators::new();
        for k in 1..=n {
            let t = k as f64 * h;
            linear.record(t, (1.0 + t).ln());
            exponential.record(t, 0.3 * t);
        }
        assert!((linear.megno() - 2.0).abs() < 2e-3, "{}", linear.megno());
        assert!((linear.mean_megno() - 2.0).abs() < 2e-2, "{}", linear.mean_megno());
        assert!(linear.lyapunov() < 1e-3);
        let t = n as f64 * h;
        assert!((exponential.megno() - 0.3 * t).abs() < 1e-6 * t);
        assert!((exponential.mean_megno() - 0.15 * t).abs() < 1e-3 * t);
        assert!((exponential.lyapunov() - 0.3).abs() < 1e-12);
        assert!((exponential.fli() - 0.3 * t / std::f64::consts::LN_10).abs() < 1e-9 * t);
    }

    /// A bounded, oscillating growth (a stable periodic orbit): the mean MEGNO tends to 0.
    #[test]
    fn bounded_growth_gives_zero() {
        let mut bounded = Indicators::new();
        let h = 0.01;
        for k in 1..=1_000_000 {
            let t = k as f64 * h;
            bounded.record(t, t.sin().abs().ln_1p());
        }
        assert!(bounded.mean_megno().abs() < 1e-3, "{}", bounded.mean_megno());
    }
}
