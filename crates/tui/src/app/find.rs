//! The picker's find (`/`): the items whose name and description hold
//! every word typed, in any case.
//!
//! Each key costs one pass over the items still found, never one over all
//! of them per word: a character typed can only narrow the list (the word
//! it extends or starts must now be held too, and the other words already
//! are), so only the word it touched is looked for, and only among the
//! items found; a Backspace puts back what that character took out. A
//! 1000-character query on 200,000 swings is as quick a key as a short one
//! (docs/speed.md). Queries and items are lower-cased a character at a
//! time, so that a word's lower case is its start's lower case extended.
//! An item whose only upper case is ASCII's (a Savant file's swings,
//! nearly all: ψ and ° are their own lower case) is searched as it is,
//! ASCII case aside, which is its lower case searched: no copy of its text
//! is held (a million swings' ~270 MB).

use std::sync::Arc;

use aho_corasick::AhoCorasick;
use memchr::memmem;
use preset::Preset;
use preset::compact::CompactPresets;

use super::PickItem;

/// An item the picker lists: a swing of a Savant file's (its index among
/// them: a million swings are not a million items), or a preset.
#[derive(Clone, Debug)]
pub enum Pick {
    Swing(u32),
    Preset(Arc<PickItem>),
}

impl Pick {
    /// Its name, a swing's from `swings`.
    pub fn name<'a>(&'a self, swings: &'a Searchable) -> &'a str {
        match self {
            Pick::Swing(i) => swings.name(*i as usize),
            Pick::Preset(item) => &item.name,
        }
    }

    /// Its description (a broken preset's error), a swing's from `swings`.
    pub fn detail<'a>(&'a self, swings: &'a Searchable) -> &'a str {
        match self {
            Pick::Swing(i) => swings.detail(*i as usize),
            Pick::Preset(item) => &item.detail,
        }
    }

    /// The preset it loads, if it is not broken.
    pub fn preset(&self, swings: &Searchable) -> Option<Preset> {
        match self {
            Pick::Swing(i) => match &swings.items {
                Items::Swings(list) => Some(list.preset(*i as usize)),
                Items::Presets(_) => None,
            },
            Pick::Preset(item) => item.preset.clone(),
        }
    }
}

/// Items a find can choose from, and the name and description in lower
/// case of each item with an upper case outside ASCII, one after another. A Savant
/// file's swings are made so once, when they are offered, so that `/`
/// costs nothing on 200,000 of them.
#[derive(Debug, Default)]
pub struct Searchable {
    items: Items,
    texts: String,
    /// Item `i`'s text in lower case ends at `ends[i]` (it starts where
    /// the one before ends): empty for an item lower-cased as ASCII is.
    ends: Vec<usize>,
}

/// What a [`Searchable`] holds: a Savant file's swings, compact, or
/// presets.
#[derive(Debug)]
enum Items {
    Swings(CompactPresets),
    Presets(Vec<Arc<PickItem>>),
}

impl Default for Items {
    fn default() -> Items {
        Items::Presets(Vec::new())
    }
}

/// An item's text as a find searches it.
enum Text<'a> {
    /// Its name and description as they are, lower-cased as ASCII is.
    AsIs(&'a str, &'a str),
    /// Both in lower case, a space between.
    Lower(&'a [u8]),
}

impl Searchable {
    /// A Savant file's swings.
    pub fn swings(swings: CompactPresets) -> Searchable {
        Searchable::new(Items::Swings(swings))
    }

    pub fn presets(items: Vec<Arc<PickItem>>) -> Searchable {
        Searchable::new(Items::Presets(items))
    }

    fn new(items: Items) -> Searchable {
        let mut searchable = Searchable {
            items,
            texts: String::new(),
            ends: Vec::new(),
        };
        let (mut texts, mut ends) = (String::new(), Vec::with_capacity(searchable.len()));
        for i in 0..searchable.len() {
            let (name, detail) = (searchable.name(i), searchable.detail(i));
            if !(lowers_as_ascii(name) && lowers_as_ascii(detail)) {
                push_lower_case(&mut texts, name);
                texts.push(' ');
                push_lower_case(&mut texts, detail);
            }
            ends.push(texts.len());
        }
        texts.shrink_to_fit();
        (searchable.texts, searchable.ends) = (texts, ends);
        searchable
    }

    pub fn len(&self) -> usize {
        match &self.items {
            Items::Swings(list) => list.len(),
            Items::Presets(items) => items.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Item `i`'s name.
    pub fn name(&self, i: usize) -> &str {
        match &self.items {
            Items::Swings(list) => list.name(i),
            Items::Presets(items) => &items[i].name,
        }
    }

    /// Item `i`'s description.
    pub fn detail(&self, i: usize) -> &str {
        match &self.items {
            Items::Swings(list) => list.description(i),
            Items::Presets(items) => &items[i].detail,
        }
    }

    /// Item `i`, as the picker lists it.
    fn pick(&self, i: usize) -> Pick {
        match &self.items {
            Items::Presets(items) => Pick::Preset(Arc::clone(&items[i])),
            // Fewer than 4 billion: each took a row of a file.
            Items::Swings(_) => Pick::Swing(i as u32),
        }
    }

    /// Every item, as the picker lists them.
    pub fn picks(&self) -> impl Iterator<Item = Pick> + '_ {
        (0..self.len()).map(|i| self.pick(i))
    }

    fn text_of(&self, i: usize) -> Text<'_> {
        let start = if i == 0 { 0 } else { self.ends[i - 1] };
        match start == self.ends[i] {
            true => Text::AsIs(self.name(i), self.detail(i)),
            false => Text::Lower(&self.texts.as_bytes()[start..self.ends[i]]),
        }
    }
}

