//! When each part shows, at what size and in what colour: the calendar of flowers, fruit,
//! catkins and buds, in Season months (northern temperate; 1.0 is 1 January).
//!
//! Dates are means for temperate Europe and the north-eastern United States, rounded to a
//! tenth of a month (the USA National Phenology Network's *Nature's Notebook* phenophases
//! "flowers or flower buds", "open flowers", "fruits", "ripe fruits", "recent fruit or seed
//! drop"; Menzel 2000 for leaf-out, see [`crate::season`]):
//!
//! * **Cherry** (*Prunus avium*): white blossom in clusters just before and with its leaves in
//!   April, petals falling within two weeks; cherries green in May, red and ripe in June,
//!   gone (picked or taken by birds) by July.
//! * **Apple** (*Malus domestica*): pink buds opening white in late April to May, with the
//!   leaves; apples set in June and swell all summer, red-cheeked by September, falling or
//!   picked in October.
//! * **Catkins**: birch's male catkins form in late summer and hang small and brown all
//!   winter, then lengthen and shed yellow pollen in April; aspen's hang grey and woolly in
//!   March before the leaves; willow's slender yellow-green ones come with the leaves in April.
//! * **Acorns** (oaks): green from August, brown and dropping from late September into
//!   November. **Samaras** (maples): green bunches from August, tan by October, falling into
//!   November. **Cones**: a pine's hang brown from August through the winter and drop by
//!   spring; a fir's stand on its upper branches and fall apart on the tree by November.
//! * **Buds**: every shoot tip of a bare deciduous tree, from its leaf fall to its leaf-out,
//!   swelling in the last month before bud burst.
//!
//! Parts that are present in summer but hardly seen (young green acorns, next year's buds)
//! start in August, so July stays the summer tree of every preset.

use super::set::OrganKind;
use crate::params::{Fruit, LeafPhenology};
use crate::season::{phenology, Phenology};

/// What the calendar shows of one kind of part at one month.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Show {
    /// The part.
    pub part: Part,
    /// Its size as a fraction of its full size.
    pub size: f32,
    /// How open a flower is (0: a closed bud, 1: fully open); 1 for other parts.
    pub open: f32,
    /// Its colour this month (sRGB): where two, each instance lies between them.
    pub color: [[f32; 3]; 2],
    /// The fraction of the parts still on the tree (each instance falls at its own time).
    pub present: f32,
}

/// The kinds of part the calendar knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// Cherry blossom (white, in clusters of two to four on long stalks).
    CherryBlossom,
    /// Apple blossom (pink in bud, white open, clusters of four to six).
    AppleBlossom,
    /// Birch catkins (hanging, brown through the winter, yellow in April).
    BirchCatkin,
    /// Aspen catkins (hanging, grey and woolly in March).
    AspenCatkin,
    /// Willow catkins (slender, yellow-green, in April).
    WillowCatkin,
    /// A winter bud at a shoot tip.
    Bud,
    /// The tree's Fruit.
    Fruit(Fruit),
}

impl Part {
    /// Whether the part is a flower (petals and a centre).
    pub fn is_blossom(self) -> bool {
        matches!(self, Part::CherryBlossom | Part::AppleBlossom)
    }

    /// Whether the part is a catkin.
    pub fn is_catkin(self) -> bool {
        matches!(self, Part::BirchCatkin | Part::AspenCatkin | Part::WillowCatkin)
    }

    /// The sets the part is drawn with.
    pub fn kinds(self) -> &'static [OrganKind] {
        match self {
            Part::CherryBlossom | Part::AppleBlossom => &[OrganKind::Stalk, OrganKind::Petals, OrganKind::FlowerCentre],
            Part::BirchCatkin | Part::AspenCatkin | Part::WillowCatkin => &[OrganKind::Catkin],
            Part::Bud => &[OrganKind::Bud],
            Part::Fruit(Fruit::Acorns | Fruit::Samaras) => &[OrganKind::Stalk, OrganKind::Fruit, OrganKind::FruitPart],
            Part::Fruit(Fruit::Cherries | Fruit::Apples) => &[OrganKind::Stalk, OrganKind::Fruit],
            Part::Fruit(_) => &[OrganKind::Fruit],
        }
    }
}

/// `t` clamped to 0..1 and eased (smoothstep).
fn ease(t: f32) -> f32 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// 0 before `a`, 1 after `b`, eased between.
fn ramp(m: f32, a: f32, b: f32) -> f32 {
    ease((m - a) / (b - a))
}

