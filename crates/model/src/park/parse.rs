//! Parks from the text of a park file (`data/parks.toml`'s format, see
//! docs/parks.md): one `[[park]]` table per park, SI units.

use serde::Deserialize;

use super::fence::{Fence, FenceError, FencePoint};
use super::home::{HOME_FORMS, HomeSpan, spans_text};
use super::{EarlierWalls, Park, ParkDimensions};

/// Why a park file's text is not a list of parks. The message is one line;
/// the caller names the file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParkError {
    #[error("malformed park file: {message}")]
    Syntax { message: String },
    #[error("no [[park]] table: a park file holds one or more")]
    Empty,
    #[error("park {code}: {field} = {value}: {expected}")]
    Field {
        code: String,
        field: &'static str,
        value: String,
        expected: &'static str,
    },
    #[error("park {code}: fence {source}")]
    Fence { code: String, source: FenceError },
    #[error("park {code}: earlier walls {walls}: fence {source}")]
    EarlierFence {
        code: String,
        walls: String,
        source: FenceError,
    },
    #[error("park {code} is given twice (as {first} and {second})")]
    Twice {
        code: String,
        first: String,
        second: String,
    },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    #[serde(default)]
    park: Vec<Entry>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Entry {
    code: String,
    #[serde(default)]
    aliases: Vec<String>,
    name: String,
    #[serde(default)]
    city: String,
    elevation: f64,
    center_field_bearing: f64,
    #[serde(default)]
    published: Option<Published>,
    fence: Vec<Point>,
    #[serde(default)]
    home: Vec<String>,
    /// When its fence stood (absent: its `home`).
    #[serde(default)]
    walls: Option<Vec<String>>,
    /// `[[park.earlier]]`: other walls and when they stood.
    #[serde(default)]
    earlier: Vec<Earlier>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Earlier {
    walls: Vec<String>,
    fence: Vec<Point>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Published {
    left_line: f64,
    center: f64,
    right_line: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Point {
    direction: f64,
    distance: f64,
    height: f64,
}

/// A bundled park as build.rs writes it from data/parks.toml: the file's
/// fields, unchecked (fence points as [direction, distance, height]).
pub(super) struct BundledEntry {
    pub code: &'static str,
    pub aliases: &'static [&'static str],
    pub name: &'static str,
    pub city: &'static str,
    pub elevation: f64,
    pub center_field_bearing: f64,
    pub published: Option<[f64; 3]>,
    pub fence: &'static [[f64; 3]],
    pub home: &'static [&'static str],
    /// `walls`, if the file gives it.
    pub walls: Option<&'static [&'static str]>,
    /// `earlier`: each one's `walls` and fence.
    pub earlier: &'static [(&'static [&'static str], &'static [[f64; 3]])],
}

impl BundledEntry {
    /// The park, checked as a park file's would be.
    pub(super) fn checked(&self) -> Result<Park, ParkError> {
        Entry {
            code: self.code.to_owned(),
            aliases: self.aliases.iter().map(|&a| a.to_owned()).collect(),
            name: self.name.to_owned(),
            city: self.city.to_owned(),
            elevation: self.elevation,
            center_field_bearing: self.center_field_bearing,
            published: self
                .published
                .map(|[left_line, center, right_line]| Published {
                    left_line,
                    center,
                    right_line,
                }),
            fence: points(self.fence),
            home: self.home.iter().map(|&h| h.to_owned()).collect(),
            walls: (self.walls).map(|spans| spans.iter().map(|&w| w.to_owned()).collect()),
            earlier: (self.earlier.iter())
                .map(|(walls, fence)| Earlier {
                    walls: walls.iter().map(|&w| w.to_owned()).collect(),
                    fence: points(fence),
                })
                .collect(),
        }
        .checked()
    }
}

/// A bundled fence's points, as a park file's.
fn points(fence: &[[f64; 3]]) -> Vec<Point> {
    (fence.iter())
        .map(|&[direction, distance, height]| Point {
            direction,
            distance,
            height,
        })
        .collect()
}

/// Elevations accepted (m): the Dead Sea's shore to well above any park
/// (the same range as `environment.elevation`).
const ELEVATION: (f64, f64) = (-500.0, 5000.0);