/// A find being typed in the picker.
#[derive(Debug)]
pub struct Find {
    pub text: String,
    /// What the find chooses from: the swings, then the presets (listed
    /// again at each `/`: the user's folder may have changed).
    swings: Arc<Searchable>,
    presets: Searchable,
    /// The indices of the items found, ascending: a swing's in `swings`,
    /// a preset's after them.
    found: Vec<u32>,
    /// For each character of `text`, the items it took out of `found`.
    removed: Vec<Vec<u32>>,
    /// How many times an item's text was searched, for the tests of the
    /// work a key does.
    searches: u64,
}

impl Find {
    /// A find over `swings` and `presets`, nothing typed yet, and the items
    /// it finds: all of them.
    pub fn new(swings: Arc<Searchable>, presets: Searchable) -> (Find, Vec<Pick>) {
        let items: Vec<Pick> = swings.picks().chain(presets.picks()).collect();
        // The picker lists swings and presets: never near 4 billion.
        let found = (0..items.len()).map(|i| i as u32).collect();
        let find = Find {
            text: String::new(),
            swings,
            presets,
            found,
            removed: Vec::new(),
            searches: 0,
        };
        (find, items)
    }

    /// Item `i`'s text.
    fn text_of(&self, i: u32) -> Text<'_> {
        let i = i as usize;
        match i.checked_sub(self.swings.len()) {
            None => self.swings.text_of(i),
            Some(preset) => self.presets.text_of(preset),
        }
    }

    /// Item `i`.
    fn item(&self, i: u32) -> Pick {
        let i = i as usize;
        match i.checked_sub(self.swings.len()) {
            None => self.swings.pick(i),
            Some(preset) => self.presets.pick(preset),
        }
    }

    /// Types `c`: the items found (`found`, as the picker lists them) keep
    /// those that hold the word it ends.
    pub fn push(&mut self, c: char, found: &mut Vec<Pick>) {
        self.text.push(c);
        if c.is_whitespace() {
            // No word changed.
            self.removed.push(Vec::new());
            return;
        }
        let mut word = String::new();
        push_lower_case(
            &mut word,
            self.text.split_whitespace().last().unwrap_or_default(),
        );
        let finder = memmem::Finder::new(word.as_bytes());
        // The word in any ASCII case: in a text whose only upper case is
        // ASCII's, the lower-case word's matches are those in its lower
        // case.
        let any_case = AhoCorasick::builder()
            .ascii_case_insensitive(true)
            .build([word.as_bytes()])
            .expect("one word is a small automaton");
        let mut held = Vec::with_capacity(self.found.len());
        let mut removed = Vec::new();
        for &i in &self.found {
            let holds = match self.text_of(i) {
                Text::AsIs(name, detail) => any_case.is_match(name) || any_case.is_match(detail),
                Text::Lower(text) => finder.find(text).is_some(),
            };
            if !holds {
                removed.push(i);
            }
            held.push(holds);
        }
        self.searches += self.found.len() as u64;
        if !removed.is_empty() {
            let mut keep = held.iter();
            self.found.retain(|_| *keep.next().unwrap_or(&true));
            let mut keep = held.iter();
            found.retain(|_| *keep.next().unwrap_or(&true));
        }
        self.removed.push(removed);
    }

    /// Erases the last character typed, if any: the items it had taken out
    /// of `found` are found again, in their places.
    pub fn pop(&mut self, found: &mut Vec<Pick>) {
        if self.text.pop().is_none() {
            return;
        }
        let back = self.removed.pop().unwrap_or_default();
        if back.is_empty() {
            return;
        }
        // Both ascending: merged, the list keeps the picker's order. The
        // items found move; only those put back are made anew.
        let mut indices = Vec::with_capacity(self.found.len() + back.len());
        let mut items = Vec::with_capacity(indices.capacity());
        let old = std::mem::take(found);
        let mut kept = self.found.iter().copied().zip(old).peekable();
        let mut back = back.into_iter().peekable();
        loop {
            let from_kept = match (kept.peek(), back.peek()) {
                (Some((k, _)), Some(b)) => k < b,
                (Some(_), None) => true,
                (None, Some(_)) => false,
                (None, None) => break,
            };
            let (index, item) = match from_kept {
                true => kept.next().expect("peeked"),
                false => {
                    let index = back.next().expect("peeked");
                    (index, self.item(index))
                }
            };
            indices.push(index);
            items.push(item);
        }
        self.found = indices;
        *found = items;
    }

    /// How many times an item's text has been searched since `/`.
    pub fn searches(&self) -> u64 {
        self.searches
    }
}

/// Whether `text`'s lower case is its ASCII lower case: every other
/// character its own lower case.
fn lowers_as_ascii(text: &str) -> bool {
    text.chars()
        .all(|c| c.is_ascii() || c.to_lowercase().eq([c]))
}

/// Appends `text` in lower case a character at a time (no final-sigma
/// rule, which would make a word's lower case change as it is typed); runs
/// of ASCII in one go, as most of a Savant file's text is.
fn push_lower_case(out: &mut String, text: &str) {
    let mut rest = text;
    while !rest.is_empty() {
        let ascii = rest
            .bytes()
            .position(|b| !b.is_ascii())
            .unwrap_or(rest.len());
        let start = out.len();
        out.push_str(&rest[..ascii]);
        out[start..].make_ascii_lowercase();
        rest = &rest[ascii..];
        let mut chars = rest.chars();
        if let Some(c) = chars.next() {
            out.extend(c.to_lowercase());
        }
        rest = chars.as_str();
    }
}
