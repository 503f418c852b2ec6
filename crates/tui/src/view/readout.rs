//! The numbers: launch state, flight summary, impact summary, and the
//! optimum beside the current swing.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph};

use super::pane_views::InUnits;
use super::readout_view::Readout;
use crate::app::{App, OptimumState};
use crate::format::signed;
use crate::shown::{READOUT_DECIMALS, angle_text, quantity_text, undercut_text};
use analysis::figures::trimmed;
use analysis::landing::fence_text;
use analysis::optimum::Status;
use model::atmosphere::Atmosphere;
use model::impact::Regime;
use model::launch::BattedBall;
use units::{Quantity, UnitSystem};

/// A launch as the readout writes it, in the units shown: "44.30 m/s
/// 191.8 rad/s  0.4604 rad" or "99.09 mph  1832 rpm  26.38°"; with `sign`,
/// a difference of two ("+1.20 mph  +95 rpm  -0.50°").
fn launch_text(view: &Readout, launch: &BattedBall, sign: bool) -> String {
    let text = |quantity, si, decimals| quantity_text(view.units, quantity, si, decimals, sign);
    format!(
        "{}  {}  {}",
        text(Quantity::Speed, launch.speed, 2),
        text(Quantity::Spin, launch.spin, 1),
        text(Quantity::Angle, launch.angle, 4)
    )
}

/// An angle as the readout writes it: "0.3791 rad" or "21.72°".
pub(super) fn angle(view: &Readout, radians: f64, sign: bool) -> String {
    angle_text(view.units, radians, READOUT_DECIMALS, sign)
}

/// The air in force: "ρ 1.194 kg/m³  ν 1.51e-5 m²/s" and where it comes
/// from, "from 21 °C, 5 m, 1013 hPa, 50 %" (in baseball units "from 70 °F,
/// 16 ft, 29.92 inHg, 50 %") or "(given)".
fn air(view: &Readout) -> (String, String) {
    let air = view.scene.environment.air();
    let values = format!(
        "ρ {:.3} kg/m³  ν {:.3e} m²/s",
        air.density, air.kinematic_viscosity
    );
    // In a park's own air (key `a`), whose: "COL's standard air at
    // 1579.8 m", while it is that (a weather typed since reads as any).
    let park = view.park.filter(|_| view.in_park_air);
    if let (Some(park), Some(a)) = (park, air.atmosphere)
        && a == (Atmosphere {
            elevation: park.elevation,
            ..Atmosphere::STANDARD
        })
    {
        let elevation = match view.units {
            UnitSystem::Si => format!("{} m", trimmed(a.elevation)),
            UnitSystem::Imperial => format!("{:.0} ft", view.distance(a.elevation).0),
        };
        let code = preset::escape_cut(&park.code, 8);
        return (values, format!("{code}'s standard air at {elevation}"));
    }
    let source = match air.atmosphere {
        Some(a) if view.units == UnitSystem::Imperial => {
            let unit = |q: Quantity| view.unit(q);
            format!(
                "from {} °F, {:.0} ft, {:.2} inHg, {} %",
                trimmed((unit(Quantity::Temperature).show(a.temperature) * 10.0).round() / 10.0),
                unit(Quantity::Distance).show(a.elevation),
                unit(Quantity::Pressure).show(a.pressure),
                trimmed(a.humidity)
            )
        }
        Some(a) => format!(
            "from {} °C, {} m, {} hPa, {} %",
            trimmed(a.temperature),
            trimmed(a.elevation),
            trimmed(a.pressure),
            trimmed(a.humidity)
        ),
        None => "(given)".to_owned(),
    };
    (values, source)
}

pub fn draw(frame: &mut Frame, area: Rect, view: &Readout) {
    let lines = lines(view, area);
    let inner = Block::bordered().inner(area);
    let block = Block::bordered().title(Span::styled(" Readout ", view.theme.title));
    // Rows past the pane's foot (at 80×24 the parks and the air, at 120×40
    // a model's description): `i` shows them all.
    let needed: usize = lines
        .iter()
        .map(|l| super::words::rows_needed(&l.spans, inner.width as usize))
        .sum();
    let cut = needed > inner.height as usize;
    // Long lines (a model's description) wrap rather than run off the pane.
    frame.render_widget(
        Paragraph::new(lines)
            .block(block)
            .wrap(ratatui::widgets::Wrap { trim: false }),
        area,
    );
    if cut {
        super::read_all_hint(frame, area, view.theme);
    }
}

