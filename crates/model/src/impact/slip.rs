//! The tangential slip of a 3-D impact against the normal impulse p.
//!
//! The slip s = (v1, v2) lives in the tangent plane, across the bat (n1) and
//! along it (n2). While it slides, Coulomb friction μ·dp opposes it (Eq. 14
//! in the plane), and Eq. (12)'s inverse inertia is diagonal here (β1 across
//! the bat, where the bat's roll adds to the ball's; β_a along it, where
//! only the ball rolls):
//!
//! ```text
//! ds/dp = −(μ/m)·diag(β1, β_a)·s/|s|
//! ```
//!
//! With β1 > β_a the part across the bat dies faster, so the slip turns
//! toward the bat's axis as it slows. In p the turn rate grows as 1/|s| near
//! the halt, where an integrator in p would crawl; in σ = ∫dp/|s| the slip
//! is exact, v1 = v1(0)·e^(−k1·σ), v2 = v2(0)·e^(−k2·σ) with k = μβ/m, and
//! only p(σ) = ∫|s|dσ is left, a smooth integral of decaying exponentials.
//! Scaled (T = k2·σ, P = k2·p/|s(0)|, r = β1/β_a ≥ 1, â and b̂ the initial
//! slip's direction cosines squared):
//!
//! ```text
//! dP/dT = √(â·e^(−2rT) + b̂·e^(−2T))
//! ```
//!
//! which is integrated by adaptive Gauss–Legendre quadrature
//! (`numerics::quadrature`), the T where P = P_f by Newton's method. The
//! slip halts at P_s = P(∞); the contact then sticks, since the normal and
//! tangential directions do not couple (the stick coefficient μ̄ = 0, as in
//! the plane).

use nalgebra::Vector2;

use numerics::quadrature;
#[cfg(test)]
use numerics::{
    ode::{self, Control, Settings, State, Tolerance},
    roots::find_root_newton,
};

/// T at which the slip counts as halted: e^(−40) ≈ 4e-18, so the rest of
/// the integral is below any double's resolution of P_s ≥ 1/r.
const T_HALT: f64 = 40.0;

/// The ODE pair's tolerance on P (which runs from 0 to at most 1), in the
/// tests' check of the quadrature.
#[cfg(test)]
const TOLERANCE: f64 = 1e-14;

/// The quadrature's tolerance on P (which runs from 0 to at most 1).
const QUADRATURE_TOLERANCE: f64 = 1e-14;

/// The longest piece of T that Newton's steps integrate on one Gauss
/// panel, without halving. dP/dT is analytic but where â·e^(−2rT) +
/// b̂·e^(−2T) vanishes, at |Im T| = π/(2(r − 1)) ≥ 0.5 for r ≤
/// [`ONE_PANEL_RATIO`]. On a piece of 0.25 the 10-point rule's error is
/// then below ρ^(−20) ≈ 7e-19 of the integrand's size (ρ = 8.1, the
/// Bernstein ellipse reaching 0.5 off the real line), times its growth
/// there, e^(2r·0.52) < 75: far under QUADRATURE_TOLERANCE, for a third of
/// the adaptive rule's evaluations (it checks two halves against the whole).
const ONE_PANEL: f64 = 0.25;

/// The largest r = β1/β_a for which [`ONE_PANEL`] holds: 1 + π.
const ONE_PANEL_RATIO: f64 = 1.0 + std::f64::consts::PI;

/// The slip phase of one impact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slip {
    /// s(0) = (v1(0), v2(0)) (m/s).
    pub initial: Vector2<f64>,
    /// k2 = μ·β_a/m (1/kg), the slower decay rate in σ (kg); 0 without
    /// friction.
    rate: f64,
    /// r = β1/β_a.
    ratio: f64,
    /// â, b̂: the squared direction cosines of s(0).
    across: f64,
    along: f64,
}

impl Slip {
    pub fn new(
        initial: Vector2<f64>,
        (beta1, beta_axial): (f64, f64),
        friction: f64,
        pair_mass: f64,
    ) -> Slip {
        let speed = initial.norm();
        let (across, along) = if speed > 0.0 {
            ((initial.x / speed).powi(2), (initial.y / speed).powi(2))
        } else {
            (0.0, 0.0)
        };
        Slip {
            initial,
            rate: friction * beta_axial / pair_mass,
            ratio: beta1 / beta_axial,
            across,
            along,
        }
    }

    /// Whether friction can act at all: some friction and some slip.
    fn slides(&self) -> bool {
        self.rate > 0.0 && self.initial != Vector2::zeros()
    }

