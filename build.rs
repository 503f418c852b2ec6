//! Turns `data/parks.toml` into Rust statics (`$OUT_DIR/bundled_parks.rs`),
//! so that no run parses 190 kB of TOML: that parse took ~5 ms, most of a
//! `homerun fly`'s start-up (callgrind: 19 of 26 M instructions). The model
//! still checks every bundled park as it checks a user's park file
//! (`model::park::parse`), and a test holds the statics equal to a parse of
//! the file itself, so the file stays the one source.
//!
//! Where the binary is linked statically, it is also linked at a fixed
//! address ([`link_at_a_fixed_address`]).

use std::fmt::Write as _;

fn main() {
    link_at_a_fixed_address();
    bundled_presets();
    let source = "data/parks.toml";
    println!("cargo::rerun-if-changed={source}");
    println!("cargo::rerun-if-changed=build.rs");
    let text = std::fs::read_to_string(source).expect("data/parks.toml is readable");
    let file: toml::Table = text.parse().expect("data/parks.toml is TOML");
    let parks = file["park"].as_array().expect("[[park]] tables");
    let mut out = String::from("&[\n");
    for park in parks {
        let park = park.as_table().expect("a [[park]] table");
        let text = |key: &str| format!("{:?}", park[key].as_str().expect(key));
        let number = |value: &toml::Value| -> f64 {
            value
                .as_float()
                .or_else(|| value.as_integer().map(|i| i as f64))
                .expect("a number")
        };
        let aliases: Vec<String> = park
            .get("aliases")
            .and_then(|a| a.as_array())
            .map(|a| {
                a.iter()
                    .map(|s| format!("{:?}", s.as_str().expect("alias")))
                    .collect()
            })
            .unwrap_or_default();
        let published = match park.get("published").and_then(|p| p.as_table()) {
            Some(p) => format!(
                "Some([{:?}, {:?}, {:?}])",
                number(&p["left_line"]),
                number(&p["center"]),
                number(&p["right_line"])
            ),
            None => "None".to_owned(),
        };
        let _ = write!(
            out,
            "BundledEntry {{ code: {}, aliases: &[{}], name: {}, city: {:?}, elevation: {:?}, \
             center_field_bearing: {:?}, published: {published}, fence: &[",
            text("code"),
            aliases.join(", "),
            text("name"),
            park.get("city").and_then(|c| c.as_str()).unwrap_or(""),
            number(&park["elevation"]),
            number(&park["center_field_bearing"]),
        );
        for point in park["fence"].as_array().expect("fence points") {
            let p = point.as_table().expect("a fence point");
            let _ = write!(
                out,
                "[{:?}, {:?}, {:?}], ",
                number(&p["direction"]),
                number(&p["distance"]),
                number(&p["height"])
            );
        }
        out.push_str("] },\n");
    }
    out.push(']');
    let path =
        std::path::Path::new(&std::env::var("OUT_DIR").expect("OUT_DIR")).join("bundled_parks.rs");
    std::fs::write(path, out).expect("OUT_DIR is writable");
}

/// Turns `presets/*.toml` (`src/preset/mod.rs` bundles them) into
/// statics (`$OUT_DIR/bundled_presets.rs`): each preset's entries as the
/// TOML crate gives them, in its order, for `preset::bundled` to read as it
/// reads a file's (its TOML parse was a third of a command's start-up work
/// before its own; a test holds the two equal).
fn bundled_presets() {
    println!("cargo::rerun-if-changed=presets");
    let mut names: Vec<String> = std::fs::read_dir("presets")
        .expect("presets/ is readable")
        .filter_map(|entry| {
            let name = entry.ok()?.file_name().into_string().ok()?;
            Some(name.strip_suffix(".toml")?.to_owned())
        })
        .collect();
    names.sort();
    let mut out = String::from("&[\n");
    for name in names {
        let source = format!("presets/{name}.toml");
        println!("cargo::rerun-if-changed={source}");
        let text = std::fs::read_to_string(&source).expect("a bundled preset is readable");
        let table: toml::Table = text.parse().expect("a bundled preset is TOML");
        let _ = write!(out, "({name:?}, &[");
        for (key, value) in &table {
            let _ = write!(out, "({key:?}, {}), ", preset_value(value));
        }
        out.push_str("]),\n");
    }
    out.push(']');
    let path = std::path::Path::new(&std::env::var("OUT_DIR").expect("OUT_DIR"))
        .join("bundled_presets.rs");
    std::fs::write(path, out).expect("OUT_DIR is writable");
}

/// A bundled preset's value as `preset::bundled::Value` (an integer as the
/// float a file's integer is read as).
fn preset_value(value: &toml::Value) -> String {
    match value {
        toml::Value::Float(f) => format!("Value::Number({f:?})"),
        toml::Value::Integer(i) => format!("Value::Number({:?})", *i as f64),
        toml::Value::String(text) => format!("Value::Text({text:?})"),
        toml::Value::Table(table) => {
            let entries: Vec<String> = table
                .iter()
                .map(|(key, value)| format!("({key:?}, {})", preset_value(value)))
                .collect();
            format!("Value::Table(&[{}])", entries.join(", "))
        }
        other => panic!("a bundled preset holds only numbers, texts and tables, not {other}"),
    }
}

/// A binary linked statically (glibc too: `.cargo/config.toml` turns on
/// `crt-static`) is also linked at a fixed address, not as rustc links it
/// (position-independent, `-static-pie`): its ~5400 relocations are then
/// done by the linker, not at each start (0.1 ms of `homerun --version`).
/// The code stays position-independent, for the tests and doctests linked
/// against the library; only the binary is linked so.
fn link_at_a_fixed_address() {
    let var = |name| std::env::var(name).unwrap_or_default();
    let crt_static = var("CARGO_CFG_TARGET_FEATURE")
        .split(',')
        .any(|feature| feature == "crt-static");
    if crt_static && var("CARGO_CFG_TARGET_OS") == "linux" && var("CARGO_CFG_TARGET_ENV") == "gnu" {
        println!("cargo::rustc-link-arg-bins=-static");
        println!("cargo::rustc-link-arg-bins=-no-pie");
    }
}