/// The parks in `text`, each checked: a code of 1 to 8 letters or digits
/// (and its aliases), a name, an elevation in [-500, 5000] m, a bearing in
/// [0, 360)°, published distances in (0, 1000] m if given, and a fence
/// ([`Fence::new`]). Codes are compared without case.
pub fn parse(text: &str) -> Result<Vec<Park>, ParkError> {
    let file: File = toml::from_str(text).map_err(|e| ParkError::Syntax {
        message: one_line(&e),
    })?;
    if file.park.is_empty() {
        return Err(ParkError::Empty);
    }
    let mut parks: Vec<Park> = Vec::with_capacity(file.park.len());
    for entry in file.park {
        let park = entry.checked()?;
        for code in park.codes() {
            if let Some(other) = parks.iter().find(|p| p.answers_to(code)) {
                return Err(ParkError::Twice {
                    code: code.to_owned(),
                    first: other.code.clone(),
                    second: park.code.clone(),
                });
            }
        }
        parks.push(park);
    }
    Ok(parks)
}

/// The toml crate's message with the line it points at, on one line.
fn one_line(error: &toml::de::Error) -> String {
    let message = error.message().trim().replace('\n', " ");
    match error.span() {
        Some(span) => format!("{message} (at byte {})", span.start),
        None => message,
    }
}

fn is_code(code: &str) -> bool {
    (1..=8).contains(&code.len()) && code.chars().all(|c| c.is_ascii_alphanumeric())
}

impl Entry {
    fn checked(self) -> Result<Park, ParkError> {
        let code = self.code.to_ascii_uppercase();
        let field = |field, value: String, expected| ParkError::Field {
            code: code.clone(),
            field,
            value,
            expected,
        };
        if !is_code(&self.code) {
            return Err(field(
                "code",
                format!("{:?}", self.code),
                "1 to 8 letters or digits, as Baseball Savant's home_team (e.g. \"BOS\")",
            ));
        }
        for alias in &self.aliases {
            if !is_code(alias) {
                return Err(field(
                    "aliases",
                    format!("{alias:?}"),
                    "each 1 to 8 letters or digits",
                ));
            }
        }
        let name = self.name.trim();
        if name.is_empty() || name.chars().count() > 80 || name.chars().any(char::is_control) {
            return Err(field(
                "name",
                format!("{:?}", self.name.chars().take(80).collect::<String>()),
                "1 to 80 characters, none of them control characters",
            ));
        }
        if self.city.chars().count() > 80 || self.city.chars().any(char::is_control) {
            return Err(field(
                "city",
                format!("{:?}", self.city.chars().take(80).collect::<String>()),
                "at most 80 characters, none of them control characters",
            ));
        }
        let (low, high) = ELEVATION;
        if !(self.elevation.is_finite() && (low..=high).contains(&self.elevation)) {
            return Err(field(
                "elevation",
                self.elevation.to_string(),
                "must be a finite number in [-500, 5000] m",
            ));
        }
        let bearing = self.center_field_bearing;
        if !(bearing.is_finite() && (0.0..360.0).contains(&bearing)) {
            return Err(field(
                "center_field_bearing",
                bearing.to_string(),
                "must be a finite number in [0, 360) degrees clockwise from true north",
            ));
        }
        let published = match self.published {
            None => None,
            Some(p) => {
                for (name, value) in [
                    ("published.left_line", p.left_line),
                    ("published.center", p.center),
                    ("published.right_line", p.right_line),
                ] {
                    if !(value.is_finite() && value > 0.0 && value <= 1000.0) {
                        return Err(field(
                            name,
                            value.to_string(),
                            "must be a finite number in (0, 1000] m",
                        ));
                    }
                }
                Some(ParkDimensions {
                    left_line: p.left_line,
                    center: p.center,
                    right_line: p.right_line,
                })
            }
        };
        // `home` and `walls` are read alike; walls absent stood while home.
        let spans = |name, texts: &[String]| -> Result<Vec<HomeSpan>, ParkError> {
            (texts.iter())
                .map(|text| {
                    HomeSpan::parse(text)
                        .ok_or_else(|| field(name, format!("{text:?}"), HOME_FORMS))
                })
                .collect()
        };
        let home = spans("home", &self.home)?;
        let walls = match &self.walls {
            Some(texts) => spans("walls", texts)?,
            None => home.clone(),
        };
        let fence = Fence::new(fence_points(self.fence)).map_err(|source| ParkError::Fence {
            code: code.clone(),
            source,
        })?;
        let mut earlier: Vec<EarlierWalls> = Vec::with_capacity(self.earlier.len());
        // The days other walls stood: the fence's (no spans: every day),
        // then each earlier one's as it is read.
        let mut taken = match walls.is_empty() {
            true => vec![HomeSpan {
                from: None,
                to: None,
            }],
            false => walls.clone(),
        };
        for Earlier {
            walls: texts,
            fence,
        } in self.earlier
        {
            let spans = spans("earlier.walls", &texts)?;
            if spans.is_empty() {
                let expected = "one or more spans: the days those walls stood";
                return Err(field("earlier.walls", "[]".to_owned(), expected));
            }
            // A day has one set of walls: earlier ones on the days of the
            // fence as given would never be met.
            if let Some(text) = (spans.iter().zip(&texts))
                .find(|(span, _)| taken.iter().any(|t| t.overlaps(span)))
                .map(|(_, text)| text)
            {
                return Err(field(
                    "earlier.walls",
                    format!("{text:?}"),
                    "days no other walls of the park stood: outside its `walls` (its `home` \
                     years where `walls` is not given) and each other earlier walls'",
                ));
            }
            let fence =
                Fence::new(fence_points(fence)).map_err(|source| ParkError::EarlierFence {
                    code: code.clone(),
                    walls: spans_text(&spans),
                    source,
                })?;
            taken.extend_from_slice(&spans);
            earlier.push(EarlierWalls {
                walls: spans,
                fence,
            });
        }
        Ok(Park {
            code,
            aliases: self
                .aliases
                .iter()
                .map(|a| a.to_ascii_uppercase())
                .collect(),
            name: self.name.trim().to_owned(),
            city: self.city.trim().to_owned(),
            elevation: self.elevation,
            center_field_bearing: bearing,
            published,
            fence,
            home,
            walls,
            earlier,
        })
    }
}

