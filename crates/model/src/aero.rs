//! Aerodynamic coefficients, one small type per model behind two
//! interfaces: [`DragCurve`] (C_D) and [`LiftCurve`] (C_L). The flight holds
//! a [`DragModel`] and a [`LiftModel`], enums that dispatch to them, and
//! never asks which it has.
//!
//! - Drag: the paper's C_D(Re) with the drag crisis (Fig. 3), a constant 0.5,
//!   or Alan Nathan's spin-dependent C_D.
//! - Lift: the paper's bilinear C_L(S) (Eq. 29), Nathan's C_L(S), or none.
//!
//! Nathan's formulas are those of his trajectory calculator (A. M. Nathan,
//! "Trajectory calculator", baseball.physics.illinois.edu, 2012 onward).
//!
//! A flight asks which models it has once, not at every evaluation:
//! [`DragModel::with_lift`] runs a [`WithModels`] with the two models as
//! types of their own, so that the integration is compiled for each pair
//! with the coefficients inlined. Each formula is written once, generic
//! over [`Real`]: one flight's numbers or four flights' in lock-step.

use serde::{Deserialize, Serialize};

use numerics::real::{Real, exp_lanes};

/// What a drag model gives the flight.
pub trait DragCurve {
    /// C_D at Reynolds number `reynolds` and spin rate `spin_rate` = |ω|
    /// (rad/s), by the formula of smooth piece `piece` (see
    /// [`DragModel::drag_coefficient_on`]); a curve without kinks has one
    /// piece and ignores it.
    fn coefficient_on(&self, piece: usize, reynolds: f64, spin_rate: f64) -> f64;

    /// Reynolds numbers where C_D(Re) has a corner (its derivative jumps),
    /// in increasing order. An integrator that steps across one loses an
    /// order of accuracy, so the flight can stop its steps there.
    fn kinks(&self) -> &'static [f64] {
        &[]
    }

    /// Which smooth piece of C_D(Re) holds at `re`: the number of kinks at
    /// or below it.
    #[inline(always)]
    fn piece(&self, re: f64) -> usize {
        self.kinks().iter().take_while(|&&kink| re >= kink).count()
    }

    /// As [`DragCurve::coefficient_on`], for four flights at once, each on
    /// its own piece (`pieces`, the pieces' numbers as floats).
    fn coefficient_lanes<R: Real>(&self, pieces: R, reynolds: R, spin_rate: R) -> R;

    /// As [`DragCurve::piece`], for four flights, as floats.
    #[inline(always)]
    fn piece_lanes<R: Real>(&self, re: R) -> R {
        let mut count = R::splat(0.0);
        for &kink in self.kinks() {
            count = count + R::select(R::splat(kink).le(re), R::splat(1.0), R::splat(0.0));
        }
        count
    }
}

/// What a lift model gives the flight.
pub trait LiftCurve {
    /// C_L at spin parameter S = r_b|ω|/|V_r|.
    fn coefficient(&self, spin_parameter: f64) -> f64;

    /// C_L·|V_r| from |V_r| and the surface speed r_b|ω|, written without
    /// dividing by |V_r|, so that a zero relative wind or a zero spin gives
    /// exactly zero lift, never 0/0; for one flight or four at once.
    fn coefficient_times_speed<R: Real>(&self, air_speed: R, surface_speed: R) -> R;
}

/// Work to do with a flight's drag and lift models as types of their own:
/// see [`DragModel::with_lift`].
pub trait WithModels {
    type Output;
    fn run<D: DragCurve + Copy, L: LiftCurve + Copy>(self, drag: D, lift: L) -> Self::Output;
}

