//! The impact's step-through: where `,` and `.` stop.

use model::impact::{Collision, Stop};

/// The collision's phases in order of impulse (approach, compression, the
/// halt of slip, …, separation) and, for a 3-D swing, three stops while
/// the slip turns: at half, 9/10 and 99/100 of the impulse over which it
/// slides. Its direction turns little while it is fast and most as it
/// dies (from 26° to 28°, 31° and 37° for a fastball met by a bat 0.5 rad
/// down, swung 0.3 rad toward right field), so the stops crowd toward the
/// halt. The paper's planar collision keeps its own stops.
pub fn impact_stops(impact: &Collision) -> Vec<Stop> {
    let mut stops = impact.stops();
    if let Some(spatial) = impact.spatial() {
        let sliding = spatial.slip_halt_impulse().min(spatial.separation_impulse);
        if sliding > 0.0 && sliding.is_finite() {
            stops.extend([0.5, 0.9, 0.99].map(|f| Stop {
                name: "slip turning",
                impulse: f * sliding,
            }));
            stops.sort_by(|a, b| a.impulse.total_cmp(&b.impulse));
        }
    }
    stops
}
