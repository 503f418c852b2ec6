//! Users' own parks: files of `data/parks.toml`'s format (one or more
//! `[[park]]` tables) in the parks folder, `parks` in
//! [`super::config_dir`] beside the presets, or `--parks-dir`. Each is read safely
//! ([`read_text`]); a user's park whose code or alias names a bundled park
//! hides that park, as a user's preset hides a bundled one.

use std::path::{Path, PathBuf};

use super::file::preset_files;
use super::{PresetError, escape_cut, read_text, shown};
use model::park::{self, Park};

/// The user's parks folder: `parks` in [`super::config_dir`].
pub fn user_dir() -> Option<PathBuf> {
    super::config_dir().map(|d| d.join("parks"))
}

/// Every park available, bundled first (less those a user's park hides),
/// then the user's, with the file each came from.
#[derive(Clone, Debug, Default)]
pub struct Parks {
    pub parks: Vec<Park>,
    /// The file of each park in `parks`; `None`: bundled.
    pub files: Vec<Option<PathBuf>>,
    /// Said once when the folder held more than [`MAX_USER_PARKS`] parks
    /// or files: which were read.
    pub note: Option<String>,
}

impl Parks {
    /// The park `code` names: by code, then by alias, any case.
    pub fn find(&self, code: &str) -> Option<&Park> {
        park::find(&self.parks, code)
    }

