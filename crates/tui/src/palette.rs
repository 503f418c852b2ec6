//! Colours worked out rather than named: the heatmaps' ramps, and the
//! 16-colour fallback that draws any colour in the nearest of the named
//! sixteen, for a terminal that shows no more (TERM=xterm, linux).

use ratatui::style::Color;

use ratatui::style::{Modifier, Style};

use crate::theme::{ColorMode, Theme};

impl ColorMode {
    /// Sixteen colours where `TERM` names a terminal known to show no
    /// more ("xterm", "xterm-color", "xterm-16color", "linux", "vt100",
    /// "ansi", "rxvt"); "xterm-256color", "tmux-256color", "screen" (tmux
    /// and screen pass 256 colours on) and an unknown or unset TERM keep
    /// the 256-colour palette.
    pub fn for_term(self, term: Option<&str>) -> ColorMode {
        const SIXTEEN_ONLY: [&str; 9] = [
            "xterm",
            "xterm-color",
            "xterm-16color",
            "linux",
            "vt100",
            "vt220",
            "ansi",
            "rxvt",
            "cygwin",
        ];
        let few = term.is_some_and(|t| SIXTEEN_ONLY.contains(&t));
        match self {
            ColorMode::Indexed if few => ColorMode::Sixteen,
            other => other,
        }
    }
}

/// The sixteen named colours, as xterm draws them by default.
const SIXTEEN: [(Color, (u8, u8, u8)); 16] = [
    (Color::Black, (0, 0, 0)),
    (Color::Red, (205, 0, 0)),
    (Color::Green, (0, 205, 0)),
    (Color::Yellow, (205, 205, 0)),
    (Color::Blue, (0, 0, 238)),
    (Color::Magenta, (205, 0, 205)),
    (Color::Cyan, (0, 205, 205)),
    (Color::Gray, (229, 229, 229)),
    (Color::DarkGray, (127, 127, 127)),
    (Color::LightRed, (255, 0, 0)),
    (Color::LightGreen, (0, 255, 0)),
    (Color::LightYellow, (255, 255, 0)),
    (Color::LightBlue, (92, 92, 255)),
    (Color::LightMagenta, (255, 0, 255)),
    (Color::LightCyan, (0, 255, 255)),
    (Color::White, (255, 255, 255)),
];

/// The named colour nearest `rgb` (squared distance in RGB).
pub fn nearest_of_sixteen((r, g, b): (u8, u8, u8)) -> Color {
    let distance = |(p, q, s): (u8, u8, u8)| {
        let d = |a: u8, b: u8| (i32::from(a) - i32::from(b)).pow(2);
        d(r, p) + d(g, q) + d(b, s)
    };
    SIXTEEN
        .iter()
        .min_by_key(|(_, rgb)| distance(*rgb))
        .map_or(Color::Reset, |(colour, _)| *colour)
}

/// `theme` in the sixteen named colours. The walls' heights, lowest to
/// tallest, keep four distinct colours (the nearest would draw the 2nd and
/// 3rd both yellow).
pub fn in_sixteen(theme: Theme) -> Theme {
    let mut theme = theme.map_colours(to_sixteen);
    let fg = |c: Color| Style::new().fg(c);
    theme.walls = [
        fg(Color::Blue),
        fg(Color::Yellow),
        fg(Color::Red),
        fg(Color::LightRed).add_modifier(Modifier::BOLD),
    ];
    theme
}

/// `colour` as xterm draws it by default, in RGB: a named colour, one of
/// the 256-colour palette (its 6×6×6 cube and greys) or an RGB one; `None`
/// for the terminal's own (Reset).
pub fn xterm_rgb(colour: Color) -> Option<(u8, u8, u8)> {
    let index = match colour {
        Color::Rgb(r, g, b) => return Some((r, g, b)),
        Color::Indexed(i) => i,
        named => SIXTEEN.iter().position(|(c, _)| *c == named)? as u8,
    };
    let level = |k: u8| if k == 0 { 0 } else { 55 + 40 * k };
    Some(match index {
        0..=15 => SIXTEEN[index as usize].1,
        16..=231 => {
            let k = index - 16;
            (level(k / 36), level(k / 6 % 6), level(k % 6))
        }
        _ => {
            let grey = 8 + 10 * (index - 232);
            (grey, grey, grey)
        }
    })
}

