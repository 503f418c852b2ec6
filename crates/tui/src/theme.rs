//! Every colour and style of the explorer, once. The views name what a thing
//! is (an error, the current swing, the fence); a [`Theme`] says how it
//! looks: on a dark or a light background, and in how many colours, none
//! at all under `NO_COLOR` (then glyphs, bold and reverse tell things
//! apart: see [`Theme::path`] and the heatmap's shades).

use std::fmt;
use std::str::FromStr;

pub use crate::palette::{diverging, ramp};
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;

/// How many colours the terminal shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorMode {
    TrueColor,
    /// The 16 named colours only (TERM=xterm, linux, vt100): the rest are
    /// drawn in the nearest of them ([`crate::palette`]).
    Sixteen,
    /// The xterm 256-colour palette: the heatmap is quantised to its 6×6×6 cube.
    Indexed,
    /// None (`NO_COLOR`): no colour escapes at all.
    NoColor,
}

impl ColorMode {
    /// From the environment: no colour when `NO_COLOR` is set and not
    /// empty (no-color.org); truecolor only when the terminal says so
    /// (`COLORTERM`); 256 colours otherwise, which every terminal and tmux
    /// over SSH shows.
    pub fn detect() -> ColorMode {
        let var = |name| std::env::var(name).ok();
        ColorMode::from_env(var("NO_COLOR").as_deref(), var("COLORTERM").as_deref())
            .for_term(var("TERM").as_deref())
    }

    /// [`ColorMode::detect`] from the variables' values.
    pub fn from_env(no_color: Option<&str>, colorterm: Option<&str>) -> ColorMode {
        if no_color.is_some_and(|v| !v.is_empty()) {
            return ColorMode::NoColor;
        }
        match colorterm {
            Some(v) if v.contains("truecolor") || v.contains("24bit") => ColorMode::TrueColor,
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
            ColorMode::Sixteen => crate::palette::nearest_of_sixteen((r, g, b)),
            ColorMode::NoColor => Color::Reset,
        }
    }
}

/// The terminal's background, which the text's colours must stand out on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Background {
    #[default]
    Dark,
    Light,
}

impl Background {
    /// From `COLORFGBG` ("15;0": white on black; rxvt's "0;default;15"),
    /// which many terminals set: a background of colour 7 or 9–15 is
    /// light. Dark when it is not set, as most terminals are.
    pub fn detect() -> Background {
        Background::from_colorfgbg(std::env::var("COLORFGBG").ok().as_deref())
    }

    /// [`Background::detect`] from the variable's value.
    pub fn from_colorfgbg(value: Option<&str>) -> Background {
        let background = value.and_then(|v| v.rsplit(';').next()?.trim().parse::<u8>().ok());
        match background {
            Some(7 | 9..=15) => Background::Light,
            _ => Background::Dark,
        }
    }
}

impl fmt::Display for Background {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Background::Dark => "dark",
            Background::Light => "light",
        })
    }
}

/// A theme's name that is not one.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown theme {0:?}: expected dark or light")]
pub struct UnknownTheme(pub String);

impl FromStr for Background {
    type Err = UnknownTheme;

    fn from_str(text: &str) -> Result<Background, UnknownTheme> {
        match text.trim().to_ascii_lowercase().as_str() {
            "dark" => Ok(Background::Dark),
            "light" => Ok(Background::Light),
            _ => Err(UnknownTheme(text.to_owned())),
        }
    }
}

