//! Every colour and style of the explorer, once. The views name what a thing
//! is (an error, the current swing, the fence); this file says how it looks,
//! and how many colours the terminal shows.

use ratatui::style::{Color, Modifier, Style};

/// How many colours the terminal shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorMode {
    TrueColor,
    /// The xterm 256-colour palette: the heatmap is quantised to its 6×6×6 cube.
    Indexed,
}

impl ColorMode {
    /// Truecolor only when the terminal says so (`COLORTERM`); 256 colours
    /// otherwise, which every terminal and tmux over SSH shows.
    pub fn detect() -> ColorMode {
        match std::env::var("COLORTERM") {
            Ok(v) if v.contains("truecolor") || v.contains("24bit") => ColorMode::TrueColor,
            _ => ColorMode::Indexed,
        }
    }

    pub fn rgb(self, (r, g, b): (u8, u8, u8)) -> Color {
        match self {
            ColorMode::TrueColor => Color::Rgb(r, g, b),
            ColorMode::Indexed => {
                // The cube's levels are 0, 95, 135, 175, 215, 255.
                let level = |c: u8| -> u8 {
                    if c < 48 {
                        0
                    } else if c < 115 {
                        1
                    } else {
                        ((c as u16 - 35) / 40).min(5) as u8
                    }
                };
                Color::Indexed(16 + 36 * level(r) + 6 * level(g) + level(b))
            }
        }
    }
}

/// A pane's or a pop-up's title.
pub fn title_style() -> Style {
    Style::new().add_modifier(Modifier::BOLD)
}

/// What explains rather than tells: axes, labels, hints, group headers.
pub fn dim() -> Style {
    Style::new().fg(Color::DarkGray)
}

/// `style`, in bold: a name that heads its line.
pub fn strong(style: Style) -> Style {
    style.add_modifier(Modifier::BOLD)
}

// Text.

/// Text as the terminal shows it.
pub const PLAIN: Style = Style::new();
/// The selected input, tab or preset.
pub const SELECTED: Style = Style::new().add_modifier(Modifier::REVERSED);
/// Why an input, an edit or a save was refused.
pub const ERROR: Style = Style::new().fg(Color::Red).add_modifier(Modifier::BOLD);
/// A preset that does not load, and what is wrong with it.
pub const BROKEN: Style = Style::new().fg(Color::Red);
/// Something that worked: a message, a converged optimum.
pub const GOOD: Style = Style::new().fg(Color::Green);
/// Work still under way: the optimiser searching, a surface refining.
pub const BUSY: Style = Style::new().fg(Color::Yellow);
/// A key in the help.
pub const KEY: Style = Style::new().fg(Color::Cyan);

// The sensitivity columns.

/// A range gained per nudge, graded by its size against the largest shown
/// (`max`, > 0): four intensities, green for a gain and red for a loss (the
/// sign is written too, for terminals without colour).
pub fn gain(value: f64, max: f64) -> Style {
    let share = value.abs() / max;
    let (faint, normal, strong) = if value >= 0.0 {
        (Color::Green, Color::Green, Color::LightGreen)
    } else {
        (Color::Red, Color::Red, Color::LightRed)
    };
    if share >= 0.5 {
        Style::new().fg(strong).add_modifier(Modifier::BOLD)
    } else if share >= 0.1 {
        Style::new().fg(normal)
    } else if share >= 0.01 {
        Style::new().fg(faint).add_modifier(Modifier::DIM)
    } else {
        dim()
    }
}

/// A sensitivity for inputs that have changed since: shown until the new
/// one arrives.
pub const STALE_GAIN: Style = Style::new()
    .fg(Color::DarkGray)
    .add_modifier(Modifier::ITALIC);

// The trajectory.

/// The current swing's path (and its legend).
pub const SWING: Style = Style::new().fg(Color::Cyan);
/// The optimal swing's path (and its legend).
pub const OPTIMAL: Style = Style::new().fg(Color::Green);
/// The pinned scene's path (and its legend, and the readout's deltas).
pub const PINNED: Style = Style::new().fg(Color::LightRed);
pub const APEX: Style = Style::new().fg(Color::Yellow);
pub const LANDING: Style = Style::new().fg(Color::Magenta);
pub const FENCE: Style = Style::new().fg(Color::White);

// The figures.

/// A figure's curves, in turn (the current input's line is `SWING`, the
/// paper's marked points `APEX`).
pub const FIGURE_CURVES: [Style; 3] = [
    Style::new().fg(Color::Green),
    Style::new().fg(Color::Yellow),
    Style::new().fg(Color::Magenta),
];

// The impact: each curve or mark in the chart and in its legend below.

/// v1, the tangential slip of the contact points.
pub const SLIP: Style = Style::new().fg(Color::Cyan);
/// v3, their normal approach.
pub const APPROACH: Style = Style::new().fg(Color::Yellow);
/// p_c, the end of compression.
pub const COMPRESSION: Style = Style::new().fg(Color::LightBlue);
/// p_s, where slip halts.
pub const STICK: Style = Style::new().fg(Color::Magenta);
/// p at the step-through's cursor.
pub const CURSOR: Style = Style::new().fg(Color::White);

// The heatmap, painted cell by cell.

/// The fence's distance as a contour.
pub const CONTOUR: Color = Color::White;
/// Where the bat misses the ball: no range.
pub const NO_RANGE: Color = Color::Black;
/// Where the ball does not land within its limits: no range, and off the
/// colour scale (grey, which the ramp never takes).
pub const NOT_LANDED: Color = Color::Gray;
/// The optimum's mark.
pub const OPTIMUM_MARK: Color = Color::Yellow;
/// The current swing's mark.
pub const SWING_MARK: Color = Color::White;

/// A mark on the heatmap: bold, in `colour`, on black.
pub fn mark(colour: Color) -> Style {
    Style::new()
        .fg(colour)
        .bg(Color::Black)
        .add_modifier(Modifier::BOLD)
}

/// A cell of the heatmap's colour bar.
pub fn swatch(colour: Color) -> Style {
    Style::new().fg(colour)
}

/// The heatmap's perceptual ramp (after viridis), t in [0, 1].
pub fn ramp(t: f64) -> (u8, u8, u8) {
    const STOPS: [(f64, f64, f64); 6] = [
        (68.0, 1.0, 84.0),
        (65.0, 68.0, 135.0),
        (42.0, 120.0, 142.0),
        (34.0, 168.0, 132.0),
        (122.0, 209.0, 81.0),
        (253.0, 231.0, 37.0),
    ];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let x = t * (STOPS.len() - 1) as f64;
    let k = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - k as f64;
    let (a, b) = (STOPS[k], STOPS[k + 1]);
    let mix = |p: f64, q: f64| (p + f * (q - p)).round() as u8;
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}