/// Which drag curve the flight uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum DragModel {
    /// The paper's two-exponential fit with the drag crisis (Fig. 3),
    /// reconstructed: the paper gives it only as a figure. The constants were
    /// fitted so that the whole model reproduces Table II's three optimal
    /// ranges to 0.02 m while following the text's description of Fig. 3: a
    /// floor of 0.15 between Re = 160 000 and 175 000, 0.30 at Re = 208 000 on
    /// the recovery branch, ≈ 0.5 below the crisis. It is bounded at high Re,
    /// which bat-speed sweeps need.
    #[default]
    Sawicki2003,
    /// C_D = 0.5 throughout, as Watts & Baroni assumed: no drag crisis.
    Constant,
    /// Nathan's C_D = 0.3008 + 0.0292·(ω/1000 rpm): no crisis, more drag
    /// with more spin.
    Nathan,
}

impl DragModel {
    pub const ALL: [DragModel; 3] = [
        DragModel::Sawicki2003,
        DragModel::Constant,
        DragModel::Nathan,
    ];

    pub fn name(self) -> &'static str {
        match self {
            DragModel::Sawicki2003 => "sawicki2003",
            DragModel::Constant => "constant",
            DragModel::Nathan => "nathan",
        }
    }

    pub fn description(self) -> &'static str {
        match self {
            DragModel::Sawicki2003 => "drag crisis at Re ≈ 160 000 (the paper's Fig. 3)",
            DragModel::Constant => "C_D = 0.5 at every Re (no drag crisis)",
            DragModel::Nathan => "C_D = 0.3008 + 0.0292·(spin/1000 rpm) (Nathan's calculator)",
        }
    }

    /// C_D at Reynolds number `re`, for a ball without spin (only Nathan's
    /// C_D depends on spin: see [`DragCurve::coefficient_on`]).
    #[inline]
    pub fn drag_coefficient(self, re: f64) -> f64 {
        self.drag_coefficient_on(self.piece(re), re)
    }

    /// Which smooth piece of C_D(Re) holds at `re`: the number of kinks at
    /// or below it.
    #[inline]
    pub fn piece(self, re: f64) -> usize {
        self.kinks().iter().take_while(|&&kink| re >= kink).count()
    }

    /// C_D by the formula of piece `piece`, continued smoothly past the
    /// piece's ends (see [`Sawicki2003Drag`]), for a ball without spin.
    #[inline]
    pub fn drag_coefficient_on(self, piece: usize, re: f64) -> f64 {
        self.coefficient_on(piece, re, 0.0)
    }

    /// Reynolds numbers where C_D(Re) has a corner (see [`DragCurve::kinks`]).
    pub fn kinks(self) -> &'static [f64] {
        DragCurve::kinks(&self)
    }

    /// Runs `work` with this drag model and `lift` as their own types: the
    /// one place a flight asks which models it has.
    pub fn with_lift<W: WithModels>(self, lift: LiftModel, work: W) -> W::Output {
        match self {
            DragModel::Sawicki2003 => lift.with_drag(Sawicki2003Drag, work),
            DragModel::Constant => lift.with_drag(ConstantDrag, work),
            DragModel::Nathan => lift.with_drag(NathanDrag, work),
        }
    }
}

impl DragCurve for DragModel {
    #[inline]
    fn coefficient_on(&self, piece: usize, reynolds: f64, spin_rate: f64) -> f64 {
        match self {
            DragModel::Sawicki2003 => Sawicki2003Drag.coefficient_on(piece, reynolds, spin_rate),
            DragModel::Constant => ConstantDrag.coefficient_on(piece, reynolds, spin_rate),
            DragModel::Nathan => NathanDrag.coefficient_on(piece, reynolds, spin_rate),
        }
    }

    fn coefficient_lanes<R: Real>(&self, pieces: R, reynolds: R, spin_rate: R) -> R {
        match self {
            DragModel::Sawicki2003 => {
                Sawicki2003Drag.coefficient_lanes(pieces, reynolds, spin_rate)
            }
            DragModel::Constant => ConstantDrag.coefficient_lanes(pieces, reynolds, spin_rate),
            DragModel::Nathan => NathanDrag.coefficient_lanes(pieces, reynolds, spin_rate),
        }
    }

    fn kinks(&self) -> &'static [f64] {
        match self {
            DragModel::Sawicki2003 => Sawicki2003Drag.kinks(),
            DragModel::Constant => ConstantDrag.kinks(),
            DragModel::Nathan => NathanDrag.kinks(),
        }
    }
}