/// A line's label, in the readout's first column.
fn label(view: &Readout, name: &'static str) -> Span<'static> {
    Span::styled(format!("{name:<9}"), view.theme.dim)
}

/// The readout's lines for a pane of `area`: what a short pane has no room
/// for is left out, or takes a less needed line's place. Each piece below
/// adds its lines in turn, in the order the pane shows them.
pub(super) fn lines(view: &Readout, area: Rect) -> Vec<Line<'static>> {
    let inner = Block::bordered().inner(area);
    let mut lines = launch_and_flight(view);
    lines.extend(impact_lines(view));
    // Air derived from the weather is worth a line even on a small screen,
    // where it takes the impulses' (tab 3 shows them); given air, the
    // paper's, is shown only with room to spare (below).
    let derived = view.scene.environment.atmosphere().is_some();
    if derived {
        let extra = air_lines(view, inner.width);
        if (inner.height as usize) < lines.len() + 3 + extra.len() && lines.len() > 3 {
            lines.remove(3);
        }
        for (k, line) in extra.into_iter().enumerate() {
            lines.insert(2 + k, line);
        }
    }
    insert_pin(view, inner, &mut lines);
    push_optimum(view, inner, &mut lines);
    // A batted ball's readout has room for its landing: no impact, no optimum.
    let batted = !view.is_swing();
    if batted && view.flown.flight.landed {
        lines.push(landing_line(view));
    }
    push_fence_and_parks(view, &mut lines);
    place_park_verdict(view, inner, &mut lines);
    place_paper_line(view, inner, &mut lines);
    // A batted ball's readout has room for the given air too, and for the
    // models in force (Nathan's unless chosen: not the swing's).
    if batted && !derived {
        lines.extend(air_lines(view, inner.width));
    }
    if batted {
        lines.push(Line::from(vec![
            label(view, "model"),
            Span::raw(view.scene.models_text()),
        ]));
    }
    // Room to spare (the large layouts): the rest of the story.
    if area.height as usize >= lines.len() + 6 {
        lines.extend(the_rest(view, derived, inner.width));
    }
    let mut lines = glued(lines);
    keep_fence_in_view(inner, &mut lines);
    lines
}

/// A line that wraps (you − opt far from the optimum, "ΔE +0.0162 m  Δψ
/// +0.0433 rad  -533.45 m" at 80×24) must not push the fence off a short
/// pane: the impact's lines give up their rows first (tab 3 shows them).
fn keep_fence_in_view(inner: Rect, lines: &mut Vec<Line<'static>>) {
    let width = inner.width as usize;
    for name in ["impulse", "impact"] {
        let rows_to_fence = labelled(lines, "fence").map(|k| {
            lines[..=k]
                .iter()
                .map(|l| super::words::rows_needed(&l.spans, width))
                .sum::<usize>()
        });
        if rows_to_fence.is_none_or(|rows| rows <= inner.height as usize) {
            return;
        }
        remove_labelled(lines, name);
    }
}

/// The launch and the flight: "launch 44.30 m/s …", "flight range …".
fn launch_and_flight(view: &Readout) -> Vec<Line<'static>> {
    let flight = &view.flown.flight;
    let (d, u) = (|metres: f64| view.distance(metres).0, view.distance(1.0).1);
    vec![
        Line::from(vec![
            label(view, "launch"),
            Span::raw(launch_text(view, &view.flown.launch, false)),
        ]),
        Line::from(vec![
            label(view, "flight"),
            // A ball that does not land has no range: where it is instead
            // (the end of the drawn path).
            if flight.landed {
                Span::raw(format!(
                    "range {}{}  {:.2} s  apex\u{a0}{:.1} {u}",
                    view.range_text(flight.range),
                    App::landing_call(flight).map_or(String::new(), |c| format!(" {c}")),
                    flight.flight_time,
                    d(flight.apex)
                ))
            } else {
                Span::styled(
                    format!(
                        "did not land in {:.0} s ({:.0} {u} up)",
                        flight.flight_time,
                        d(view.path_end_height)
                    ),
                    view.theme.busy,
                )
            },
        ]),
    ]
}