fn fence_points(points: Vec<Point>) -> Vec<FencePoint> {
    (points.into_iter())
        .map(|p| FencePoint {
            direction: p.direction,
            distance: p.distance,
            height: p.height,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const ONE: &str = r#"
[[park]]
code = "xyz"
aliases = ["xy1"]
name = "Test Field"
elevation = 100
center_field_bearing = 90
fence = [
  { direction = -0.7854, distance = 100, height = 3 },
  { direction = 0.7854, distance = 100, height = 3 },
]
"#;

    #[test]
    fn a_minimal_park_parses_with_codes_in_capitals() {
        let parks = parse(ONE).unwrap();
        assert_eq!(parks.len(), 1);
        let park = &parks[0];
        assert_eq!(
            (park.code.as_str(), park.aliases[0].as_str()),
            ("XYZ", "XY1")
        );
        assert_eq!(park.published, None);
        assert_eq!(park.fence.distance_at(0.3), Some(100.0));
    }

    #[test]
    fn errors_name_the_park_and_the_field() {
        let bad = ONE.replace("elevation = 100", "elevation = 9000");
        assert_eq!(
            parse(&bad).unwrap_err().to_string(),
            "park XYZ: elevation = 9000: must be a finite number in [-500, 5000] m"
        );
        let bad = ONE.replace(
            "distance = 100, height = 3 },\n]",
            "distance = 0, height = 3 },\n]",
        );
        assert_eq!(
            parse(&bad).unwrap_err().to_string(),
            "park XYZ: fence point 1: distance = 0: must be a finite number in (0, 1000] m"
        );
        let bad = ONE.replace("fence =", "home = [\"2025..2024\"]\nfence =");
        assert_eq!(
            parse(&bad).unwrap_err().to_string(),
            format!("park XYZ: home = \"2025..2024\": {}", super::HOME_FORMS)
        );
        let good = ONE.replace("fence =", "home = [\"2025..2027\"]\nfence =");
        assert_eq!(parse(&good).unwrap()[0].home[0].to_string(), "2025–2027");
        // Walls default to the home spans; given, they are read alike.
        assert_eq!(
            parse(&good).unwrap()[0].walls,
            parse(&good).unwrap()[0].home
        );
        let walls = good.replace("fence =", "walls = [\"2026..\"]\nfence =");
        assert_eq!(parse(&walls).unwrap()[0].walls[0].to_string(), "2026 on");
        let bad = good.replace("fence =", "walls = [\"2026\"]\nfence =");
        assert_eq!(
            parse(&bad).unwrap_err().to_string(),
            format!("park XYZ: walls = \"2026\": {}", super::HOME_FORMS)
        );
        // Earlier walls: when they stood, and their fence, checked alike.
        let earlier = format!(
            "{}[[park.earlier]]\nwalls = [\"2001..2010\"]\nfence = [\n  {{ direction = -0.7854, \
             distance = 90, height = 2 }},\n  {{ direction = 0.7854, distance = 90, height = 2 }},\n]\n",
            ONE.replace("fence =", "walls = [\"2011..\"]\nfence =")
        );
        let park = &parse(&earlier).unwrap()[0];
        assert_eq!(park.earlier[0].walls[0].to_string(), "2001–2010");
        assert_eq!(park.earlier[0].fence.distance_at(0.0), Some(90.0));
        assert_eq!(park.fence_of(Some(0)), &park.earlier[0].fence);
        assert_eq!(park.fence_of(None), &park.fence);
        let bad = earlier.replace(
            "distance = 90, height = 2 },\n]",
            "distance = 0, height = 2 },\n]",
        );
        assert_eq!(
            parse(&bad).unwrap_err().to_string(),
            "park XYZ: earlier walls 2001–2010: fence point 1: distance = 0: must be a finite \
             number in (0, 1000] m"
        );
        // Earlier walls on a day of the walls as given, or of other
        // earlier ones, or without a day, are refused.
        let overlap = "park XYZ: earlier.walls = \"2005..2011\": days no other walls of the park \
                       stood: outside its `walls` (its `home` years where `walls` is not given) \
                       and each other earlier walls'";
        let bad = earlier.replace("\"2001..2010\"", "\"2005..2011\"");
        assert_eq!(parse(&bad).unwrap_err().to_string(), overlap);
        let block = &earlier[earlier.find("[[park.earlier]]").unwrap()..];
        let twice = format!("{earlier}{}", block.replace("2001..2010", "2009..2010"));
        let e = parse(&twice).unwrap_err().to_string();
        assert!(
            e.starts_with("park XYZ: earlier.walls = \"2009..2010\": days no"),
            "{e}"
        );
        let apart = format!("{earlier}{}", block.replace("2001..2010", "1995..2000"));
        assert_eq!(parse(&apart).unwrap()[0].earlier.len(), 2);
        let no_walls = earlier.replace("walls = [\"2011..\"]\n", "");
        assert!(
            parse(&no_walls)
                .unwrap_err()
                .to_string()
                .contains("\"2001..2010\": days no")
        );
        let no_days = earlier.replace("[\"2001..2010\"]", "[]");
        assert_eq!(
            parse(&no_days).unwrap_err().to_string(),
            "park XYZ: earlier.walls = []: one or more spans: the days those walls stood"
        );
        let bad = earlier.replace("\"2001..2010\"", "\"2010..2001\"");
        assert_eq!(
            parse(&bad).unwrap_err().to_string(),
            format!(
                "park XYZ: earlier.walls = \"2010..2001\": {}",
                super::HOME_FORMS
            )
        );
        let bad = ONE.replace("name =", "nmae =");
        let e = parse(&bad).unwrap_err().to_string();
        assert!(
            e.starts_with("malformed park file: unknown field `nmae`"),
            "{e}"
        );
        assert!(!e.contains('\n'), "{e}");
        assert_eq!(parse("").unwrap_err(), ParkError::Empty);
        let bad = ONE.replace("Test Field", "Test\\u001b[2JField");
        let e = parse(&bad).unwrap_err().to_string();
        assert!(
            e.starts_with("park XYZ: name = \"Test\\u{1b}[2JField\": 1 to 80"),
            "{e}"
        );
        let twice = format!(
            "{ONE}{}",
            ONE.replace("\"xyz\"", "\"XY1\"").replace("xy1\"]", "q\"]")
        );
        assert!(matches!(
            parse(&twice).unwrap_err(),
            ParkError::Twice { .. }
        ));
    }
}