/// How everything looks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Theme {
    pub color: ColorMode,
    pub background: Background,
    // Text.
    /// A pane's or a pop-up's title.
    pub title: Style,
    /// What explains rather than tells: axes, labels, hints, group headers.
    pub dim: Style,
    /// Text as the terminal shows it.
    pub plain: Style,
    /// The selected input, tab or preset.
    pub selected: Style,
    /// Why an input, an edit or a save was refused.
    pub error: Style,
    /// A preset that does not load, and what is wrong with it.
    pub broken: Style,
    /// Something that worked: a message, a converged optimum.
    pub good: Style,
    /// Work still under way: the optimiser searching, a surface refining.
    pub busy: Style,
    /// A key in the help.
    pub key: Style,
    /// A sensitivity for inputs that have changed since: shown until the
    /// new one arrives.
    pub stale_gain: Style,
    // The trajectory.
    /// The current swing's path (and its legend).
    pub swing: Style,
    /// The optimal swing's path (and its legend).
    pub optimal: Style,
    /// The pinned scene's path (and its legend, and the readout's deltas).
    pub pinned: Style,
    pub apex: Style,
    pub landing: Style,
    pub fence: Style,
    /// A park's wall from above, by its height: up to 8 ft, 12 ft, under
    /// 20 ft, and 20 ft or more (see [`Theme::wall_marker`]).
    pub walls: [Style; 4],
    /// A figure's curves, in turn (the current input's line is `swing`,
    /// the paper's marked points `apex`).
    pub figure_curves: [Style; 3],
    // The impact: each curve or mark in the chart and in its legend below.
    /// v1, the tangential slip of the contact points.
    pub slip: Style,
    /// v2, a 3-D swing's slip along the bat.
    pub slip_along: Style,
    /// v3, their normal approach.
    pub approach: Style,
    /// p_c, the end of compression.
    pub compression: Style,
    /// p_s, where slip halts.
    pub stick: Style,
    /// p at the step-through's cursor.
    pub cursor: Style,
    // The heatmap, painted cell by cell (in colour only).
    /// The fence's distance as a contour.
    pub contour: Color,
    /// The margin map's zero (the wall's top) as a contour: dark, on the
    /// light tints either side of it.
    pub zero_contour: Color,
    /// Where the bat misses the ball: no range.
    pub no_range: Color,
    /// Where the ball does not land within its limits: no range, and off
    /// the colour scale (grey, which the ramp never takes).
    pub not_landed: Color,
    /// The optimum's mark.
    pub optimum_mark: Color,
    /// The current swing's mark.
    pub swing_mark: Color,
}

/// xterm's 256-colour palette: a green, an amber and a teal dark enough
/// for a white background (the 16 named ones are made for black).
const DARK_GREEN: Color = Color::Indexed(28);
const AMBER: Color = Color::Indexed(130);
const TEAL: Color = Color::Indexed(30);

impl Theme {
    /// The theme for `background` in `color`s.
    pub fn new(background: Background, color: ColorMode) -> Theme {
        let theme = match background {
            Background::Dark => Theme::dark(color),
            Background::Light => Theme::light(color),
        };
        match color {
            ColorMode::NoColor => theme.without_colour(),
            ColorMode::Sixteen => crate::palette::in_sixteen(theme),
            _ => theme,
        }
    }

    /// Light text on a dark background: every colour reads on black.
    fn dark(color: ColorMode) -> Theme {
        let fg = |c: Color| Style::new().fg(c);
        Theme {
            color,
            background: Background::Dark,
            title: Style::new().add_modifier(Modifier::BOLD),
            dim: fg(Color::DarkGray),
            plain: Style::new(),
            selected: Style::new().add_modifier(Modifier::REVERSED),
            error: fg(Color::Red).add_modifier(Modifier::BOLD),
            broken: fg(Color::Red),
            good: fg(Color::Green),
            busy: fg(Color::Yellow),
            key: fg(Color::Cyan),
            stale_gain: fg(Color::DarkGray).add_modifier(Modifier::ITALIC),
            swing: fg(Color::Cyan),
            optimal: fg(Color::Green),
            pinned: fg(Color::LightRed),
            apex: fg(Color::Yellow),
            landing: fg(Color::Magenta),
            fence: fg(Color::White),
            walls: [
                fg(Color::Indexed(110)),
                fg(Color::Yellow),
                fg(Color::Indexed(208)),
                fg(Color::LightRed).add_modifier(Modifier::BOLD),
            ],
            figure_curves: [fg(Color::Green), fg(Color::Yellow), fg(Color::Magenta)],
            slip: fg(Color::Cyan),
            slip_along: fg(Color::LightGreen),
            approach: fg(Color::Yellow),
            // Light blue: xterm's dark blue hardly shows on black.
            compression: fg(Color::LightBlue),
            stick: fg(Color::Magenta),
            cursor: fg(Color::White),
            contour: Color::White,
            zero_contour: Color::Black,
            no_range: Color::Black,
            not_landed: Color::Gray,
            optimum_mark: Color::Yellow,
            swing_mark: Color::White,
        }
    }

