//! The calendar's invariants for every species and every leaf's random numbers.

use super::*;

const KINDS: [LeafPhenology; 8] = [
    LeafPhenology::Aspen,
    LeafPhenology::Maple,
    LeafPhenology::Oak,
    LeafPhenology::Birch,
    LeafPhenology::Ginkgo,
    LeafPhenology::Willow,
    LeafPhenology::Tupelo,
    LeafPhenology::Conifer,
];

/// A grid of per-leaf random numbers, the extremes included.
fn dice() -> impl Iterator<Item = LeafDice> {
    let steps = [0.0, 0.25, 0.5, 0.75, 0.999_999];
    steps.into_iter().flat_map(move |timing| {
        steps.into_iter().flat_map(move |hue| steps.into_iter().map(move |fall| LeafDice { timing, hue, fall }))
    })
}

fn state(kind: LeafPhenology, month: f32, sky: f32, d: LeafDice) -> LeafState {
    let ph = phenology(kind);
    leaf_state(ph, &Palette::of(ph), month, sky, d)
}

#[test]
fn every_leaf_is_summer_from_june_to_august() {
    for kind in KINDS {
        for month in [6.0, 6.5, 7.0, 7.5, 8.0, 8.9] {
            for sky in [0.0, 0.5, 1.0] {
                for d in dice() {
                    assert_eq!(state(kind, month, sky, d), LeafState::Summer, "{kind:?} month {month} {d:?}");
                }
            }
        }
    }
}

#[test]
fn january_is_bare_except_for_conifers() {
    for kind in KINDS {
        for month in [1.0, 1.5, 2.5, 12.9] {
            for d in dice() {
                let s = state(kind, month, 0.0, d);
                if kind == LeafPhenology::Conifer {
                    assert_ne!(s, LeafState::Absent);
                } else {
                    assert_eq!(s, LeafState::Absent, "{kind:?} month {month} {d:?}");
                }
            }
        }
    }
}

#[test]
fn spring_leaves_are_small_and_pale() {
    let d = LeafDice { timing: 0.5, hue: 0.5, fall: 0.5 };
    let LeafState::Changed { scale, tint } = state(LeafPhenology::Maple, 4.6, 1.0, d) else {
        panic!("a maple leaf in mid-April is flushing")
    };
    assert!(scale > SPRING_SIZE && scale < 0.7, "{scale}");
    // Paler and yellower than the summer green: more red than the blade's, relative to green.
    assert!(tint.x > tint.y && tint.x > 1.0, "{tint}");
}

#[test]
fn sun_leaves_turn_before_shaded_ones() {
    let d = LeafDice { timing: 0.5, hue: 0.0, fall: 0.999 };
    for kind in KINDS.into_iter().filter(|k| *k != LeafPhenology::Conifer) {
        let ph = phenology(kind);
        let month = ph.onset + 0.5 * (ph.peak - ph.onset);
        let amount = |sky: f32| match state(kind, month, sky, d) {
            LeafState::Changed { tint, .. } => (tint - Vec3::ONE).length(),
            LeafState::Summer => 0.0,
            LeafState::Absent => panic!("{kind:?} fell at its colouring"),
        };
        assert!(amount(1.0) > amount(0.0) + 0.1, "{kind:?}: sun {} shade {}", amount(1.0), amount(0.0));
    }
}

#[test]
fn a_maple_in_october_is_red_and_an_oak_brown() {
    let d = LeafDice { timing: 0.5, hue: 0.3, fall: 0.999 };
    let blade = Vec3::from(crate::leaf::texture::BLADE.map(linear));
    let shown = |kind, month| match state(kind, month, 1.0, d) {
        LeafState::Changed { tint, .. } => blade * tint,
        other => panic!("{kind:?} {other:?}"),
    };
    let maple = shown(LeafPhenology::Maple, 10.5);
    assert!(maple.x > 3.0 * maple.y && maple.x > 0.3, "{maple}");
    let aspen = shown(LeafPhenology::Aspen, 10.2);
    assert!(aspen.x > 0.4 && aspen.y > 0.3 && aspen.z < 0.1, "yellow {aspen}");
    let oak = shown(LeafPhenology::Oak, 10.9);
    assert!(oak.x > oak.y && oak.y > oak.z && oak.x < 0.5, "russet {oak}");
}

#[test]
fn conifers_bronze_a_little_in_winter_only() {
    let d = LeafDice { timing: 0.5, hue: 0.5, fall: 0.5 };
    let LeafState::Changed { tint, scale } = state(LeafPhenology::Conifer, 1.5, 1.0, d) else {
        panic!("midwinter needles bronze")
    };
    assert_eq!(scale, 1.0);
    assert!(tint.x > 1.0 && tint.z < 1.0 && tint.x < 1.4, "{tint}");
    assert_eq!(state(LeafPhenology::Conifer, 5.0, 1.0, d), LeafState::Summer);
}
