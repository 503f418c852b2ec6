//! The numbers: launch state, flight summary, impact summary, and the
//! optimum beside the current swing.

use ratatui::Frame;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph};

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
fn launch_text(app: &App, launch: &BattedBall, sign: bool) -> String {
    let text = |quantity, si, decimals| quantity_text(app.units, quantity, si, decimals, sign);
    format!(
        "{}  {}  {}",
        text(Quantity::Speed, launch.speed, 2),
        text(Quantity::Spin, launch.spin, 1),
        text(Quantity::Angle, launch.angle, 4)
    )
}

/// An angle as the readout writes it: "0.3791 rad" or "21.72°".
pub(super) fn angle(app: &App, radians: f64, sign: bool) -> String {
    angle_text(app.units, radians, READOUT_DECIMALS, sign)
}

/// The air in force: "ρ 1.194 kg/m³  ν 1.51e-5 m²/s" and where it comes
/// from, "from 21 °C, 5 m, 1013 hPa, 50 %" (in baseball units "from 70 °F,
/// 16 ft, 29.92 inHg, 50 %") or "(given)".
fn air(app: &App) -> (String, String) {
    let air = app.scene.environment.air();
    let values = format!(
        "ρ {:.3} kg/m³  ν {:.3e} m²/s",
        air.density, air.kinematic_viscosity
    );
    // In a park's own air (key `a`), whose: "COL's standard air at
    // 1579.8 m", while it is that (a weather typed since reads as any).
    let park = app.chosen_park().filter(|_| app.in_park_air());
    if let (Some(park), Some(a)) = (park, air.atmosphere)
        && a == (Atmosphere {
            elevation: park.elevation,
            ..Atmosphere::STANDARD
        })
    {
        let elevation = match app.units {
            UnitSystem::Si => format!("{} m", trimmed(a.elevation)),
            UnitSystem::Imperial => format!("{:.0} ft", app.distance(a.elevation).0),
        };
        let code = preset::escape_cut(&park.code, 8);
        return (values, format!("{code}'s standard air at {elevation}"));
    }
    let source = match air.atmosphere {
        Some(a) if app.units == UnitSystem::Imperial => {
            let unit = |q: Quantity| app.unit(q);
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

pub fn draw(frame: &mut Frame, area: Rect, app: &App) {
    let lines = lines(app, area);
    let inner = Block::bordered().inner(area);
    let block = Block::bordered().title(Span::styled(" Readout ", app.theme.title));
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
        super::read_all_hint(frame, area, app);
    }
}

/// A line's label, in the readout's first column.
fn label(app: &App, name: &'static str) -> Span<'static> {
    Span::styled(format!("{name:<9}"), app.theme.dim)
}

/// The readout's lines for a pane of `area`: what a short pane has no room
/// for is left out, or takes a less needed line's place. Each piece below
/// adds its lines in turn, in the order the pane shows them.
pub(super) fn lines(app: &App, area: Rect) -> Vec<Line<'static>> {
    let inner = Block::bordered().inner(area);
    let mut lines = launch_and_flight(app);
    lines.extend(impact_lines(app));
    // Air derived from the weather is worth a line even on a small screen,
    // where it takes the impulses' (tab 3 shows them); given air, the
    // paper's, is shown only with room to spare (below).
    let derived = app.scene.environment.atmosphere().is_some();
    if derived {
        let extra = air_lines(app, inner.width);
        if (inner.height as usize) < lines.len() + 3 + extra.len() && lines.len() > 3 {
            lines.remove(3);
        }
        for (k, line) in extra.into_iter().enumerate() {
            lines.insert(2 + k, line);
        }
    }
    insert_pin(app, inner, &mut lines);
    push_optimum(app, inner, &mut lines);
    // A batted ball's readout has room for its landing: no impact, no optimum.
    let batted = !app.is_swing();
    if batted && app.flown.flight.landed {
        lines.push(landing_line(app));
    }
    push_fence_and_parks(app, &mut lines);
    place_park_verdict(app, inner, &mut lines);
    place_paper_line(app, inner, &mut lines);
    // A batted ball's readout has room for the given air too, and for the
    // models in force (Nathan's unless chosen: not the swing's).
    if batted && !derived {
        lines.extend(air_lines(app, inner.width));
    }
    if batted {
        lines.push(Line::from(vec![
            label(app, "model"),
            Span::raw(app.scene.models_text()),
        ]));
    }
    // Room to spare (the large layouts): the rest of the story.
    if area.height as usize >= lines.len() + 6 {
        lines.extend(the_rest(app, derived, inner.width));
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
fn launch_and_flight(app: &App) -> Vec<Line<'static>> {
    let flight = &app.flown.flight;
    let (d, u) = (|metres: f64| app.distance(metres).0, app.distance(1.0).1);
    vec![
        Line::from(vec![
            label(app, "launch"),
            Span::raw(launch_text(app, &app.flown.launch, false)),
        ]),
        Line::from(vec![
            label(app, "flight"),
            // A ball that does not land has no range: where it is instead
            // (the end of the drawn path).
            if flight.landed {
                Span::raw(format!(
                    "range {}{}  {:.2} s  apex\u{a0}{:.1} {u}",
                    app.range_text(flight.range),
                    App::landing_call(flight).map_or(String::new(), |c| format!(" {c}")),
                    flight.flight_time,
                    d(flight.apex)
                ))
            } else {
                Span::styled(
                    format!(
                        "did not land in {:.0} s ({:.0} {u} up)",
                        flight.flight_time,
                        d(app.path.last().map_or(0.0, |p| p.1))
                    ),
                    app.theme.busy,
                )
            },
        ]),
    ]
}

/// A swing's impact and its impulses (a batted ball has none).
fn impact_lines(app: &App) -> Vec<Line<'static>> {
    let Some(impact) = &app.flown.impact else {
        return Vec::new();
    };
    vec![
        Line::from(vec![
            label(app, "impact"),
            Span::raw(format!(
                "e* {:.4}  {}  θ {}",
                impact.restitution(),
                match impact.regime() {
                    // It sticks, then springs back (bat.tangential_restitution).
                    Regime::Stick if impact.release_impulse() > 0.0 => "grip",
                    Regime::Stick => "stick",
                    Regime::Slip => "slip",
                },
                angle(app, impact.normal_angle(), false),
            )),
        ]),
        Line::from(vec![
            label(app, "impulse"),
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
fn air_lines(app: &App, width: u16) -> Vec<Line<'static>> {
    let (values, source) = air(app);
    let one = format!("{values}  {source}");
    if 9 + Span::raw(one.as_str()).width() <= width as usize {
        vec![Line::from(vec![label(app, "air"), Span::raw(one)])]
    } else {
        vec![
            Line::from(vec![label(app, "air"), Span::raw(values)]),
            Line::from(vec![label(app, ""), Span::raw(source)]),
        ]
    }
}

/// The pinned scene: now − pin under the launch and the flight. When the
/// pane is short, the deltas take the impact's two lines (tab 3 shows it).
fn insert_pin(app: &App, inner: Rect, lines: &mut Vec<Line<'static>>) {
    let Some(pin) = &app.pin else {
        return;
    };
    let flight = &app.flown.flight;
    let (d, u) = (|metres: f64| app.distance(metres).0, app.distance(1.0).1);
    let (now, was, was_flight) = (&app.flown.launch, &pin.flown.launch, &pin.flown.flight);
    let pinned = |text: String| {
        Line::from(vec![
            label(app, " now−pin"),
            Span::styled(text, app.theme.pinned),
        ])
    };
    let difference = BattedBall {
        speed: now.speed - was.speed,
        angle: now.angle - was.angle,
        spin: now.spin - was.spin,
        direction: now.direction - was.direction,
        sidespin: now.sidespin - was.sidespin,
    };
    let launch = pinned(launch_text(app, &difference, true));
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
fn push_optimum(app: &App, inner: Rect, lines: &mut Vec<Line<'static>>) {
    if !app.is_swing() {
        return;
    }
    let Some(o) = app.optimum else {
        lines.push(Line::from(vec![
            label(app, "optimum"),
            Span::styled("searching…", app.theme.busy),
        ]));
        return;
    };
    // Nothing that lands yet: no range to show.
    if !o.best.range.is_finite() {
        lines.push(Line::from(vec![
            label(app, "optimum"),
            if o.done {
                let why = match o.status {
                    Status::NothingLands => "no swing of 64 over the window lands",
                    _ => "no swing tried lands (stopped at a limit)",
                };
                Span::styled(format!("none: {why}"), app.theme.error)
            } else {
                Span::styled("searching… no swing lands yet", app.theme.busy)
            },
        ]));
        return;
    }
    let style = if o.done {
        app.theme.good
    } else {
        app.theme.busy
    };
    let state = optimum_tags(&o);
    let (d, u) = (|metres: f64| app.distance(metres).0, app.distance(1.0).1);
    let optimum = format!(
        "E {}  ψ {}  {:.2} {u}",
        undercut_text(app.units, o.best.undercut, false),
        angle(app, o.best.swing_angle, false),
        d(o.best.range)
    );
    // Tags that do not fit take a line of their own (at 80×24 the
    // impulses', which tab 3 shows), rather than wrap mid-tag.
    if 9 + Span::raw(format!("{optimum}{state}")).width() <= inner.width as usize {
        lines.push(Line::from(vec![
            label(app, "optimum"),
            Span::styled(optimum + &state, style),
        ]));
    } else {
        lines.push(Line::from(vec![
            label(app, "optimum"),
            Span::styled(optimum, style),
        ]));
        lines.push(Line::from(vec![
            label(app, ""),
            Span::styled(state.trim().to_owned(), style),
        ]));
        // Still to come: you − opt and the fence.
        if (inner.height as usize) < lines.len() + 2 {
            remove_labelled(lines, "impulse");
        }
    }
    let flight = &app.flown.flight;
    let range = if flight.landed {
        format!("{} {u}", signed(d(flight.range - o.best.range), 2))
    } else {
        "—".to_owned()
    };
    let (e, psi) = (app.scene.bat.undercut, app.scene.bat.swing_angle);
    lines.push(Line::from(vec![
        label(app, "you −opt"),
        Span::raw(format!(
            "ΔE {}  Δψ {}  {range}",
            undercut_text(app.units, e - o.best.undercut, true),
            angle(app, psi - o.best.swing_angle, true),
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
fn landing_line(app: &App) -> Line<'static> {
    let (flight, speed) = (&app.flown.flight, app.unit(Quantity::Speed));
    Line::from(vec![
        label(app, "landing"),
        Span::raw(format!(
            "{:.2} {} at {} below level",
            speed.show(flight.landing_speed),
            speed.symbol,
            angle_text(app.units, flight.landing_angle, 3, false)
        )),
    ])
}

/// Whether it clears the preset's fence (without a park), in the command
/// line's words, and the count of parks.
fn push_fence_and_parks(app: &App, lines: &mut Vec<Line<'static>>) {
    if let Some(fence) = app.fence.filter(|_| app.park.is_none()) {
        let unit = app.unit(Quantity::Distance);
        let mut text = fence_text(fence.distance, fence.height, app.fence_height, unit);
        // "falls short" undersells a ball hit behind the plate or foul.
        if let Some(call) = App::landing_call(&app.flown.flight)
            && let Some((fence, _)) = text.split_once(": ")
        {
            text = format!("{fence}: {call}, no home run");
        }
        lines.push(Line::from(vec![label(app, "fence"), Span::raw(text)]));
    }
    if let Some(at) = &app.at_parks {
        lines.push(Line::from(vec![
            label(app, "parks"),
            Span::raw(parks_text(app, at)),
        ]));
    }
}

/// With a park chosen its verdict is the point: where the pane is too
/// short for it in its place (80×24 with derived air), it comes right
/// after the flight (the impact and the rest are on their tabs).
fn place_park_verdict(app: &App, inner: Rect, lines: &mut Vec<Line<'static>>) {
    let rows = inner.height as usize;
    if app.park.is_some()
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
fn place_paper_line(app: &App, inner: Rect, lines: &mut Vec<Line<'static>>) {
    let Some(paper) = super::paper_line::line(app) else {
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
fn the_rest(app: &App, derived: bool, width: u16) -> Vec<Line<'static>> {
    let batted = !app.is_swing();
    let mut lines = Vec::new();
    if !derived && !batted {
        lines.extend(air_lines(app, width));
    }
    if app.flown.flight.landed && !batted {
        lines.push(landing_line(app));
    }
    if let Some(impact) = &app.flown.impact {
        let speed = app.unit(Quantity::Speed);
        lines.push(Line::from(vec![
            label(app, "pitch"),
            Span::raw(format!(
                "{:.1} {}, descending {}",
                speed.show(app.scene.pitch.speed),
                speed.symbol,
                angle(app, impact.descent_angle(), false)
            )),
        ]));
    }
    if !batted {
        lines.push(Line::from(vec![
            label(app, "model"),
            Span::raw(app.scene.models_text()),
        ]));
    }
    lines.push(Line::from(vec![
        label(app, "drag"),
        Span::raw(app.scene.drag.description()),
    ]));
    lines.push(Line::from(vec![
        label(app, "lift"),
        Span::raw(app.scene.lift.description()),
    ]));
    if app.scene.spin_decay > 0.0 {
        lines.push(Line::from(vec![
            label(app, "spin"),
            Span::raw(format!(
                "decays as e^(−t/{} s)",
                trimmed(app.scene.spin_decay)
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
fn parks_text(app: &App, at: &crate::app::AtParks) -> String {
    use model::clearing::Outcome;
    let (Some(park), Some(here)) = (app.chosen_park(), at.here) else {
        return format!("clears {} of {} parks", at.cleared, at.of);
    };
    let code = preset::escape_cut(&park.code, 8);
    let unit = app.unit(Quantity::Distance);
    let by = |m: f64| format!("{:.1} {}", unit.show_difference(m.abs()), unit.symbol);
    let verdict = match (here.outcome, here.margin) {
        (Outcome::Clears, Some(m)) => format!("clears by {}", by(m)),
        (Outcome::OffTheWall, Some(m)) => format!("off the wall by {}", by(m)),
        (Outcome::Short, Some(m)) => format!("short by {}", by(m)),
        (outcome, _) => outcome.name().to_owned(),
    };
    format!("{code} {verdict}; {}/{} parks", at.cleared, at.of)
}