/// Linear mix of two sRGB colours.
fn mix(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t]
}

/// The months from `start` (wrapping through the new year) to `m`: `m` in a season that runs
/// from `start` over the turn of the year.
fn since(m: f32, start: f32) -> f32 {
    if m >= start {
        m - start
    } else {
        m + 12.0 - start
    }
}

const GREEN: [f32; 3] = [0.45, 0.58, 0.22];
const BROWN_BUD: [f32; 3] = [0.36, 0.24, 0.15];

/// A part present from `from` to `to` (months, `to` > `from`), falling over the last `fall`
/// months; `None` outside.
fn window(m: f32, from: f32, to: f32, fall: f32) -> Option<f32> {
    (m >= from && m < to).then(|| 1.0 - ramp(m, to - fall, to))
}

fn blossom(part: Part, m: f32) -> Option<Show> {
    // (bud swells, opens, full, petals fall by) and the bud's and the open flower's colours.
    let (swell, open, full, gone, bud, white) = match part {
        Part::CherryBlossom => (3.6, 3.9, 4.1, 4.7, [0.93, 0.86, 0.84], [0.98, 0.97, 0.96]),
        _ => (4.3, 4.55, 4.75, 5.3, [0.90, 0.48, 0.60], [0.98, 0.92, 0.93]),
    };
    let present = window(m, swell, gone, gone - full)?;
    let o = ramp(m, swell + 0.5 * (open - swell), full);
    Some(Show { part, size: 0.6 + 0.4 * ramp(m, swell, open), open: o, color: [mix(bud, white, o); 2], present })
}

fn catkin(part: Part, m: f32) -> Option<Show> {
    match part {
        Part::BirchCatkin => {
            // From August over the new year to mid-May: small and brown, then long and yellow.
            let s = since(m, 8.0);
            (s < 9.6).then(|| {
                let spring = ramp(m, 3.5, 4.1) * f32::from(u8::from(m < 8.0));
                Show {
                    part,
                    size: 0.35 + 0.2 * (s / 8.0).min(1.0) + 0.45 * spring,
                    open: 1.0,
                    color: [mix([0.40, 0.28, 0.18], [0.86, 0.76, 0.30], spring); 2],
                    present: 1.0 - ramp(s, 8.6, 9.6),
                }
            })
        }
        Part::AspenCatkin => window(m, 2.6, 4.5, 0.7).map(|present| Show {
            part,
            size: 0.4 + 0.6 * ramp(m, 2.6, 3.3),
            open: 1.0,
            color: [[0.58, 0.52, 0.48], [0.50, 0.40, 0.38]],
            present,
        }),
        _ => window(m, 3.6, 5.0, 0.5).map(|present| Show {
            part,
            size: 0.4 + 0.6 * ramp(m, 3.6, 4.2),
            open: 1.0,
            color: [[0.80, 0.80, 0.36], [0.86, 0.80, 0.30]],
            present,
        }),
    }
}

fn fruit(kind: Fruit, m: f32) -> Option<Show> {
    let part = Part::Fruit(kind);
    let show = |size: f32, color: [[f32; 3]; 2], present: f32| Show { part, size, open: 1.0, color, present };
    match kind {
        Fruit::None => None,
        Fruit::Cherries => window(m, 4.6, 7.0, 0.6).map(|p| {
            let ripe = ramp(m, 5.5, 6.1);
            show(
                0.3 + 0.7 * ramp(m, 4.6, 5.6),
                [mix(GREEN, [0.62, 0.05, 0.07], ripe), mix(GREEN, [0.45, 0.03, 0.06], ripe)],
                p,
            )
        }),
        Fruit::Apples => window(m, 5.4, 10.9, 1.2).map(|p| {
            let ripe = ramp(m, 8.0, 9.2);
            let green = [0.58, 0.70, 0.26];
            show(
                0.15 + 0.85 * ramp(m, 5.4, 9.0),
                [mix(green, [0.78, 0.16, 0.10], ripe), mix(green, [0.80, 0.62, 0.20], ripe)],
                p,
            )
        }),
        Fruit::Acorns => window(m, 8.0, 11.0, 1.4).map(|p| {
            let ripe = ramp(m, 9.0, 9.8);
            show(
                0.6 + 0.4 * ramp(m, 8.0, 9.0),
                [mix(GREEN, [0.50, 0.32, 0.14], ripe), mix(GREEN, [0.42, 0.27, 0.12], ripe)],
                p,
            )
        }),
        Fruit::Samaras => window(m, 8.0, 11.3, 1.3).map(|p| {
            let ripe = ramp(m, 9.2, 10.2);
            let green = [0.56, 0.68, 0.30];
            show(
                0.7 + 0.3 * ramp(m, 8.0, 9.0),
                [mix(green, [0.74, 0.60, 0.38], ripe), mix(green, [0.64, 0.46, 0.28], ripe)],
                p,
            )
        }),
        Fruit::HangingCones => {
            // Ripe in August, hanging through the winter, dropped by May.
            let s = since(m, 8.0);
            (s < 9.0).then(|| show(1.0, [[0.46, 0.32, 0.18], [0.40, 0.28, 0.16]], 1.0 - ramp(s, 5.0, 9.0)))
        }
        Fruit::UprightCones => window(m, 8.0, 11.2, 1.4).map(|p| {
            let ripe = ramp(m, 8.4, 9.4);
            show(1.0, [mix([0.34, 0.30, 0.36], [0.46, 0.34, 0.20], ripe); 2], p)
        }),
    }
}