    /// The park `query` names as a user types it: a code or alias, a name
    /// or a city, or the start of a word of one ([`park::named`]).
    pub fn named(&self, query: &str) -> park::Named<'_> {
        park::named(&self.parks, query)
    }

    /// Every code, aliases in parentheses: "AZ (ARI), ATL, …".
    pub fn codes(&self) -> String {
        self.parks
            .iter()
            .map(|p| match p.aliases.as_slice() {
                [] => p.code.clone(),
                aliases => format!("{} ({})", p.code, aliases.join(", ")),
            })
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// [`all`], its note (if any) said on stderr: for the command line.
pub fn all_noted(dir: Option<&Path>) -> Result<Parks, PresetError> {
    let parks = all(dir)?;
    if let Some(note) = &parks.note {
        eprintln!("{note}");
    }
    Ok(parks)
}

/// The most parks read from the user's folder, and the most files: every
/// park a batch row may name is checked against every row's flight, and a
/// folder of thousands (6,600 parks took 2.35 GB and 68 s over a batch of
/// 20,000 rows) is a mistake, not a league. 200 holds the majors' 30, the
/// minors' 120 and room besides.
pub const MAX_USER_PARKS: usize = 200;

/// The bundled parks and the user's from `dir` (every `*.toml` in it, in
/// name order; a missing folder holds none), at most [`MAX_USER_PARKS`] of
/// them from as many files (the rest left, and [`Parks::note`] says so). A
/// broken file is an error naming it: a park silently missing would change
/// every count of parks.
pub fn all(dir: Option<&Path>) -> Result<Parks, PresetError> {
    let mut user: Vec<(Park, PathBuf)> = Vec::new();
    let mut note = None;
    if let Some(dir) = dir {
        let files = preset_files(dir)?;
        let (mut read, mut capped) = (0, false);
        'files: for path in &files {
            if read == MAX_USER_PARKS || user.len() == MAX_USER_PARKS {
                capped = true;
                break;
            }
            read += 1;
            let text = read_text(path)?;
            let parks = park::parse(&text).map_err(|e| PresetError::Park {
                path: shown(path),
                message: escape_cut(&e.to_string(), 400),
            })?;
            for park in parks {
                if let Some((other, file)) = user
                    .iter()
                    .find(|(o, _)| park.codes().any(|c| o.answers_to(c)))
                {
                    return Err(PresetError::Park {
                        path: shown(path),
                        message: format!(
                            "park {} is also in {} (as {}); keep it in one file",
                            park.code,
                            shown(file),
                            other.code
                        ),
                    });
                }
                if user.len() == MAX_USER_PARKS {
                    capped = true;
                    break 'files;
                }
                user.push((park, path.clone()));
            }
        }
        if capped {
            note = Some(format!(
                "note: {}: more than {MAX_USER_PARKS} parks or files ({} files); only the first {} parks, from the first {read} files in name order, are used",
                shown(dir),
                files.len(),
                user.len(),
            ));
        }
    }
    let hidden = |bundled: &Park| {
        user.iter()
            .any(|(u, _)| u.codes().any(|c| bundled.answers_to(c)))
    };
    let mut out = Parks {
        note,
        ..Parks::default()
    };
    for p in park::bundled().iter().filter(|p| !hidden(p)) {
        out.parks.push(p.clone());
        out.files.push(None);
    }
    for (p, file) in user {
        out.parks.push(p);
        out.files.push(Some(file));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINE: &str = "[[park]]\ncode = \"BOS\"\nname = \"My Fenway\"\nelevation = 6\ncenter_field_bearing = 45\nfence = [\n  { direction = -0.7854, distance = 80, height = 2 },\n  { direction = 0.7854, distance = 80, height = 2 },\n]\n";

    #[test]
    fn a_user_park_hides_the_bundled_one_of_its_code() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("fenway.toml"), MINE).unwrap();
        let parks = all(Some(dir.path())).unwrap();
        assert_eq!(parks.parks.len(), park::bundled().len());
        let bos = parks.find("bos").unwrap();
        assert_eq!(bos.name, "My Fenway");
        assert_eq!(bos.fence.distance_at(0.0), Some(80.0));
        let index = parks.parks.iter().position(|p| p.code == "BOS").unwrap();
        assert!(parks.files[index].is_some());
        // No folder, or a missing one: the bundled parks alone.
        assert_eq!(all(None).unwrap().parks.len(), 30);
        assert_eq!(all(Some(&dir.path().join("none"))).unwrap().parks.len(), 30);
    }

    #[test]
    fn at_most_200_user_parks_are_read_with_a_note() {
        // Issue 25 row 11: thousands of parks were all read.
        let dir = tempfile::tempdir().unwrap();
        for i in 0..250 {
            let code = format!("Z{i:03}");
            let text = MINE.replace("\"BOS\"", &format!("\"{code}\""));
            std::fs::write(dir.path().join(format!("{code}.toml")), text).unwrap();
        }
        let parks = all(Some(dir.path())).unwrap();
        assert_eq!(parks.parks.len(), 30 + MAX_USER_PARKS);
        assert_eq!(parks.parks.last().unwrap().code, "Z199");
        let note = parks.note.unwrap();
        assert!(
            note.contains("(250 files); only the first 200 parks"),
            "{note}"
        );
        // Many parks in one file: the same cap.
        let dir = tempfile::tempdir().unwrap();
        let many: String = (0..300)
            .map(|i| MINE.replace("\"BOS\"", &format!("\"Y{i:03}\"")))
            .collect();
        std::fs::write(dir.path().join("many.toml"), many).unwrap();
        let parks = all(Some(dir.path())).unwrap();
        assert_eq!(parks.parks.len(), 30 + MAX_USER_PARKS);
        assert!(parks.note.is_some());
        // Under the cap: no note.
        assert!(all(None).unwrap().note.is_none());
    }

    #[test]
    fn a_broken_park_file_is_one_line_naming_it() {
        let dir = tempfile::tempdir().unwrap();
        let bad = MINE.replace(
            "distance = 80, height = 2 },\n]",
            "distance = 80, height = -2 },\n]",
        );
        std::fs::write(dir.path().join("bad.toml"), bad).unwrap();
        let e = all(Some(dir.path())).unwrap_err().to_string();
        assert!(
            e.ends_with(
                "bad.toml: park BOS: fence point 1: height = -2: must be a finite number in (0, 100] m"
            ),
            "{e}"
        );
        std::fs::write(dir.path().join("bad.toml"), MINE).unwrap();
        std::fs::write(dir.path().join("copy.toml"), MINE).unwrap();
        let e = all(Some(dir.path())).unwrap_err().to_string();
        assert!(e.contains("copy.toml: park BOS is also in"), "{e}");
    }
}
