//! A sentence for each stop of the impact's step-through: what the contact
//! is doing there and why, after the paper's impact model (Sec. II,
//! Eqs. 15–21, Fig. 2).

use model::impact::{Collision, Stop};

/// What happens at `stop`, in words a class can read beside the chart.
pub fn sentence(impact: &Collision, stop: Stop) -> String {
    let p = stop.impulse;
    // Whether friction has already halted the slip here (paper: with
    // μ̄ = 0 < μ, a halted slip stays stuck to the end).
    let stuck = impact.stick_impulse().is_some_and(|ps| ps <= p);
    let tangential = if stuck {
        "the contact sticks: the ball rolls on the bat, v1 = 0"
    } else {
        "friction (μ times the push) slows the slip v1"
    };
    match stop.name {
        "approach" => "Contact begins (p = 0): the ball closes on the bat at v3 and slides \
             along it at v1; the push p grows, friction opposes the slip."
            .to_owned(),
        "compression" => format!(
            "Compression: ball and bat squash together; the push slows their approach v3, \
             and {tangential}."
        ),
        "max compression" => format!(
            "Maximum compression (p_c): v3 = 0, ball and bat move together along the \
             normal; the stored energy now pushes them apart, and {tangential}."
        ),
        "restitution" => format!(
            "Restitution: the ball springs back, v3 > 0; only e*² = {:.3} of the \
             compression's energy returns, and {tangential}.",
            impact.restitution().powi(2)
        ),
        "separation" => "Separation (p_f = p_c(1 + e*)): the ball leaves the bat; its velocity \
             and spin here are the launch."
            .to_owned(),
        "slip halts, stick" => "Slip halts (p_s): friction has stopped the sliding; the contact \
             sticks from here to the end, since μ exceeds the stick ratio μ̄ = 0."
            .to_owned(),
        "slip turning" => "3-D slip: friction acts against the slip's direction at each \
             moment, so the direction turns, most as the slip dies."
            .to_owned(),
        other => format!("{other}: p = {p:.3} N·s."),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use model::impact::Collision;

    fn fastball() -> Collision {
        Collision::new(&preset::load("fastball", None).unwrap().scene)
    }

    #[test]
    fn each_stop_of_the_fastball_has_its_own_sentence() {
        let impact = fastball();
        let sentences: Vec<String> = impact
            .stops()
            .into_iter()
            .map(|s| sentence(&impact, s))
            .collect();
        assert_eq!(sentences.len(), 6, "{sentences:?}");
        let mut unique = sentences.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(unique.len(), 6, "{sentences:?}");
        // The fastball's slip halts (p_s 1.657) before compression ends
        // (p_c 8.621), so the compression stop is already stuck.
        let compression = &sentences[2];
        assert!(compression.starts_with("Compression"), "{sentences:?}");
        assert!(compression.contains("sticks"), "{compression}");
    }
}