    /// Dark text on a light background: every colour reads on white.
    fn light(color: ColorMode) -> Theme {
        let fg = |c: Color| Style::new().fg(c);
        Theme {
            background: Background::Light,
            good: fg(DARK_GREEN),
            busy: fg(AMBER),
            key: fg(Color::Blue),
            swing: fg(Color::Blue),
            optimal: fg(DARK_GREEN),
            pinned: fg(Color::Red),
            apex: fg(AMBER),
            fence: fg(Color::Black),
            walls: [
                fg(Color::Indexed(25)),
                fg(Color::Indexed(136)),
                fg(Color::Indexed(166)),
                fg(Color::Indexed(160)).add_modifier(Modifier::BOLD),
            ],
            figure_curves: [fg(DARK_GREEN), fg(AMBER), fg(Color::Magenta)],
            slip: fg(TEAL),
            slip_along: fg(DARK_GREEN),
            approach: fg(AMBER),
            compression: fg(Color::Blue),
            cursor: fg(Color::Black),
            ..Theme::dark(color)
        }
    }

    /// No colour: the styles keep only their bold, italic, dim and
    /// reverse; a key and the hints are told apart by those.
    fn without_colour(self) -> Theme {
        let bare = |s: Style| Style {
            fg: None,
            bg: None,
            ..s
        };
        let mut theme = Theme {
            title: bare(self.title),
            dim: Style::new().add_modifier(Modifier::DIM),
            plain: bare(self.plain),
            selected: bare(self.selected),
            error: bare(self.error),
            broken: bare(self.broken).add_modifier(Modifier::ITALIC),
            good: bare(self.good),
            busy: Style::new().add_modifier(Modifier::ITALIC),
            key: Style::new().add_modifier(Modifier::BOLD),
            stale_gain: Style::new().add_modifier(Modifier::ITALIC | Modifier::DIM),
            contour: Color::Reset,
            zero_contour: Color::Reset,
            no_range: Color::Reset,
            not_landed: Color::Reset,
            optimum_mark: Color::Reset,
            swing_mark: Color::Reset,
            ..self
        };
        for style in [
            &mut theme.swing,
            &mut theme.optimal,
            &mut theme.pinned,
            &mut theme.apex,
            &mut theme.landing,
            &mut theme.fence,
            &mut theme.slip,
            &mut theme.slip_along,
            &mut theme.approach,
            &mut theme.compression,
            &mut theme.stick,
            &mut theme.cursor,
        ] {
            *style = bare(*style);
        }
        theme.figure_curves = theme.figure_curves.map(bare);
        theme.walls = theme.walls.map(bare);
        theme
    }

    /// Every colour of the theme passed through `f` (the 16-colour
    /// fallback), its modifiers kept.
    pub(crate) fn map_colours(mut self, f: fn(Color) -> Color) -> Theme {
        let map = |s: &mut Style| {
            s.fg = s.fg.map(f);
            s.bg = s.bg.map(f);
        };
        for style in [
            &mut self.title,
            &mut self.dim,
            &mut self.plain,
            &mut self.selected,
            &mut self.error,
            &mut self.broken,
            &mut self.good,
            &mut self.busy,
            &mut self.key,
            &mut self.stale_gain,
            &mut self.swing,
            &mut self.optimal,
            &mut self.pinned,
            &mut self.apex,
            &mut self.landing,
            &mut self.fence,
            &mut self.slip,
            &mut self.slip_along,
            &mut self.approach,
            &mut self.compression,
            &mut self.stick,
            &mut self.cursor,
        ] {
            map(style);
        }
        self.walls.iter_mut().for_each(map);
        self.figure_curves.iter_mut().for_each(map);
        for colour in [
            &mut self.contour,
            &mut self.zero_contour,
            &mut self.no_range,
            &mut self.not_landed,
            &mut self.optimum_mark,
            &mut self.swing_mark,
        ] {
            *colour = f(*colour);
        }
        self
    }

    /// Whether colour is shown at all.
    pub fn colored(&self) -> bool {
        self.color != ColorMode::NoColor
    }

    /// A colour of the heatmap's ramp in the terminal's colours.
    pub fn rgb(&self, rgb: (u8, u8, u8)) -> Color {
        self.color.rgb(rgb)
    }

    /// `style`, in bold: a name that heads its line.
    pub fn strong(style: Style) -> Style {
        style.add_modifier(Modifier::BOLD)
    }

    /// A range gained per nudge, graded by its size against the largest
    /// shown (`max`, > 0): four intensities, green for a gain and red for a
    /// loss (the sign is written too, for terminals without colour, where
    /// bold and dim grade it).
    pub fn gain(&self, value: f64, max: f64) -> Style {
        let share = value.abs() / max;
        let (normal, strong) = match (value >= 0.0, self.background) {
            (true, Background::Dark) => (Color::Green, Color::LightGreen),
            (false, Background::Dark) => (Color::Red, Color::LightRed),
            (true, Background::Light) => (DARK_GREEN, DARK_GREEN),
            (false, Background::Light) => (Color::Red, Color::Red),
        };
        let style = if share >= 0.5 {
            Style::new().fg(strong).add_modifier(Modifier::BOLD)
        } else if share >= 0.1 {
            Style::new().fg(normal)
        } else if share >= 0.01 {
            Style::new().fg(normal).add_modifier(Modifier::DIM)
        } else {
            self.dim
        };
        if self.colored() {
            style
        } else {
            Style { fg: None, ..style }
        }
    }