/// The paper's C_D(Re) (Fig. 3), in four pieces split at its three kinks.
///
/// Each piece's formula is continued smoothly past the piece's ends: an
/// integrator step that starts on a piece keeps its formula, so it sees a
/// smooth right-hand side, and the flight switches formula where the step
/// crosses the kink. The continuation holds for [`CONTINUATION`] past a kink
/// and is constant beyond, so that a long step cannot meet an exploding
/// exponential (C_D ≈ 37 at Re = 10⁵ on the rising piece; at most 2.3 here)
/// or a negative drag (the recovery piece, continued, turns negative below
/// Re ≈ 155 000).
#[derive(Clone, Copy, Debug)]
pub struct Sawicki2003Drag;

impl Sawicki2003Drag {
    /// The rising piece's exponent at `re` (continued for [`CONTINUATION`]
    /// below its kink): C_D = [`Self::rising`] of its exponential.
    #[inline(always)]
    pub fn rising_exponent<R: Real>(re: R) -> R {
        let re = re.max(R::splat(SAWICKI_KINKS[0] - CONTINUATION));
        (R::splat(CRISIS_START) - re) * R::splat(1.0 / 8784.46)
    }

    /// C_D on the rising piece, from e^[`Self::rising_exponent`]:
    /// 0.15 + 0.0416812·(e^x − 1), one product and one sum after e^x.
    #[inline(always)]
    pub fn rising<R: Real>(exponential: R) -> R {
        R::splat(DRAG_FLOOR - RISE) + R::splat(RISE) * exponential
    }

    /// The recovery piece's exponent at `re` (continued for
    /// [`CONTINUATION`] below its kink).
    #[inline(always)]
    pub fn recovery_exponent<R: Real>(re: R) -> R {
        let re = re.max(R::splat(CRISIS_END - CONTINUATION));
        (R::splat(CRISIS_END) - re) * R::splat(1.0 / 49808.6)
    }

    /// C_D on the recovery piece, from e^[`Self::recovery_exponent`]:
    /// 0.15 + 0.309620·(1 − e^x).
    #[inline(always)]
    pub fn recovery<R: Real>(exponential: R) -> R {
        R::splat(DRAG_FLOOR + RECOVERY) - R::splat(RECOVERY) * exponential
    }
}

impl DragCurve for Sawicki2003Drag {
    #[inline(always)]
    fn coefficient_on(&self, piece: usize, re: f64, _spin_rate: f64) -> f64 {
        match piece {
            0 => SUBCRITICAL_DRAG,
            1 => Self::rising(Self::rising_exponent(re).exp()),
            2 => DRAG_FLOOR,
            _ => Self::recovery(Self::recovery_exponent(re).exp()),
        }
    }

    /// Each lane by its piece's formula; one exponential for the lanes on
    /// either exponential piece, none if no lane is on one.
    #[inline(always)]
    fn coefficient_lanes<R: Real>(&self, pieces: R, re: R, _spin_rate: R) -> R {
        let (rising, recovering) = (pieces.eq(R::splat(1.0)), pieces.eq(R::splat(3.0)));
        let floor = pieces.eq(R::splat(2.0));
        let mut cd = R::select(floor, R::splat(DRAG_FLOOR), R::splat(SUBCRITICAL_DRAG));
        if R::any(rising | recovering) {
            let exponent = R::select(
                rising,
                Self::rising_exponent(re),
                Self::recovery_exponent(re),
            );
            let e = exp_lanes(exponent);
            cd = R::select(rising, Self::rising(e), cd);
            cd = R::select(recovering, Self::recovery(e), cd);
        }
        cd
    }

    fn kinks(&self) -> &'static [f64] {
        &SAWICKI_KINKS
    }
}

/// C_D = 0.5 at every Re and spin.
#[derive(Clone, Copy, Debug)]
pub struct ConstantDrag;