    /// p per unit of P.
    fn scale(&self) -> f64 {
        self.initial.norm() / self.rate
    }

    /// dP/dT.
    fn slope(&self, t: f64) -> f64 {
        (self.across * (-2.0 * self.ratio * t).exp() + self.along * (-2.0 * t).exp()).sqrt()
    }

    /// dP/dT and d²P/dT² at T: with f = â·e^(−2rT) + b̂·e^(−2T) under the
    /// root, (√f)' = f'/(2√f).
    fn slope_and_bend(&self, t: f64) -> (f64, f64) {
        let (across, along) = (
            self.across * (-2.0 * self.ratio * t).exp(),
            self.along * (-2.0 * t).exp(),
        );
        let slope = (across + along).sqrt();
        let f_slope = -2.0 * (self.ratio * across + along);
        (slope, f_slope / (2.0 * slope))
    }

    /// The slip at scaled time T.
    fn at_time(&self, t: f64) -> Vector2<f64> {
        Vector2::new(
            self.initial.x * (-self.ratio * t).exp(),
            self.initial.y * (-t).exp(),
        )
    }

    /// The bounds of P_s from max(a, b) ≤ √(a² + b²) ≤ a + b; equal when
    /// the slip starts along n1 or along n2 (then P_s is exact). Otherwise
    /// tightened: with u = e^(−T), P_s = ∫₀¹ √(â·u^(2r−2) + b̂) du, which
    /// is at least √(â/r² + b̂) (|∫v| ≤ ∫|v| for v = (√â·u^(r−1), √b̂))
    /// and at most √(â/(2r−1) + b̂) (Jensen: √ is concave). For β1/β_a
    /// ≈ 1.1 they are within 0.5 % of each other, so a batted ball's
    /// regime is nearly always decided without integrating.
    fn halt_bounds(&self) -> (f64, f64) {
        let (a, b) = (self.across.sqrt() / self.ratio, self.along.sqrt());
        if a == 0.0 || b == 0.0 {
            return (a.max(b), a + b);
        }
        let r = self.ratio;
        let low = (self.across / (r * r) + self.along).sqrt();
        let high = (self.across / (2.0 * r - 1.0) + self.along).sqrt();
        (a.max(b).max(low), (a + b).min(high))
    }

    /// Bounds on p_s (normal impulse), without integrating: equal where
    /// the slip starts along n1 or n2. Only for a sliding slip.
    pub fn halt_impulse_bounds(&self) -> (f64, f64) {
        let (low, high) = self.halt_bounds();
        (low * self.scale(), high * self.scale())
    }

    /// p_s, the normal impulse at which the slip halts: 0 without slip,
    /// infinite without friction (Eq. 17 in the plane).
    pub fn halt_impulse(&self) -> f64 {
        if self.initial == Vector2::zeros() {
            return 0.0;
        }
        if !self.slides() {
            return f64::INFINITY;
        }
        let (low, high) = self.halt_bounds();
        let halt = if low == high {
            low
        } else {
            self.integrate_to(f64::INFINITY).1
        };
        halt * self.scale()
    }

    /// Whether the slip halts at or before normal impulse `impulse`, deciding
    /// from the bounds of p_s when they suffice (a batted ball's slip halts
    /// well before separation, and then no integration is needed).
    pub fn halts_by(&self, impulse: f64) -> bool {
        if self.initial == Vector2::zeros() {
            return true;
        }
        if !self.slides() {
            return false;
        }
        let target = impulse / self.scale();
        let (low, high) = self.halt_bounds();
        if target >= high {
            true
        } else if target < low {
            false
        } else {
            self.time_at(target).is_none()
        }
    }

    /// The slip s(p) at normal impulse `impulse` ≥ 0: zero once it has
    /// halted.
    pub fn at(&self, impulse: f64) -> Vector2<f64> {
        if !self.slides() {
            return self.initial;
        }
        match self.time_at(impulse / self.scale()) {
            Some(t) => self.at_time(t),
            None => Vector2::zeros(),
        }
    }

    /// T at which P reaches `target`, or `None` if the slip halts first.
    /// Closed form when the slip starts along n1 or along n2.
    fn time_at(&self, target: f64) -> Option<f64> {
        if target <= 0.0 {
            return Some(0.0);
        }
        let (low, high) = self.halt_bounds();
        if target >= high || (low == high && target >= low) {
            return None;
        }
        // P < P_s from here on.
        if self.along == 0.0 {
            // P = √â·(1 − e^(−rT))/r.
            return Some(-(-self.ratio * target / self.across.sqrt()).ln_1p() / self.ratio);
        }
        if self.across == 0.0 {
            // P = √b̂·(1 − e^(−T)).
            return Some(-(-target / self.along.sqrt()).ln_1p());
        }
        self.integrate_to(target).0
    }