    /// A mark on the heatmap: bold, in `colour`, on black; reversed where
    /// there is no colour.
    pub fn mark(&self, colour: Color) -> Style {
        if self.colored() {
            Style::new()
                .fg(colour)
                .bg(Color::Black)
                .add_modifier(Modifier::BOLD)
        } else {
            Style::new().add_modifier(Modifier::BOLD | Modifier::REVERSED)
        }
    }

    /// A cell of the heatmap's colour bar.
    pub fn swatch(&self, colour: Color) -> Style {
        if self.colored() {
            Style::new().fg(colour)
        } else {
            Style::new()
        }
    }

    /// How the trajectory's path `k` (0 the current swing, 1 the optimal,
    /// 2 the pinned) and a figure's curve `k` are drawn, and the glyph of
    /// their legend: all in braille under "━" when colour tells them
    /// apart, else in braille, dots and quadrant blocks.
    pub fn path(&self, k: usize) -> (Marker, &'static str) {
        match (self.colored(), k % 3) {
            (true, _) | (false, 0) => (Marker::Braille, "━"),
            (false, 1) => (Marker::Dot, "•"),
            (false, _) => (Marker::Quadrant, "▚"),
        }
    }

    /// How a wall of height band `k` (0 lowest, 3 the tallest) is drawn
    /// from above: the taller, the thicker, so that a 37 ft wall stands
    /// out whatever the colours; without colour each band has its own.
    pub fn wall_marker(&self, k: usize) -> Marker {
        match (self.colored(), k) {
            (_, 0) | (true, 1) => Marker::Braille,
            (false, 1) => Marker::Bar,
            (_, 2) => Marker::HalfBlock,
            _ => Marker::Block,
        }
    }

    /// The heatmap's glyph for a cell at `t` of the colour scale (0 to 1)
    /// where there is no colour: shades, lightest lowest.
    pub fn shade(t: f64) -> &'static str {
        const SHADES: [&str; 5] = ["·", "░", "▒", "▓", "█"];
        let t = if t.is_finite() {
            t.clamp(0.0, 1.0)
        } else {
            0.0
        };
        SHADES[((t * SHADES.len() as f64) as usize).min(SHADES.len() - 1)]
    }
}

/// The margin map's glyph for a cell at `t` of its scale (0 to 1, the
/// wall's top at ½) where there is no colour: lines below the wall,
/// heavier the further under it; shades above it, darker the higher.
pub fn margin_shade(t: f64) -> &'static str {
    const GLYPHS: [&str; 6] = ["=", "-", "·", "░", "▒", "▓"];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.5
    };
    GLYPHS[((t * GLYPHS.len() as f64) as usize).min(GLYPHS.len() - 1)]
}