/// A swing's impact and its impulses (a batted ball has none).
fn impact_lines(view: &Readout) -> Vec<Line<'static>> {
    let Some(impact) = &view.flown.impact else {
        return Vec::new();
    };
    vec![
        Line::from(vec![
            label(view, "impact"),
            Span::raw(format!(
                "e* {:.4}  {}  θ {}",
                impact.restitution(),
                match impact.regime() {
                    // It sticks, then springs back (bat.tangential_restitution).
                    Regime::Stick if impact.release_impulse() > 0.0 => "grip",
                    Regime::Stick => "stick",
                    Regime::Slip => "slip",
                },
                angle(view, impact.normal_angle(), false),
            )),
        ]),
        Line::from(vec![
            label(view, "impulse"),
            Span::raw(format!(
                "p_s {} p_c {:.3} p_f {:.3} N·s",
                impact
                    .stick_impulse()
                    .map_or("—".to_owned(), |p| format!("{p:.3}")),
                impact.compression_impulse(),
                impact.separation_impulse()
            )),
        ]),
    ]
}

/// The air's line, or two where `width` is narrow.
fn air_lines(view: &Readout, width: u16) -> Vec<Line<'static>> {
    let (values, source) = air(view);
    let one = format!("{values}  {source}");
    if 9 + Span::raw(one.as_str()).width() <= width as usize {
        vec![Line::from(vec![label(view, "air"), Span::raw(one)])]
    } else {
        vec![
            Line::from(vec![label(view, "air"), Span::raw(values)]),
            Line::from(vec![label(view, ""), Span::raw(source)]),
        ]
    }
}

/// The pinned scene: now − pin under the launch and the flight. When the
/// pane is short, the deltas take the impact's two lines (tab 3 shows it).
fn insert_pin(view: &Readout, inner: Rect, lines: &mut Vec<Line<'static>>) {
    let Some(pin) = &view.pin else {
        return;
    };
    let flight = &view.flown.flight;
    let (d, u) = (|metres: f64| view.distance(metres).0, view.distance(1.0).1);
    let (now, was, was_flight) = (&view.flown.launch, &pin.flown.launch, &pin.flown.flight);
    let pinned = |text: String| {
        Line::from(vec![
            label(view, " now−pin"),
            Span::styled(text, view.theme.pinned),
        ])
    };
    let difference = BattedBall {
        speed: now.speed - was.speed,
        angle: now.angle - was.angle,
        spin: now.spin - was.spin,
        direction: now.direction - was.direction,
        sidespin: now.sidespin - was.sidespin,
    };
    let launch = pinned(launch_text(view, &difference, true));
    let range = if flight.landed && was_flight.landed {
        format!("{} {u}", signed(d(flight.range - was_flight.range), 2))
    } else {
        "— (not both land)".to_owned()
    };
    let flight = pinned(format!(
        "range {range}  apex {} {u}",
        signed(d(flight.apex - was_flight.apex), 1)
    ));
    let short = (inner.height as usize) < lines.len() + 5;
    if short {
        lines.retain(|l| {
            !l.spans
                .first()
                .is_some_and(|s| ["impact", "impulse"].contains(&s.content.trim()))
        });
    }
    lines.insert(2, flight);
    lines.insert(1, launch);
}

/// The optimum, its tags and you − opt (a swing's: a batted ball has no
/// swing to optimise).
fn push_optimum(view: &Readout, inner: Rect, lines: &mut Vec<Line<'static>>) {
    if !view.is_swing() {
        return;
    }
    let Some(o) = view.optimum else {
        lines.push(Line::from(vec![
            label(view, "optimum"),
            Span::styled("searching…", view.theme.busy),
        ]));
        return;
    };
    // Nothing that lands yet: no range to show.
    if !o.best.range.is_finite() {
        lines.push(Line::from(vec![
            label(view, "optimum"),
            if o.done {
                let why = match o.status {
                    Status::NothingLands => "no swing of 64 over the window lands",
                    _ => "no swing tried lands (stopped at a limit)",
                };
                Span::styled(format!("none: {why}"), view.theme.error)
            } else {
                Span::styled("searching… no swing lands yet", view.theme.busy)
            },
        ]));
        return;
    }
    let style = if o.done {
        view.theme.good
    } else {
        view.theme.busy
    };
    let state = optimum_tags(&o);
    let (d, u) = (|metres: f64| view.distance(metres).0, view.distance(1.0).1);
    let optimum = format!(
        "E {}  ψ {}  {:.2} {u}",
        undercut_text(view.units, o.best.undercut, false),
        angle(view, o.best.swing_angle, false),
        d(o.best.range)
    );
    // Tags that do not fit take a line of their own (at 80×24 the
    // impulses', which tab 3 shows), rather than wrap mid-tag.
    if 9 + Span::raw(format!("{optimum}{state}")).width() <= inner.width as usize {
        lines.push(Line::from(vec![
            label(view, "optimum"),
            Span::styled(optimum + &state, style),
        ]));
    } else {
        lines.push(Line::from(vec![
            label(view, "optimum"),
            Span::styled(optimum, style),
        ]));
        lines.push(Line::from(vec![
            label(view, ""),
            Span::styled(state.trim().to_owned(), style),
        ]));
        // Still to come: you − opt and the fence.
        if (inner.height as usize) < lines.len() + 2 {
            remove_labelled(lines, "impulse");
        }
    }
    let flight = &view.flown.flight;
    let range = if flight.landed {
        format!("{} {u}", signed(d(flight.range - o.best.range), 2))
    } else {
        "—".to_owned()
    };
    let (e, psi) = (view.scene.bat.undercut, view.scene.bat.swing_angle);
    lines.push(Line::from(vec![
        label(view, "you −opt"),
        Span::raw(format!(
            "ΔE {}  Δψ {}  {range}",
            undercut_text(view.units, e - o.best.undercut, true),
            angle(view, psi - o.best.swing_angle, true),
        )),
    ]));
}