impl DragCurve for ConstantDrag {
    #[inline(always)]
    fn coefficient_on(&self, _piece: usize, _reynolds: f64, _spin_rate: f64) -> f64 {
        SUBCRITICAL_DRAG
    }

    #[inline(always)]
    fn coefficient_lanes<R: Real>(&self, _pieces: R, _reynolds: R, _spin_rate: R) -> R {
        R::splat(SUBCRITICAL_DRAG)
    }
}

/// Nathan's C_D = 0.3008 + 0.0292·(ω/1000), ω in rpm: linear in the spin,
/// independent of Re.
#[derive(Clone, Copy, Debug)]
pub struct NathanDrag;

impl NathanDrag {
    /// C_D at spin rate |ω| (rad/s), for one flight or four.
    #[inline(always)]
    pub fn coefficient<R: Real>(spin_rate: R) -> R {
        R::splat(0.3008) + R::splat(0.0292) * (spin_rate * R::splat(THOUSAND_RPM_PER_RAD_PER_S))
    }
}

impl DragCurve for NathanDrag {
    #[inline(always)]
    fn coefficient_on(&self, _piece: usize, _reynolds: f64, spin_rate: f64) -> f64 {
        Self::coefficient(spin_rate)
    }

    #[inline(always)]
    fn coefficient_lanes<R: Real>(&self, _pieces: R, _reynolds: R, spin_rate: R) -> R {
        Self::coefficient(spin_rate)
    }
}

/// 1 rad/s in units of 1000 rpm: 60/(2π·1000).
const THOUSAND_RPM_PER_RAD_PER_S: f64 = 60.0 / (2.0 * std::f64::consts::PI * 1000.0);

/// How far (in Re) a piece's formula is continued past its kinks: ~3 m/s
/// of air speed, more than any accurate step overshoots.
pub const CONTINUATION: f64 = 15_000.0;
const DRAG_FLOOR: f64 = 0.15;
/// The sizes of the rising and recovery pieces' exponentials.
const RISE: f64 = 0.0416812;
const RECOVERY: f64 = 0.309620;
const SUBCRITICAL_DRAG: f64 = 0.5;
const CRISIS_START: f64 = 160_000.0;
const CRISIS_END: f64 = 175_000.0;
/// Where the subcritical exponential reaches 0.5 and the `min` takes over:
/// 160 000 − 8784.46·ln(1 + 0.35/0.0416812) ≈ 140 319.
const SAWICKI_KINKS: [f64; 3] = [140_319.312_894_860_5, CRISIS_START, CRISIS_END];

/// Which lift curve the flight uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum LiftModel {
    /// The paper's bilinear fit (Eq. 29, Fig. 4).
    #[default]
    Sawicki2003,
    /// Nathan's C_L = 1.120·S/(0.583 + 2.333·S): saturating at large S.
    Nathan,
    /// No lift: the Magnus force left out.
    None,
}

impl LiftModel {
    /// Runs `work` with `drag` and this lift model as its own type (see
    /// [`DragModel::with_lift`]).
    fn with_drag<D: DragCurve + Copy, W: WithModels>(self, drag: D, work: W) -> W::Output {
        match self {
            LiftModel::Sawicki2003 => work.run(drag, Sawicki2003Lift),
            LiftModel::Nathan => work.run(drag, NathanLift),
            LiftModel::None => work.run(drag, NoLift),
        }
    }

    pub const ALL: [LiftModel; 3] = [LiftModel::Sawicki2003, LiftModel::Nathan, LiftModel::None];

    pub fn name(self) -> &'static str {
        match self {
            LiftModel::Sawicki2003 => "sawicki2003",
            LiftModel::Nathan => "nathan",
            LiftModel::None => "none",
        }
    }

    pub fn description(self) -> &'static str {
        match self {
            LiftModel::Sawicki2003 => "C_L = 1.5S up to S = 0.1, 0.09 + 0.6S beyond (Eq. 29)",
            LiftModel::Nathan => "C_L = 1.120S/(0.583 + 2.333S) (Nathan's calculator)",
            LiftModel::None => "C_L = 0: no Magnus force",
        }
    }
}

