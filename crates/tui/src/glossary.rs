//! Words for the symbols and marks on screen: what each is, its unit and
//! where the paper defines it. The help's second page lists them (`?`,
//! then Tab), so that a class can read the first screen without the paper.

use units::Quantity;

/// One symbol or mark: how the screen writes it, what it is, the quantity
/// its unit follows (shown in the system in use), and where the paper
/// (or the project) defines it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Entry {
    pub symbol: &'static str,
    pub meaning: &'static str,
    pub quantity: Option<Quantity>,
    pub source: &'static str,
}

const fn entry(
    symbol: &'static str,
    meaning: &'static str,
    quantity: Option<Quantity>,
    source: &'static str,
) -> Entry {
    Entry {
        symbol,
        meaning,
        quantity,
        source,
    }
}

use Quantity::{Angle, Distance, Size, Speed, Spin};

/// Every symbol of the inputs, the readout, the impact and the charts, in
/// the order a reader meets them (inputs, readout, impact, marks).
pub const GLOSSARY: &[Entry] = &[
    entry(
        "V̂_b0",
        "pitch speed: the ball's speed just before it meets the bat",
        Some(Speed),
        "Table I, Fig. 1",
    ),
    entry(
        "ω_b0",
        "pitch spin: the ball's spin before impact, positive counter-clockwise as Fig. 1 is drawn (a fastball's backspin is negative)",
        Some(Spin),
        "Table I",
    ),
    entry(
        "V̂_B0",
        "bat speed at the point of contact, just before impact",
        Some(Speed),
        "Table I",
    ),
    entry(
        "ω_B0",
        "the bat's spin about its centre of mass before impact",
        Some(Spin),
        "Table I",
    ),
    entry(
        "E",
        "undercut: how far the bat's axis passes below the ball's centre (the batter's first control)",
        Some(Size),
        "Fig. 1, Eq. 1",
    ),
    entry(
        "ψ",
        "swing angle: the bat's velocity above the horizontal (the batter's second control)",
        Some(Angle),
        "Fig. 1",
    ),
    entry(
        "μ",
        "coefficient of friction between bat and ball (no unit)",
        None,
        "Eqs. 17, 21",
    ),
    entry(
        "M_B r_B k_B2",
        "the bat's effective mass (kg, oz in baseball units), its radius and its radius of gyration",
        None,
        "Table I",
    ),
    entry(
        "M_b r_b k_b",
        "the ball's mass, radius and radius of gyration",
        None,
        "Table I",
    ),
    entry(
        "launch",
        "the batted ball leaving the bat: speed V̂_bf, spin ω_bf (backspin positive), launch angle ζ above the horizontal",
        None,
        "Fig. 1, Eq. 22",
    ),
    entry(
        "range",
        "where the ball comes back to the height it was hit at, along the ground; apex is its highest point",
        Some(Distance),
        "Sec. IV",
    ),
    entry(
        "e*",
        "energetic coefficient of restitution: e*² is the share of the compression's energy given back; it falls as the approach speed v3(0) rises",
        None,
        "Eq. 19",
    ),
    entry(
        "θ",
        "angle of the common normal n3 (the line of centres) above the horizontal, set by the undercut: sin θ = E/(r_b + r_B)",
        Some(Angle),
        "Eq. 1",
    ),
    entry(
        "stick / slip",
        "stick: the contact points stop sliding before separation (p_s < p_f) and the ball rolls on the bat; slip: they slide to the end",
        None,
        "Sec. II, after Eq. 18",
    ),
    entry(
        "p",
        "normal impulse so far: the push along n3, the clock of the collision (N·s)",
        None,
        "Fig. 2",
    ),
    entry(
        "p_s",
        "the normal impulse at which friction has halted the slip (N·s); '—' when it never halts",
        None,
        "Eq. 17",
    ),
    entry(
        "p_c",
        "the normal impulse at maximum compression, where the approach v3 reaches 0 (N·s)",
        None,
        "Eq. 18",
    ),
    entry(
        "p_f",
        "the normal impulse at separation: p_f = p_c (1 + e*) (N·s)",
        None,
        "Eq. 20",
    ),
    entry(
        "v1 v3",
        "the contact points' relative velocity: v1 sliding along the bat (slip), v3 along the normal (approach, negative while closing)",
        Some(Speed),
        "Fig. 2, Eq. 15",
    ),
    entry(
        "|ω|",
        "3-D impact: the size of the ball's spin vector at the stop shown; at separation it is the launch's spin, whose backspin part the launch line gives",
        Some(Spin),
        "project, 3-D",
    ),
    entry(
        "optimum",
        "the (E, ψ) of the longest range for these inputs, found by the optimiser; ★ on the surface",
        None,
        "Sec. V, Table II",
    ),
    entry(
        "Table II",
        "the paper's optimum, under ours on its three pitches. They differ most in ψ: the range is flat along a ridge in (E, ψ), so at the paper's own swing ours is 134.70 m for the fastball, 0.10 m under our optimum (homerun table2)",
        None,
        "Table II, Fig. 7",
    ),
    entry(
        "44.04",
        "the curve ball's launch speed. Table II prints 43.04 m/s, and the text's \"1.26 m/s higher\" is 44.30 − 43.04; yet 44.04 is right: it flies the printed 138.83 m, 43.04 only 134.93 m, and the spin and angle beside it are ours",
        Some(Speed),
        "Table II, Sec. V",
    ),
    entry(
        "you −opt",
        "your swing minus the optimum: ΔE, Δψ and the range you give away",
        Some(Distance),
        "project",
    ),
    entry(
        "over by",
        "how high the ball passes over the fence. Past the optimum it can rise while the range falls: a steeper launch clears the wall higher yet lands shorter",
        Some(Distance),
        "project",
    ),
    entry(
        "Δ",
        "in the inputs' title: the range gained by the last nudge (negative: lost)",
        Some(Distance),
        "project",
    ),
    entry(
        "yellow •",
        "the trajectory's apex, its highest point",
        None,
        "chart mark",
    ),
    entry(
        "magenta █",
        "where the ball lands (absent when it does not land)",
        None,
        "chart mark",
    ),
    entry(
        "✚ ★",
        "surface: ✚ your swing (E, ψ), ★ the optimum; the contour is the fence (•• without colour)",
        None,
        "Fig. 7",
    ),
    entry(
        "Re C_D C_L S",
        "Reynolds number; drag and lift coefficients; spin parameter rω/V. The drag crisis (C_D falling) is near Re ≈ 160 000",
        None,
        "Figs. 3, 4",
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_readouts_symbols_each_have_an_entry() {
        // The symbols the issue names as unexplained on the first screen.
        for symbol in [
            "e*",
            "θ",
            "p_s",
            "p_c",
            "p_f",
            "|ω|",
            "yellow •",
            "magenta █",
        ] {
            assert!(
                GLOSSARY.iter().any(|e| e.symbol == symbol),
                "{symbol} has no entry"
            );
        }
        assert_eq!(GLOSSARY.len(), 30);
    }

    #[test]
    fn every_entry_says_where_it_comes_from() {
        for e in GLOSSARY {
            assert!(!e.source.is_empty() && !e.meaning.is_empty(), "{e:?}");
            assert!(e.meaning.len() < 300, "{} is too long to read", e.symbol);
        }
    }
}
