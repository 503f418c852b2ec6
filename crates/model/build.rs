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

/// A number of the file, written as a float or an integer.
fn number(value: &toml::Value) -> f64 {
    value
        .as_float()
        .or_else(|| value.as_integer().map(|i| i as f64))
        .expect("a number")
}

/// A list of strings (`aliases`, `home`, `walls`), as Rust's `&[..]` items.
fn strings_of(table: &toml::Table, key: &str) -> String {
    let items = table.get(key).and_then(|a| a.as_array());
    let quoted = (items.into_iter().flatten()).map(|s| format!("{:?}", s.as_str().expect(key)));
    quoted.collect::<Vec<_>>().join(", ")
}

/// A table's `fence`, as `[direction, distance, height], ` items.
fn write_fence(out: &mut String, table: &toml::Table) {
    for point in table["fence"].as_array().expect("fence points") {
        let p = point.as_table().expect("a fence point");
        let _ = write!(
            out,
            "[{:?}, {:?}, {:?}], ",
            number(&p["direction"]),
            number(&p["distance"]),
            number(&p["height"])
        );
    }
}

fn main() {
    let source = "../../data/parks.toml";
    println!("cargo::rerun-if-changed={source}");
    println!("cargo::rerun-if-changed=build.rs");
    let text = std::fs::read_to_string(source).expect("data/parks.toml is readable");
    let file: toml::Table = text.parse().expect("data/parks.toml is TOML");
    let parks = file["park"].as_array().expect("[[park]] tables");
    let mut out = String::from("&[\n");
    for park in parks {
        let park = park.as_table().expect("a [[park]] table");
        let text = |key: &str| format!("{:?}", park[key].as_str().expect(key));
        let strings = |key: &str| strings_of(park, key);
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
            strings("aliases"),
            text("name"),
            park.get("city").and_then(|c| c.as_str()).unwrap_or(""),
            number(&park["elevation"]),
            number(&park["center_field_bearing"]),
        );
        write_fence(&mut out, park);
        let walls = match park.get("walls") {
            Some(_) => format!("Some(&[{}])", strings("walls")),
            None => "None".to_owned(),
        };
        let _ = write!(
            out,
            "], home: &[{}], walls: {walls}, earlier: &[",
            strings("home")
        );
        // `[[park.earlier]]`: each one's walls and fence.
        let earlier = park.get("earlier").and_then(|e| e.as_array());
        for walls in earlier.into_iter().flatten() {
            let walls = walls.as_table().expect("a [[park.earlier]] table");
            let _ = write!(out, "(&[{}], &[", strings_of(walls, "walls"));
            write_fence(&mut out, walls);
            out.push_str("]), ");
        }
        let _ = writeln!(out, "] }},");
    }
    out.push(']');
    let path =
        std::path::Path::new(&std::env::var("OUT_DIR").expect("OUT_DIR")).join("bundled_parks.rs");
    std::fs::write(path, out).expect("OUT_DIR is writable");
}