impl LiftCurve for LiftModel {
    #[inline]
    fn coefficient(&self, spin_parameter: f64) -> f64 {
        match self {
            LiftModel::Sawicki2003 => Sawicki2003Lift.coefficient(spin_parameter),
            LiftModel::Nathan => NathanLift.coefficient(spin_parameter),
            LiftModel::None => NoLift.coefficient(spin_parameter),
        }
    }

    #[inline]
    fn coefficient_times_speed<R: Real>(&self, air_speed: R, surface_speed: R) -> R {
        match self {
            LiftModel::Sawicki2003 => {
                Sawicki2003Lift.coefficient_times_speed(air_speed, surface_speed)
            }
            LiftModel::Nathan => NathanLift.coefficient_times_speed(air_speed, surface_speed),
            LiftModel::None => NoLift.coefficient_times_speed(air_speed, surface_speed),
        }
    }
}

/// The paper's C_L(S) (Eq. 29): see [`lift_coefficient`].
#[derive(Clone, Copy, Debug)]
pub struct Sawicki2003Lift;

impl LiftCurve for Sawicki2003Lift {
    fn coefficient(&self, spin_parameter: f64) -> f64 {
        lift_coefficient(spin_parameter)
    }

    #[inline(always)]
    fn coefficient_times_speed<R: Real>(&self, air_speed: R, surface_speed: R) -> R {
        // S ≤ 0.1  ⇔  r_b|ω| ≤ 0.1·|V_r|.
        R::select(
            R::le(surface_speed, R::splat(0.1) * air_speed),
            R::splat(1.5) * surface_speed,
            R::splat(0.09) * air_speed + R::splat(0.6) * surface_speed,
        )
    }
}

/// Nathan's C_L = 1.120·S/(0.583 + 2.333·S).
#[derive(Clone, Copy, Debug)]
pub struct NathanLift;

const NATHAN_LIFT_SCALE: f64 = 1.120;
const NATHAN_LIFT_OFFSET: f64 = 0.583;
const NATHAN_LIFT_SATURATION: f64 = 2.333;

impl LiftCurve for NathanLift {
    fn coefficient(&self, spin_parameter: f64) -> f64 {
        NATHAN_LIFT_SCALE * spin_parameter
            / (NATHAN_LIFT_OFFSET + NATHAN_LIFT_SATURATION * spin_parameter)
    }

    /// With S = w/|V| (w = r_b|ω|), numerator and denominator times |V|:
    /// C_L·|V| = 1.120·w·|V|/(0.583·|V| + 2.333·w), whose denominator is
    /// positive whenever w is; without spin it is exactly zero.
    #[inline(always)]
    fn coefficient_times_speed<R: Real>(&self, air_speed: R, surface_speed: R) -> R {
        let zero = R::splat(0.0);
        // Without spin, exactly zero (where the quotient may be 0/0).
        R::select(
            R::eq(surface_speed, zero),
            zero,
            R::splat(NATHAN_LIFT_SCALE) * surface_speed * air_speed
                / (R::splat(NATHAN_LIFT_OFFSET) * air_speed
                    + R::splat(NATHAN_LIFT_SATURATION) * surface_speed),
        )
    }
}

/// C_L = 0.
#[derive(Clone, Copy, Debug)]
pub struct NoLift;

impl LiftCurve for NoLift {
    fn coefficient(&self, _spin_parameter: f64) -> f64 {
        0.0
    }

    #[inline(always)]
    fn coefficient_times_speed<R: Real>(&self, _air_speed: R, _surface_speed: R) -> R {
        R::splat(0.0)
    }
}

/// The keys that choose the models (in `--set`, presets and batch columns).
pub const DRAG_KEY: &str = "model.drag";
pub const LIFT_KEY: &str = "model.lift";