/// Why the optimum is what it is, after its numbers: " (searching)", "
/// (work limit)", " (time limit)"…, or nothing.
fn optimum_tags(o: &OptimumState) -> String {
    let mut state = match (o.done, o.status) {
        (false, _) => " (searching)",
        (true, Status::OutOfWork) => " (work limit)",
        (true, Status::OutOfEvaluations) => " (eval. limit)",
        (true, _) => "",
    }
    .to_owned();
    // A hovering ball's best lands just before the flight's time
    // limit: the limit, not the swing, sets that range.
    if o.best.at_time_limit {
        state.push_str(" (time limit)");
    }
    // Its best grazes the ground at the optimiser's precision only.
    if !o.lands_at_readout {
        state.push_str(" (readout: does not land)");
    }
    state
}

/// The landing: "23.34 m/s at 0.836 rad below level".
fn landing_line(view: &Readout) -> Line<'static> {
    let (flight, speed) = (&view.flown.flight, view.unit(Quantity::Speed));
    Line::from(vec![
        label(view, "landing"),
        Span::raw(format!(
            "{:.2} {} at {} below level",
            speed.show(flight.landing_speed),
            speed.symbol,
            angle_text(view.units, flight.landing_angle, 3, false)
        )),
    ])
}

/// Whether it clears the preset's fence (without a park), in the command
/// line's words, and the count of parks.
fn push_fence_and_parks(view: &Readout, lines: &mut Vec<Line<'static>>) {
    if let Some(fence) = view.fence.filter(|_| view.park.is_none()) {
        let unit = view.unit(Quantity::Distance);
        let mut text = fence_text(fence.distance, fence.height, view.fence_height, unit);
        // "falls short" undersells a ball hit behind the plate or foul.
        if let Some(call) = App::landing_call(&view.flown.flight)
            && let Some((fence, _)) = text.split_once(": ")
        {
            text = format!("{fence}: {call}, no home run");
        }
        lines.push(Line::from(vec![label(view, "fence"), Span::raw(text)]));
    }
    if let Some(at) = &view.at_parks {
        lines.push(Line::from(vec![
            label(view, "parks"),
            Span::raw(parks_text(view, at)),
        ]));
    }
}

/// With a park chosen its verdict is the point: where the pane is too
/// short for it in its place (80×24 with derived air), it comes right
/// after the flight (the impact and the rest are on their tabs).
fn place_park_verdict(view: &Readout, inner: Rect, lines: &mut Vec<Line<'static>>) {
    let rows = inner.height as usize;
    if view.park.is_some()
        && lines.len() > rows
        && rows > 3
        && let Some(k) = labelled(lines, "parks")
    {
        let verdict = lines.remove(k);
        let after_flight = labelled(lines, "flight").map_or(0, |f| f + 1);
        lines.insert(after_flight, verdict);
    }
}