    /// P from 0 until it reaches `target` (then T there) or to the halt
    /// (then P there, which is P_s), by Gauss–Legendre quadrature of dP/dT,
    /// a smooth integrand of two exponentials: tens of evaluations where
    /// the ODE pair took some 350 steps of six (a tilted bat's slip has
    /// both parts, and the 3-D solve of its swings spent most of its time
    /// here; docs/speed.md). The T at which P reaches `target` by Newton's
    /// method, each P the last plus the piece between.
    fn integrate_to(&self, target: f64) -> (Option<f64>, f64) {
        let slope = |t: f64| self.slope(t);
        let between = |a: f64, b: f64| quadrature::integrate(&slope, a, b, QUADRATURE_TOLERANCE);
        // Below P_s's lower bound the slip cannot have halted, and P_s
        // itself (the longest of the integrals, most of the cost of a
        // glancing swing's solve) is not needed: Newton starts from the
        // bounds' middle, within 0.5 % of it.
        let (low_bound, high_bound) = self.halt_bounds();
        let halt = if target < low_bound {
            None
        } else {
            let halt = between(0.0, T_HALT);
            if target >= halt {
                return (None, halt);
            }
            Some(halt)
        };
        let guess_halt = halt.unwrap_or(0.5 * (low_bound + high_bound));
        // P rises from 0 at T = 0 to P_s, by slope(T) > 0: Newton from the
        // slip's start, kept within the bracket.
        let (mut low, mut high) = (0.0, T_HALT);
        let mut t = (-(1.0 - target / guess_halt).ln()).min(T_HALT);
        let mut at = between(0.0, t);
        for _ in 0..60 {
            let miss = at - target;
            if miss == 0.0 {
                break;
            }
            if miss > 0.0 {
                high = t;
            } else {
                low = t;
            }
            // Halley's step (cubic, where Newton's is quadratic): one
            // piece fewer to integrate, from the same two exponentials.
            let (slope_here, bend) = self.slope_and_bend(t);
            let mut next =
                t - 2.0 * miss * slope_here / (2.0 * slope_here * slope_here - miss * bend);
            if !(next > low && next < high) {
                next = 0.5 * (low + high);
            }
            at += if (next - t).abs() <= ONE_PANEL && self.ratio <= ONE_PANEL_RATIO {
                quadrature::gauss(&slope, t, next)
            } else {
                between(t, next)
            };
            let moved = (next - t).abs();
            t = next;
            if moved <= 1e-15 * t.max(1.0) {
                break;
            }
        }
        (Some(t), halt.map_or(at, |halt| at.min(halt)))
    }

