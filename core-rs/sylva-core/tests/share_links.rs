//! The core's share-link codec (`sylva_core::share`) against the links the studio's codec writes
//! (`share_links.json`, checked on the studio's side by `url/shareFixtures.test.ts`): the same
//! link for the same tree, the same tree from the link; and the strict reading of bad links.

use sylva_core::params::{edits, volumes};
use sylva_core::{presets, share, TreeParams};

/// The fixtures: `(name, tree, link)`.
fn fixtures() -> Vec<(String, TreeParams, String)> {
    let text = include_str!("share_links.json");
    let doc: serde_json::Value = serde_json::from_str(text).expect("fixtures parse");
    let links = doc["links"].as_array().expect("links");
    links
        .iter()
        .map(|f| {
            let mut p = match f["preset"].as_str() {
                Some(name) => presets::find(name).expect("preset").params().expect("preset params"),
                None => TreeParams::default(),
            };
            for (id, v) in f["values"].as_object().expect("values") {
                p.set(id, v.as_f64().expect("number")).expect("value in range");
            }
            if let Some(v) = f.get("volumes") {
                p.skeleton.volumes = volumes::from_json_value(v).expect("volumes");
            }
            if let Some(e) = f.get("edits") {
                p.skeleton.edits = edits::from_json_value(e).expect("edits");
            }
            let link = f["link"].as_str().expect("link").to_string();
            (f["name"].as_str().unwrap_or_default().to_string(), p, link)
        })
        .collect()
}

#[test]
fn the_core_writes_the_studios_links() {
    for (name, p, link) in fixtures() {
        assert_eq!(share::encode(&p), link, "{name}");
    }
}

#[test]
fn the_core_reads_the_studios_links_to_the_same_tree() {
    for (name, p, link) in fixtures() {
        for form in [link.clone(), format!("http://localhost:5173/?{link}#top")] {
            let decoded = share::decode(&form);
            assert!(decoded.messages.is_empty(), "{name}: {:?}", decoded.messages);
            assert_eq!(decoded.params, p, "{name}");
        }
    }
}

#[test]
fn a_round_trip_keeps_the_hash() {
    let mut p = presets::find("weeping").unwrap().params().unwrap();
    p.set("levels", 2.0).unwrap();
    p.set("l1_length", 0.4321).unwrap();
    let back = share::decode(&share::encode(&p)).params;
    assert_eq!(back, p);
    let (a, b) = (sylva_core::generate(&p).unwrap(), sylva_core::generate(&back).unwrap());
    assert_eq!(a.hash_hex(), b.hash_hex());
}

#[test]
fn a_bad_value_keeps_its_default_and_says_so() {
    let d = share::decode("?v=1&scale=abc&l1_length=0.5&l1_length=0.9&levels=2.5&unknown=3&shape=99");
    assert_eq!(d.params.get("scale"), TreeParams::default().get("scale"));
    assert_eq!(d.params.get("l1_length"), Some(f64::from(0.5f32)));
    assert_eq!(d.params.get("levels"), TreeParams::default().get("levels"));
    assert_eq!(d.messages.len(), 4, "{:?}", d.messages);
    assert!(d.messages[0].starts_with("Ignored \"scale\" from the link: \"abc\" is not a number"), "{:?}", d.messages);
    assert!(d.messages.iter().any(|m| m.contains("repeated \"l1_length\"")));
    assert!(d.messages.iter().any(|m| m.contains("\"2.5\" is not an integer")));
    assert!(d.messages.iter().any(|m| m.contains("\"99\" is out of range")));
}

#[test]
fn another_version_or_a_long_link_gives_the_defaults() {
    let d = share::decode("v=2&scale=20");
    assert_eq!(d.params, TreeParams::default());
    assert!(d.messages[0].contains("Unsupported share-link version \"2\""));
    let long = format!("v=1&scale=20&{}", "x=1&".repeat(1100));
    let d = share::decode(&long);
    assert_eq!(d.params, TreeParams::default());
    assert!(d.messages[0].contains("too long"));
}

#[test]
fn hostile_numbers_are_refused() {
    // `+` is a space in a query, as in the studio: `+5` is refused, `%2B5` read.
    for bad in ["NaN", "Infinity", "0x10", " 5", "+5", "1e999", "", "1..2", "-", "e5"] {
        let d = share::decode(&format!("v=1&scale={}", bad.replace(' ', "%20")));
        assert_eq!(d.params, TreeParams::default(), "{bad}");
        assert_eq!(d.messages.len(), 1, "{bad}");
    }
    for good in ["20", "%2B20", "20.", ".5e2", "2E1"] {
        let d = share::decode(&format!("v=1&scale={good}"));
        assert!(d.messages.is_empty(), "{good}: {:?}", d.messages);
    }
}

#[test]
fn bad_primitives_are_skipped_and_bad_edits_drop_the_list() {
    let d = share::decode("v=1&vol=1%3Bs%3Ac%3A0%2C5%2C0%2C2%3Bq%3Ac%3A1%3Bs%3Ac%3A0%2C5%2C0%2C0.01");
    assert_eq!(d.params.skeleton.volumes.len(), 1);
    assert_eq!(d.messages.len(), 2, "{:?}", d.messages);
    assert!(d.messages[0].starts_with("Ignored vol[1] from the link: unknown kind \"q\""));
    assert!(d.messages[1].starts_with("Ignored vol[2] from the link: radius is 0.01"), "{:?}", d.messages);

    let d = share::decode("v=1&e=1~c80.410.-20~z1.2.3");
    assert!(d.params.skeleton.edits.is_empty());
    assert!(d.messages[0].contains("e[1]: unknown op \"z\""), "{:?}", d.messages);
    let d = share::decode("v=1&e=1~c80.2.-20");
    assert!(d.params.skeleton.edits.is_empty());
    assert!(d.messages[0].contains("edits[0].at"), "{:?}", d.messages);
    let d = share::decode("v=1&e=1~c80.4100.1.5.6");
    assert!(d.messages[0].contains("a cut takes 3 numbers (and a year), got 5"), "{:?}", d.messages);
    let d = share::decode("v=1&e=1~c80.410.1.301");
    assert!(d.params.skeleton.edits.is_empty());
    assert!(d.messages[0].contains("edits[0].year is 301: allowed range is 0 to 300 years"), "{:?}", d.messages);
}

#[test]
fn edits_too_long_for_a_link_are_left_out() {
    let mut p = TreeParams::default();
    let cuts: Vec<String> = (0..300).map(|i| format!("{{\"op\":\"cut\",\"at\":[1.{i:03},4,0]}}")).collect();
    p.skeleton.edits = edits::from_json(&format!("[{}]", cuts.join(","))).unwrap();
    assert_eq!(share::encode(&p), "v=1");
}