/// The paper's optimum under ours, on a Table II preset, after the
/// optimum and its tags; at 80×24 in the impulses' row (tab 3 shows
/// them) and the parks' (`i` shows them), never the fence's.
fn place_paper_line(view: &Readout, inner: Rect, lines: &mut Vec<Line<'static>>) {
    let Some(paper) = super::paper_line::line(view) else {
        return;
    };
    let rows = inner.height as usize;
    if lines.len() + 1 > rows {
        remove_labelled(lines, "impulse");
    }
    let parks_last = labelled(lines, "parks").is_some_and(|k| k + 1 == lines.len());
    if (lines.len() < rows || lines.len() == rows && parks_last)
        && let Some(k) = labelled(lines, "optimum")
    {
        let tags = lines
            .get(k + 1)
            .is_some_and(|l| l.spans.first().is_some_and(|s| s.content.trim().is_empty()));
        lines.insert(k + 1 + usize::from(tags), paper);
    }
}

/// What a large pane has room for: the given air, the landing, the
/// pitch, the models and their descriptions, the spin's decay.
fn the_rest(view: &Readout, derived: bool, width: u16) -> Vec<Line<'static>> {
    let batted = !view.is_swing();
    let mut lines = Vec::new();
    if !derived && !batted {
        lines.extend(air_lines(view, width));
    }
    if view.flown.flight.landed && !batted {
        lines.push(landing_line(view));
    }
    if let Some(impact) = &view.flown.impact {
        let speed = view.unit(Quantity::Speed);
        lines.push(Line::from(vec![
            label(view, "pitch"),
            Span::raw(format!(
                "{:.1} {}, descending {}",
                speed.show(view.scene.pitch.speed),
                speed.symbol,
                angle(view, impact.descent_angle(), false)
            )),
        ]));
    }
    if !batted {
        lines.push(Line::from(vec![
            label(view, "model"),
            Span::raw(view.scene.models_text()),
        ]));
    }
    lines.push(Line::from(vec![
        label(view, "drag"),
        Span::raw(view.scene.drag.description()),
    ]));
    lines.push(Line::from(vec![
        label(view, "lift"),
        Span::raw(view.scene.lift.description()),
    ]));
    if view.scene.spin_decay > 0.0 {
        lines.push(Line::from(vec![
            label(view, "spin"),
            Span::raw(format!(
                "decays as e^(−t/{} s)",
                trimmed(view.scene.spin_decay)
            )),
        ]));
    }
    lines
}

/// `lines` with each number glued to its unit, so that they wrap together
/// ("27.3 m", "50 %").
fn glued(lines: Vec<Line<'static>>) -> Vec<Line<'static>> {
    lines
        .into_iter()
        .map(|line| {
            let spans = line.spans.into_iter().map(|span| {
                let content = super::words::non_breaking(&span.content, |next| {
                    !next.is_ascii_digit() && !next.is_whitespace() && next != '('
                });
                Span::styled(content, span.style)
            });
            Line::from(spans.collect::<Vec<_>>())
        })
        .collect()
}

/// `lines` without the one labelled `name`, if any.
fn remove_labelled(lines: &mut Vec<Line<'static>>, name: &str) {
    lines.retain(|l| l.spans.first().is_none_or(|s| s.content.trim() != name));
}

/// Where the line labelled `name` is among `lines`.
fn labelled(lines: &[Line], name: &str) -> Option<usize> {
    lines
        .iter()
        .position(|l| l.spans.first().is_some_and(|s| s.content.trim() == name))
}

/// "clears 26 of 30 parks", or with a park chosen "BOS clears by 8.6 m;
/// 26/30 parks" (off the wall by, short by, foul), in the units shown.
fn parks_text(view: &Readout, at: &crate::app::AtParks) -> String {
    use model::clearing::Outcome;
    let (Some(park), Some(here)) = (view.park, at.here) else {
        return format!("clears {} of {} parks", at.cleared, at.of);
    };
    let code = preset::escape_cut(&park.code, 8);
    let unit = view.unit(Quantity::Distance);
    let by = |m: f64| format!("{:.1} {}", unit.show_difference(m.abs()), unit.symbol);
    let verdict = match (here.outcome, here.margin) {
        (Outcome::Clears, Some(m)) => format!("clears by {}", by(m)),
        (Outcome::OffTheWall, Some(m)) => format!("off the wall by {}", by(m)),
        (Outcome::Short, Some(m)) => format!("short by {}", by(m)),
        (outcome, _) => outcome.name().to_owned(),
    };
    format!("{code} {verdict}; {}/{} parks", at.cleared, at.of)
}