/// `colour` in the sixteen: the named ones stay, the 256-colour palette's
/// cube and greys and any RGB go to the nearest.
pub fn to_sixteen(colour: Color) -> Color {
    match colour {
        Color::Indexed(i) if i < 16 => SIXTEEN[i as usize].0,
        Color::Indexed(_) | Color::Rgb(..) => xterm_rgb(colour).map_or(colour, nearest_of_sixteen),
        named => named,
    }
}

/// The margin map's diverging ramp, t in [0, 1] with the wall's top at ½:
/// magenta under the wall, green over it, through a light grey
/// (ColorBrewer's PiYG, which colour-blind eyes tell apart). Both ends
/// are dark, so that they read on a dark and a light terminal alike.
pub fn diverging(t: f64) -> (u8, u8, u8) {
    const STOPS: [(f64, f64, f64); 9] = [
        (142.0, 1.0, 82.0),
        (197.0, 27.0, 125.0),
        (222.0, 119.0, 174.0),
        (241.0, 182.0, 218.0),
        (247.0, 247.0, 247.0),
        (184.0, 225.0, 134.0),
        (127.0, 188.0, 65.0),
        (77.0, 146.0, 33.0),
        (39.0, 100.0, 25.0),
    ];
    interpolate(&STOPS, t)
}

/// The colour at `t` in [0, 1] along evenly spaced `stops`.
fn interpolate(stops: &[(f64, f64, f64)], t: f64) -> (u8, u8, u8) {
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let x = t * (stops.len() - 1) as f64;
    let k = (x.floor() as usize).min(stops.len() - 2);
    let f = x - k as f64;
    let (a, b) = (stops[k], stops[k + 1]);
    let mix = |p: f64, q: f64| (p + f * (q - p)).round() as u8;
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
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
    interpolate(&STOPS, t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theme::{Background, Theme};

    #[test]
    fn plain_xterm_gets_sixteen_colours_and_256color_keeps_its_palette() {
        let indexed = ColorMode::Indexed;
        assert_eq!(indexed.for_term(Some("xterm")), ColorMode::Sixteen);
        assert_eq!(indexed.for_term(Some("linux")), ColorMode::Sixteen);
        assert_eq!(indexed.for_term(Some("xterm-256color")), ColorMode::Indexed);
        assert_eq!(indexed.for_term(Some("tmux-256color")), ColorMode::Indexed);
        assert_eq!(indexed.for_term(Some("screen")), ColorMode::Indexed);
        assert_eq!(indexed.for_term(None), ColorMode::Indexed);
        // NO_COLOR and truecolor are not touched by TERM.
        assert_eq!(
            ColorMode::NoColor.for_term(Some("xterm")),
            ColorMode::NoColor
        );
        assert_eq!(
            ColorMode::TrueColor.for_term(Some("xterm")),
            ColorMode::TrueColor
        );
    }

    #[test]
    fn the_sixteen_colour_themes_use_only_named_colours() {
        // xterm's 208 (orange) is nearest its yellow, 28 its green; the
        // viridis ramp's ends are blue-black and yellow.
        assert_eq!(to_sixteen(Color::Indexed(208)), Color::Yellow);
        assert_eq!(to_sixteen(Color::Indexed(28)), Color::Green);
        assert_eq!(nearest_of_sixteen(ramp(0.0)), Color::Black);
        assert_eq!(nearest_of_sixteen(ramp(1.0)), Color::LightYellow);
        for background in [Background::Dark, Background::Light] {
            let theme = Theme::new(background, ColorMode::Sixteen);
            let text = format!("{theme:?}");
            assert!(!text.contains("Indexed") && !text.contains("Rgb"), "{text}");
            let walls: Vec<_> = theme.walls.iter().map(|s| s.fg).collect();
            let mut distinct = walls.clone();
            distinct.dedup();
            assert_eq!(distinct.len(), 4, "{walls:?}");
        }
    }
}