/// A model name that is not one of the accepted ones.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{key} = {text:?}: unknown {kind} model; accepted: {accepted}")]
pub struct UnknownModel {
    /// The key that was given it (`model.drag`, `model.lift`).
    pub key: &'static str,
    /// What it chooses: "drag", "lift".
    pub kind: &'static str,
    pub text: String,
    pub accepted: String,
}

/// The model among `all` named `text`, or an error listing the names.
fn parse_model<M: Copy, const N: usize>(
    text: &str,
    all: [M; N],
    name: fn(M) -> &'static str,
    (key, kind): (&'static str, &'static str),
) -> Result<M, UnknownModel> {
    all.into_iter()
        .find(|&m| name(m) == text.trim())
        .ok_or_else(|| UnknownModel {
            key,
            kind,
            text: text.to_owned(),
            accepted: all.map(name).join(", "),
        })
}

impl std::str::FromStr for DragModel {
    type Err = UnknownModel;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        parse_model(text, DragModel::ALL, DragModel::name, (DRAG_KEY, "drag"))
    }
}

impl std::str::FromStr for LiftModel {
    type Err = UnknownModel;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        parse_model(text, LiftModel::ALL, LiftModel::name, (LIFT_KEY, "lift"))
    }
}

impl std::fmt::Display for DragModel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::fmt::Display for LiftModel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// C_L at spin parameter S = r_b|ω|/|V_r| (Eq. 29), the bilinear fit of Fig. 4.
pub fn lift_coefficient(spin_parameter: f64) -> f64 {
    if spin_parameter <= 0.1 {
        1.5 * spin_parameter
    } else {
        0.09 + 0.6 * spin_parameter
    }
}