    /// The same by the crate's Dormand–Prince pair, the event found on its
    /// continuous extension: how P was integrated before, kept to check
    /// the quadrature against.
    #[cfg(test)]
    fn integrate_by_ode(&self, target: f64) -> (Option<f64>, f64) {
        let f = |t: f64, _: &State<1>| State::<1>::new(self.slope(t));
        let settings = Settings::new(Tolerance::uniform(TOLERANCE));
        let mut found = None;
        let mut reached = 0.0;
        ode::integrate(f, 0.0, State::<1>::zeros(), T_HALT, &settings, |step| {
            reached = step.y1[0];
            if step.y1[0] < target {
                return Control::Continue;
            }
            let g = |t: f64| (step.at(t)[0] - target, self.slope(t));
            found = Some(find_root_newton(g, step.t0, step.t1, 1e-15));
            Control::Stop
        });
        (found, reached)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BETAS: (f64, f64) = (3.433, 3.125);

    #[test]
    fn a_slip_across_the_bat_halts_as_eq_17_says() {
        let (m, mu, v1) = (0.12275, 0.5, -1.3);
        let slip = Slip::new(Vector2::new(v1, 0.0), BETAS, mu, m);
        let expected = m * v1.abs() / (mu * BETAS.0);
        assert!((slip.halt_impulse() - expected).abs() < 1e-16);
        // Halfway, the slip has lost half of itself: v1 is linear in p.
        let half = slip.at(0.5 * expected);
        assert!((half.x - 0.5 * v1).abs() < 1e-15 && half.y == 0.0);
        assert_eq!(slip.at(expected * 1.000001), Vector2::zeros());
    }

    #[test]
    fn an_oblique_slip_turns_toward_the_bat_and_halts_between_its_bounds() {
        let (m, mu) = (0.12275, 0.5);
        let s0 = Vector2::new(1.0, 1.0);
        let slip = Slip::new(s0, BETAS, mu, m);
        let halt = slip.halt_impulse();
        let (low, high) = slip.halt_bounds();
        let scale = slip.scale();
        assert!(low * scale < halt && halt < high * scale, "{halt}");
        // The angle from n1 grows from 45° toward 90° as the slip slows.
        let angle = |p: f64| {
            let s = slip.at(p);
            s.y.atan2(s.x)
        };
        let mut last = angle(0.0);
        assert!((last - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        for k in 1..10 {
            let now = angle(halt * k as f64 / 10.0);
            assert!(now > last, "{k}: {now} ≤ {last}");
            last = now;
        }
        // `halts_by` decides at p_s itself, to the integral's precision.
        assert!(slip.halts_by(halt * (1.0 + 1e-12)));
        assert!(!slip.halts_by(halt * (1.0 - 1e-12)));
        // P(T) against a quadrature of its own: Simpson on a fine grid.
        let t_end = std::f64::consts::LN_2;
        let n = 2000;
        let h = t_end / n as f64;
        let simpson: f64 = (0..=n)
            .map(|k| {
                let w = if k == 0 || k == n {
                    1.0
                } else if k % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                w * slip.slope(k as f64 * h)
            })
            .sum::<f64>()
            * h
            / 3.0;
        let t = slip.time_at(simpson).unwrap();
        assert!((t - t_end).abs() < 1e-12, "{t} vs {t_end}");
    }

    #[test]
    fn the_halt_lies_between_its_tightened_bounds() {
        for k in 1..40 {
            let angle = std::f64::consts::FRAC_PI_2 * k as f64 / 40.0;
            let slip = Slip::new(Vector2::new(angle.cos(), angle.sin()), BETAS, 0.5, 0.12275);
            let (low, high) = slip.halt_bounds();
            let halt = slip.integrate_to(f64::INFINITY).1;
            assert!(low <= halt && halt <= high, "{angle}: {low} {halt} {high}");
            // Within 0.5 % of each other.
            assert!(high - low < 5e-3 * halt, "{angle}: {low} {high}");
        }
    }

    /// P by quadrature agrees with P by the ODE pair: the halt, and the T
    /// at which P reaches a fifth, half and 0.999 of it, over slips from
    /// across the bat to along it, at the paper's bat's β and others'. And
    /// against mpmath's quadrature to 30 digits.
    #[test]
    fn the_slip_by_quadrature_is_the_slip_by_the_ode() {
        // The last at r just under ONE_PANEL_RATIO, the one-panel pieces'
        // hardest case.
        for betas in [BETAS, (3.6, 3.1), (3.9, 3.1), (6.0, 3.0), (12.4, 3.0)] {
            for k in 1..40 {
                let angle = std::f64::consts::FRAC_PI_2 * k as f64 / 40.0;
                let slip = Slip::new(Vector2::new(angle.cos(), angle.sin()), betas, 0.5, 0.12275);
                let (_, halt) = slip.integrate_to(f64::INFINITY);
                let (_, halt_ode) = slip.integrate_by_ode(f64::INFINITY);
                assert!(
                    (halt - halt_ode).abs() < 1e-13,
                    "{angle}: {halt} {halt_ode}"
                );
                if betas == BETAS && k == 1 {
                    // 0.91043592261731698727 (mpmath); the ODE's is 2.3e-14 off.
                    assert!((halt - 0.910_435_922_617_317).abs() < 1e-14, "{halt}");
                }
                for share in [0.2, 0.5, 0.999] {
                    let target = share * halt_ode;
                    let t = slip.integrate_to(target).0.unwrap();
                    let t_ode = slip.integrate_by_ode(target).0.unwrap();
                    // Apart by less than P's own error, seen through dP/dT
                    // (near the halt T moves far for a small P).
                    let apart = (t - t_ode).abs() * slip.slope(t_ode);
                    assert!(apart < 2e-13, "{angle} {share}: {t} {t_ode}");
                }
            }
        }
    }

    #[test]
    fn without_friction_or_slip_nothing_slides() {
        let slip = Slip::new(Vector2::new(2.0, -1.0), BETAS, 0.0, 0.1);
        assert_eq!(slip.halt_impulse(), f64::INFINITY);
        assert_eq!(slip.at(5.0), Vector2::new(2.0, -1.0));
        assert!(!slip.halts_by(5.0));
        let none = Slip::new(Vector2::zeros(), BETAS, 0.5, 0.1);
        assert_eq!(none.halt_impulse(), 0.0);
        assert!(none.halts_by(0.0));
    }
}