fn buds(ph: &Phenology, m: f32) -> Option<Show> {
    if ph.evergreen {
        return None;
    }
    // From a little before the last leaves fall until bud burst.
    let s = since(m, ph.fall_end - 0.4);
    let until = since(ph.leaf_out + 0.1, ph.fall_end - 0.4);
    (s < until).then(|| Show {
        part: Part::Bud,
        size: 1.0 + 0.5 * ramp(m, ph.leaf_out - 1.0, ph.leaf_out) * f32::from(u8::from(m < 8.0)),
        open: 1.0,
        color: [BROWN_BUD, [0.44, 0.22, 0.14]],
        present: 1.0,
    })
}

/// Every part a tree of leaf calendar `kind` and fruit `fruit` shows at month `m`, in a fixed
/// order (blossom or catkins, fruit, buds).
pub fn shows(kind: LeafPhenology, fruit_kind: Fruit, m: f32) -> Vec<Show> {
    let flower = match kind {
        LeafPhenology::Cherry => blossom(Part::CherryBlossom, m),
        LeafPhenology::Apple => blossom(Part::AppleBlossom, m),
        LeafPhenology::Birch => catkin(Part::BirchCatkin, m),
        LeafPhenology::Aspen => catkin(Part::AspenCatkin, m),
        LeafPhenology::Willow => catkin(Part::WillowCatkin, m),
        _ => None,
    };
    [flower, fruit(fruit_kind, m), buds(phenology(kind), m)].into_iter().flatten().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn july_shows_nothing_but_the_new_species_fruit() {
        for &kind in LeafPhenology::ALL {
            for &fruit_kind in Fruit::ALL {
                for m in [7.0, 7.5, 7.99] {
                    let s = shows(kind, fruit_kind, m);
                    let expected = usize::from(fruit_kind == Fruit::Apples);
                    assert_eq!(s.len(), expected, "{kind:?} {fruit_kind:?} at {m}: {s:?}");
                }
            }
        }
    }

    #[test]
    fn the_calendar_of_the_cherry() {
        let at = |m| shows(LeafPhenology::Cherry, Fruit::Cherries, m);
        assert!(at(4.2)[0].part.is_blossom() && at(4.2)[0].open > 0.9, "open in April");
        assert!(at(6.0).iter().any(|s| s.part == Part::Fruit(Fruit::Cherries) && s.color[0][0] > 0.5));
        assert!(at(1.5).iter().all(|s| s.part == Part::Bud), "buds only in January");
        assert!(at(9.0).is_empty(), "nothing in September");
    }

    #[test]
    fn cones_hang_over_the_new_year_and_birch_catkins_wait_all_winter() {
        assert_eq!(shows(LeafPhenology::Conifer, Fruit::HangingCones, 1.5).len(), 1);
        assert!(shows(LeafPhenology::Conifer, Fruit::HangingCones, 6.0).is_empty());
        let jan = shows(LeafPhenology::Birch, Fruit::None, 1.5);
        assert_eq!(jan.iter().map(|s| s.part).collect::<Vec<_>>(), [Part::BirchCatkin, Part::Bud]);
        let april = shows(LeafPhenology::Birch, Fruit::None, 4.0)[0];
        assert!(april.size > jan[0].size + 0.3 && april.color[0][1] > 0.6, "long and yellow in April");
    }
}