/// Eq. (29)'s C_L·|V_r|, written without dividing by |V_r| (S·|V_r| = r_b|ω|),
/// so that a zero relative wind or a zero spin gives exactly zero lift, never 0/0.
#[inline]
pub fn lift_coefficient_times_speed(air_speed: f64, surface_speed: f64) -> f64 {
    Sawicki2003Lift.coefficient_times_speed(air_speed, surface_speed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drag_curve_follows_the_text_of_fig_3() {
        let m = DragModel::Sawicki2003;
        assert_eq!(m.drag_coefficient(165_000.0), 0.15);
        assert!((m.drag_coefficient(208_000.0) - 0.30).abs() < 0.005);
        assert_eq!(m.drag_coefficient(100_000.0), 0.5);
        // Continuous at every kink.
        for &re in m.kinks() {
            let below = m.drag_coefficient(re * (1.0 - 1e-12));
            let above = m.drag_coefficient(re * (1.0 + 1e-12));
            assert!((below - above).abs() < 1e-9, "jump at {re}");
        }
        assert!((m.drag_coefficient(SAWICKI_KINKS[0]) - 0.5).abs() < 1e-9);
        // The first kink is where the rising exponential itself reaches 0.5
        // (not merely where the `min` clips it).
        let rise = |re: f64| 0.15 + 0.0416812 * (((CRISIS_START - re) / 8784.46).exp() - 1.0);
        assert!((rise(SAWICKI_KINKS[0]) - 0.5).abs() < 1e-12);
        assert_eq!(m.drag_coefficient(140_000.0), 0.5);
        assert!(m.drag_coefficient(150_000.0) < 0.5 && m.drag_coefficient(150_000.0) > 0.15);
    }

    #[test]
    fn each_piece_continues_its_own_formula() {
        let m = DragModel::Sawicki2003;
        assert_eq!(m.piece(100_000.0), 0);
        assert_eq!(m.piece(150_000.0), 1);
        assert_eq!(m.piece(CRISIS_START), 2);
        assert_eq!(m.piece(200_000.0), 3);
        // Past its end, the rising piece keeps rising and the recovery piece
        // keeps falling, so a step that overshoots a kink stays smooth.
        assert!(m.drag_coefficient_on(1, 139_000.0) > 0.5);
        assert!(m.drag_coefficient_on(3, 170_000.0) < 0.15);
        // …but not without bound.
        assert!(m.drag_coefficient_on(1, 50_000.0) < 2.5);
        assert_eq!(
            m.drag_coefficient_on(1, 50_000.0),
            m.drag_coefficient_on(1, SAWICKI_KINKS[0] - CONTINUATION)
        );
        assert!(m.drag_coefficient_on(3, 0.0) > 0.0);
        for (piece, &re) in m.kinks().iter().enumerate() {
            let below = m.drag_coefficient_on(piece, re);
            let above = m.drag_coefficient_on(piece + 1, re);
            assert!(
                (below - above).abs() < 1e-9,
                "pieces {piece}, {} at {re}",
                piece + 1
            );
        }
        assert_eq!(DragModel::Constant.piece(150_000.0), 0);
    }

    #[test]
    fn nathan_drag_grows_with_spin_and_has_no_kinks() {
        let m = DragModel::Nathan;
        assert!(m.kinks().is_empty() && DragModel::Constant.kinks().is_empty());
        // 2500 rpm = 261.8 rad/s: 0.3008 + 0.0292·2.5 = 0.3738, at any Re.
        let rad_per_s = 2500.0 * 2.0 * std::f64::consts::PI / 60.0;
        for re in [5e4, 1.6e5, 3e5] {
            assert!((m.coefficient_on(0, re, rad_per_s) - 0.3738).abs() < 1e-15);
        }
        assert_eq!(m.drag_coefficient(1e5), 0.3008);
        // The paper's curve and the constant ignore the spin.
        for model in [DragModel::Sawicki2003, DragModel::Constant] {
            for re in [1e5, 1.5e5, 1.65e5, 2.5e5] {
                let piece = model.piece(re);
                assert_eq!(
                    model.coefficient_on(piece, re, 300.0),
                    model.drag_coefficient(re)
                );
            }
        }
    }

    #[test]
    fn every_lift_times_speed_is_its_coefficient_times_the_speed() {
        for model in LiftModel::ALL {
            assert_eq!(model.coefficient_times_speed(0.0, 0.0), 0.0, "{model}");
            assert_eq!(model.coefficient_times_speed(40.0, 0.0), 0.0, "{model}");
            assert!(model.coefficient_times_speed(0.0, 5.0).is_finite());
            for (speed, surface) in [(40.0, 2.0), (40.0, 4.0), (30.0, 9.0), (5.0, 20.0)] {
                let direct = model.coefficient(surface / speed) * speed;
                let written = model.coefficient_times_speed(speed, surface);
                assert!(
                    (direct - written).abs() < 1e-13,
                    "{model}: {direct} {written}"
                );
            }
        }
        // Nathan's saturates at 1.120/2.333 ≈ 0.48 and is 1.120/0.583·S at small S.
        let nathan = LiftModel::Nathan;
        assert!((nathan.coefficient(1e6) - 1.120 / 2.333).abs() < 1e-6);
        assert!((nathan.coefficient(1e-9) / 1e-9 - 1.120 / 0.583).abs() < 1e-6);
        assert_eq!(LiftModel::None.coefficient(0.3), 0.0);
    }

    #[test]
    fn models_parse_by_name() {
        for m in DragModel::ALL {
            assert_eq!(m.name().parse::<DragModel>(), Ok(m));
        }
        for m in LiftModel::ALL {
            assert_eq!(format!(" {m} ").parse::<LiftModel>(), Ok(m));
        }
        let e = "magnus".parse::<LiftModel>().unwrap_err();
        assert_eq!(e.accepted, "sawicki2003, nathan, none");
    }

    #[test]
    fn lift_is_continuous_and_zero_without_spin() {
        assert_eq!(lift_coefficient_times_speed(0.0, 0.0), 0.0);
        assert_eq!(lift_coefficient_times_speed(40.0, 0.0), 0.0);
        let at_break = lift_coefficient(0.1);
        assert!((at_break - (0.09 + 0.06)).abs() < 1e-12);
        assert!(
            (lift_coefficient_times_speed(40.0, 4.0) - 40.0 * lift_coefficient(0.1)).abs() < 1e-12
        );
    }
}
