//! Aerodynamic coefficients: drag C_D(Re) (Fig. 3) and lift C_L(S) (Eq. 29).

use serde::{Deserialize, Serialize};

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
}

impl DragModel {
    pub const ALL: [DragModel; 2] = [DragModel::Sawicki2003, DragModel::Constant];

    pub fn name(self) -> &'static str {
        match self {
            DragModel::Sawicki2003 => "sawicki2003",
            DragModel::Constant => "constant",
        }
    }

    pub fn description(self) -> &'static str {
        match self {
            DragModel::Sawicki2003 => "drag crisis at Re ≈ 160 000 (the paper's Fig. 3)",
            DragModel::Constant => "C_D = 0.5 at every Re (no drag crisis)",
        }
    }

    /// C_D at Reynolds number `re`.
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
    /// piece's ends: an integrator step that starts on a piece keeps its
    /// formula, so it sees a smooth right-hand side, and the flight switches
    /// formula where the step crosses the kink. The continuation holds for
    /// [`CONTINUATION`] past a kink and is constant beyond, so that a long
    /// step cannot meet an exploding exponential (C_D ≈ 37 at Re = 10⁵ on the
    /// rising piece; at most 2.3 here) or a negative drag (the recovery piece,
    /// continued, turns negative below Re ≈ 155 000).
    #[inline]
    pub fn drag_coefficient_on(self, piece: usize, re: f64) -> f64 {
        match self {
            DragModel::Sawicki2003 => match piece {
                0 => SUBCRITICAL_DRAG,
                1 => {
                    let re = re.max(SAWICKI_KINKS[0] - CONTINUATION);
                    DRAG_FLOOR + 0.0416812 * (((CRISIS_START - re) * (1.0 / 8784.46)).exp() - 1.0)
                }
                2 => DRAG_FLOOR,
                _ => {
                    let re = re.max(CRISIS_END - CONTINUATION);
                    DRAG_FLOOR + 0.309620 * (1.0 - ((CRISIS_END - re) * (1.0 / 49808.6)).exp())
                }
            },
            DragModel::Constant => SUBCRITICAL_DRAG,
        }
    }

    /// Reynolds numbers where C_D(Re) has a corner (its derivative jumps).
    /// An integrator that steps across one loses an order of accuracy, so the
    /// flight can stop its steps there.
    pub fn kinks(self) -> &'static [f64] {
        match self {
            DragModel::Sawicki2003 => &SAWICKI_KINKS,
            DragModel::Constant => &[],
        }
    }
}

/// How far (in Re) a piece's formula is continued past its kinks: ~3 m/s
/// of air speed, more than any accurate step overshoots.
pub const CONTINUATION: f64 = 15_000.0;
const DRAG_FLOOR: f64 = 0.15;
const SUBCRITICAL_DRAG: f64 = 0.5;
const CRISIS_START: f64 = 160_000.0;
const CRISIS_END: f64 = 175_000.0;
/// Where the subcritical exponential reaches 0.5 and the `min` takes over:
/// 160 000 − 8784.46·ln(1 + 0.35/0.0416812) ≈ 140 319.
const SAWICKI_KINKS: [f64; 3] = [140_319.312_894_860_5, CRISIS_START, CRISIS_END];

/// A model name that is not one of the accepted ones.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("model.drag = {text:?}: unknown drag model; accepted: {accepted}")]
pub struct UnknownModel {
    pub text: String,
    pub accepted: String,
}

impl std::str::FromStr for DragModel {
    type Err = UnknownModel;
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        DragModel::ALL
            .into_iter()
            .find(|m| m.name() == text.trim())
            .ok_or_else(|| UnknownModel {
                text: text.to_owned(),
                accepted: DragModel::ALL.map(DragModel::name).join(", "),
            })
    }
}

impl std::fmt::Display for DragModel {
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

/// C_L·|V_r|, written without dividing by |V_r| (S·|V_r| = r_b|ω|), so that a
/// zero relative wind or a zero spin gives exactly zero lift, never 0/0.
#[inline]
pub fn lift_coefficient_times_speed(air_speed: f64, surface_speed: f64) -> f64 {
    // S ≤ 0.1  ⇔  r_b|ω| ≤ 0.1·|V_r|.
    if surface_speed <= 0.1 * air_speed {
        1.5 * surface_speed
    } else {
        0.09 * air_speed + 0.6 * surface_speed
    }
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