impl From<ColorMode> for Theme {
    /// The dark theme in `color`s.
    fn from(color: ColorMode) -> Theme {
        Theme::new(Background::Dark, color)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// xterm's default palette, as RGB.
    fn xterm(colour: Color) -> (u8, u8, u8) {
        crate::palette::xterm_rgb(colour).unwrap_or_else(|| panic!("{colour:?}"))
    }

    /// WCAG's contrast ratio of two colours, 1 to 21.
    fn contrast(a: (u8, u8, u8), b: (u8, u8, u8)) -> f64 {
        let luminance = |(r, g, b): (u8, u8, u8)| {
            let channel = |c: u8| {
                let c = f64::from(c) / 255.0;
                if c <= 0.03928 {
                    c / 12.92
                } else {
                    ((c + 0.055) / 1.055).powf(2.4)
                }
            };
            0.2126 * channel(r) + 0.7152 * channel(g) + 0.0722 * channel(b)
        };
        let (x, y) = (luminance(a), luminance(b));
        (x.max(y) + 0.05) / (x.min(y) + 0.05)
    }

    fn text_styles(theme: &Theme) -> Vec<Style> {
        let mut styles = vec![
            theme.dim,
            theme.error,
            theme.broken,
            theme.good,
            theme.busy,
            theme.key,
            theme.stale_gain,
            theme.swing,
            theme.optimal,
            theme.pinned,
            theme.apex,
            theme.landing,
            theme.fence,
            theme.slip,
            theme.slip_along,
            theme.approach,
            theme.compression,
            theme.stick,
            theme.cursor,
        ];
        styles.extend(theme.figure_curves);
        styles.extend(theme.walls);
        for value in [1.0, 0.3, 0.05, -1.0, -0.3, -0.05] {
            styles.push(theme.gain(value, 1.0));
        }
        styles
    }

    #[test]
    fn every_colour_reads_on_its_background() {
        // 3:1, WCAG's least for large text and graphics: xterm's blue on
        // black is 2.2:1, its yellow on white 1.9:1.
        for (background, paper) in [
            (Background::Dark, (0, 0, 0)),
            (Background::Light, (255, 255, 255)),
        ] {
            let theme = Theme::new(background, ColorMode::Indexed);
            for style in text_styles(&theme) {
                if let Some(colour) = style.fg {
                    let ratio = contrast(xterm(colour), paper);
                    assert!(ratio >= 3.0, "{background}: {colour:?} {ratio:.2}");
                }
            }
        }
        assert!(contrast(xterm(Color::Blue), (0, 0, 0)) < 3.0);
    }

    #[test]
    fn no_colour_means_no_colour_and_the_paths_differ_by_glyph() {
        for background in [Background::Dark, Background::Light] {
            let theme = Theme::new(background, ColorMode::NoColor);
            for style in text_styles(&theme).into_iter().chain([
                theme.title,
                theme.selected,
                theme.mark(Color::Yellow),
                theme.swatch(Color::Red),
            ]) {
                assert!(style.fg.is_none() && style.bg.is_none(), "{style:?}");
            }
            assert_eq!(theme.rgb((10, 20, 30)), Color::Reset);
            let glyphs: Vec<&str> = (0..3).map(|k| theme.path(k).1).collect();
            assert_eq!(glyphs, ["━", "•", "▚"]);
        }
        assert_eq!(Theme::shade(0.0), "·");
        assert_eq!(Theme::shade(1.0), "█");
    }

    #[test]
    fn the_margin_scale_tells_over_the_wall_from_under_it() {
        // Magenta under the wall, green over it, grey at its top; both
        // ends dark enough to read on white, and light enough on black.
        for k in 0..=20 {
            let t = f64::from(k) / 20.0;
            let (r, g, b) = diverging(t);
            if t < 0.5 {
                assert!(r > g && b > g, "{t}: {:?}", (r, g, b));
                assert_eq!(margin_shade(t).chars().count(), 1);
                assert!(["=", "-", "·"].contains(&margin_shade(t)), "{t}");
            } else if t > 0.5 {
                assert!(g > r && g > b, "{t}: {:?}", (r, g, b));
                assert!(["░", "▒", "▓"].contains(&margin_shade(t)), "{t}");
            }
        }
        assert_eq!(diverging(0.5), (247, 247, 247));
        for end in [diverging(0.0), diverging(1.0)] {
            assert!(contrast(end, (255, 255, 255)) >= 3.0, "{end:?}");
            assert!(contrast(end, (0, 0, 0)) >= 2.0, "{end:?}");
        }
    }

    #[test]
    fn the_environment_chooses_the_colours_and_the_background() {
        assert_eq!(ColorMode::from_env(Some("1"), None), ColorMode::NoColor);
        // NO_COLOR set but empty does not count (no-color.org).
        assert_eq!(ColorMode::from_env(Some(""), None), ColorMode::Indexed);
        assert_eq!(
            ColorMode::from_env(None, Some("truecolor")),
            ColorMode::TrueColor
        );
        assert_eq!(
            ColorMode::from_env(Some("yes"), Some("truecolor")),
            ColorMode::NoColor
        );
        assert_eq!(Background::from_colorfgbg(Some("15;0")), Background::Dark);
        assert_eq!(Background::from_colorfgbg(Some("0;15")), Background::Light);
        assert_eq!(
            Background::from_colorfgbg(Some("0;default;15")),
            Background::Light
        );
        assert_eq!(Background::from_colorfgbg(Some("0;7")), Background::Light);
        assert_eq!(Background::from_colorfgbg(Some("7;8")), Background::Dark);
        assert_eq!(Background::from_colorfgbg(None), Background::Dark);
        assert_eq!("light".parse(), Ok(Background::Light));
        assert!("beige".parse::<Background>().is_err());
    }
}
