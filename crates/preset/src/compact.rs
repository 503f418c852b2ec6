//! Many presets held compactly: a Savant file's swings (`tui --savant`),
//! up to a million of them, in about a third of a kilobyte each.
//!
//! A swing's scene differs from its neighbours' in a few numbers: the
//! pitch and the bat its solve found, and its contact height. The rest
//! (the ball, the park's air, the season's bat, the fence) is shared by
//! thousands, so each swing keeps those few numbers and the index of a
//! shared background: everything else, interned once. The names and
//! descriptions are kept one after another in one text, without a
//! string (and its allocation) each. [`CompactPresets::preset`] gives a
//! swing back bit for bit as it was pushed.

use std::collections::HashMap;

use model::scene::Scene;

use crate::Preset;

/// The numbers each swing keeps for itself: read from its scene, and
/// written into its background to give the scene back.
const OWN_NUMBERS: [fn(&mut Scene) -> &mut f64; 9] = [
    |s| &mut s.pitch.speed,
    |s| &mut s.pitch.spin,
    |s| &mut s.bat.speed,
    |s| &mut s.bat.undercut,
    |s| &mut s.bat.swing_angle,
    |s| &mut s.bat.tilt,
    |s| &mut s.bat.direction,
    |s| &mut s.bat.lead,
    |s| &mut s.environment.contact_height,
];

/// One swing: its own numbers, its background, and where its name and
/// description end in the text.
#[derive(Clone, Copy, Debug)]
struct Compact {
    numbers: [f64; OWN_NUMBERS.len()],
    background: u32,
    name_end: usize,
    description_end: usize,
}

/// Presets in a list, each held as a few numbers, a shared background and
/// its text (see the module's doc).
#[derive(Debug, Default)]
pub struct CompactPresets {
    swings: Vec<Compact>,
    /// The presets with their own numbers zeroed and no name or
    /// description, each once.
    backgrounds: Vec<Preset>,
    /// Each background's index, by its `Debug` text: equal texts are equal
    /// bits (Rust prints a float's shortest exact form, -0 apart from 0).
    background_index: HashMap<String, u32>,
    /// Every name and description, one after another.
    text: String,
}

impl CompactPresets {
    pub fn new() -> CompactPresets {
        CompactPresets::default()
    }

    /// Adds `preset` at the end of the list.
    pub fn push(&mut self, preset: &Preset) {
        let mut background = Preset {
            name: String::new(),
            description: String::new(),
            ..preset.clone()
        };
        let mut numbers = [0.0; OWN_NUMBERS.len()];
        for (number, field) in numbers.iter_mut().zip(OWN_NUMBERS) {
            *number = std::mem::take(field(&mut background.scene));
        }
        let key = format!("{background:?}");
        let count = self.backgrounds.len();
        let index = *self.background_index.entry(key).or_insert_with(|| {
            // A list of a million swings shares a few dozen backgrounds:
            // never near 4 billion.
            u32::try_from(count).expect("fewer than 4 billion backgrounds")
        });
        if index as usize == count {
            self.backgrounds.push(background);
        }
        self.text.push_str(&preset.name);
        let name_end = self.text.len();
        self.text.push_str(&preset.description);
        self.swings.push(Compact {
            numbers,
            background: index,
            name_end,
            description_end: self.text.len(),
        });
    }

    /// Gives back the room left for more: the list is complete.
    pub fn shrink_to_fit(&mut self) {
        self.swings.shrink_to_fit();
        self.backgrounds.shrink_to_fit();
        self.background_index = HashMap::new();
        self.text.shrink_to_fit();
    }

    pub fn len(&self) -> usize {
        self.swings.len()
    }

    pub fn is_empty(&self) -> bool {
        self.swings.is_empty()
    }

    /// How many backgrounds the swings share.
    pub fn backgrounds(&self) -> usize {
        self.backgrounds.len()
    }

    /// Swing `i`'s name.
    pub fn name(&self, i: usize) -> &str {
        let start = match i {
            0 => 0,
            _ => self.swings[i - 1].description_end,
        };
        &self.text[start..self.swings[i].name_end]
    }

    /// Swing `i`'s description.
    pub fn description(&self, i: usize) -> &str {
        let swing = &self.swings[i];
        &self.text[swing.name_end..swing.description_end]
    }

    /// Swing `i`, as it was pushed.
    pub fn preset(&self, i: usize) -> Preset {
        let swing = &self.swings[i];
        let mut preset = self.backgrounds[swing.background as usize].clone();
        for (number, field) in swing.numbers.iter().zip(OWN_NUMBERS) {
            *field(&mut preset.scene) = *number;
        }
        preset.name = self.name(i).to_owned();
        preset.description = self.description(i).to_owned();
        preset
    }
}

impl FromIterator<Preset> for CompactPresets {
    fn from_iter<I: IntoIterator<Item = Preset>>(presets: I) -> CompactPresets {
        let mut list = CompactPresets::new();
        for preset in presets {
            list.push(&preset);
        }
        list.shrink_to_fit();
        list
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Presets that differ in their own numbers, their backgrounds (a -0
    /// wind against a 0 one too) and their texts come back bit for bit,
    /// sharing one background where only their own numbers differ.
    #[test]
    fn every_preset_comes_back_bit_for_bit() {
        let base = crate::load("fastball", None).unwrap();
        let mut presets = Vec::new();
        for i in 0..40 {
            let mut p = base.clone();
            p.name = format!("swing {i}");
            p.description = format!("ψ ° line {i}");
            p.scene.bat.undercut = 0.001 * f64::from(i);
            p.scene.pitch.speed = 40.0 + f64::from(i) / 3.0;
            p.scene.environment.contact_height = 0.7 + f64::from(i) * 1e-3;
            if i % 10 == 9 {
                p.scene.environment.wind = -0.0;
            }
            if i % 20 == 19 {
                p.fence = None;
            }
            presets.push(p);
        }
        let list: CompactPresets = presets.iter().cloned().collect();
        assert_eq!(list.len(), 40);
        // Base, -0 wind, and -0 wind without a fence.
        assert_eq!(list.backgrounds(), 3);
        for (i, p) in presets.iter().enumerate() {
            let back = list.preset(i);
            assert_eq!(format!("{back:?}"), format!("{p:?}"));
            assert_eq!(back, *p);
            assert_eq!(
                (list.name(i), list.description(i)),
                (&*p.name, &*p.description)
            );
        }
        assert_eq!(
            list.preset(9).scene.environment.wind.to_bits(),
            (-0.0f64).to_bits()
        );
    }
}
