//! # Seasons
//!
//! What the **Season** (the month of the year, northern temperate: 1.0 is 1 January, 12.99 the
//! end of December) does to the placed leaves ([`crate::foliage`]): each leaf is left as it is
//! (summer), changed in size and tint, or absent (not yet out, or fallen). July, the default,
//! is the summer tree: every leaf is left exactly as it is, and [`Sites::new`] skips the
//! season altogether at the default.
//!
//! **Calendar** ([`Phenology`], one per [`LeafPhenology`]). Mean dates for temperate Europe
//! and the north-eastern United States, rounded to a tenth of a month: leaf unfolding in
//! April to early May and leaf colouring in October (Menzel 2000, *Trends in phenological
//! phases in Europe between 1951 and 1996*, Int. J. Biometeorology 44; the phenophases
//! "breaking leaf buds", "increasing leaf size", "colored leaves" and "falling leaves" of the
//! USA National Phenology Network's *Nature's Notebook*). Species order: willows and birches
//! leaf out first and oaks last; tupelo turns first, ginkgo late and then drops its leaves
//! within days; oaks hold their brown leaves into winter (marcescence).
//!
//! * **Spring** (the flush): a leaf leaves the bud at [`SPRING_SIZE`] of its length and pale
//!   yellow-green ([`FLUSH`]), and grows to full size and colour by the full-size date.
//! * **Autumn**: a leaf's colour goes from green to its species' palette between the onset
//!   and the peak, then toward dead brown until it falls. After Chiba, Ohshida, Muraoka and
//!   Saito 1996 (*Visual Simulation of Leaf Arrangement and Autumn Colours*, J. Visualization
//!   and Computer Animation 7: the ageing of a leaf runs with the sunlight it receives), the
//!   timing follows each leaf's light: the crown's light field ([`crate::crown_shade`], of the
//!   summer crown; a leaf takes `√sky` of the sun) delays a fully shaded leaf by
//!   [`SHADE_DELAY`] and dulls its colour toward the palette's shade colour, so the outer sun
//!   leaves turn first and brightest.
//!   Anthocyanin reds are made in the light (Lee et al. 2003, *Pigment dynamics and autumn
//!   leaf senescence in a New England deciduous forest*, Ecological Research 18).
//! * **Leaf fall**: each leaf falls at its own time between a little before its peak and the
//!   fall end (a per-leaf random number); shaded leaves fall later, as they turn later.
//! * **Winter**: deciduous trees are bare (every leaf has fallen before 1 January and none
//!   leaves the bud before March); an evergreen conifer keeps its needles, which bronze a
//!   little in the winter months, more in the sun ([`BRONZE`]).
//!
//! Colours are given as the blade shows them (sRGB, like the leaf texture's blade green
//! [`crate::leaf::texture::BLADE`]) and applied as a multiplier of the leaf's tint (the tint
//! multiplies the texture decoded to linear light), so a leaf's own brightness and yellow
//! variation and the crown shade stay. Randomness: the named stream `"season"` (timing,
//! colour and fall order per leaf), drawn for every leaf site, so a drag's preview (every
//! other site) keeps the leaves it shows in the same state.

use crate::crown_shade::CrownLight;
use crate::math;
use crate::params::{FoliageParams, LeafPhenology};
use crate::rng::Rng;
use glam::Vec3;

/// The Season of the summer tree (the default): every leaf as it is.
pub const SUMMER: f32 = 7.0;
/// How much later (months) a leaf in full shade turns than one in the open.
pub const SHADE_DELAY: f32 = 0.4;
/// Per-leaf variation of the dates (± months).
const JITTER: f32 = 0.25;
/// A new leaf's length, as a fraction of its full length, when it leaves the bud.
pub const SPRING_SIZE: f32 = 0.2;
/// The pale yellow-green of a new leaf (sRGB).
pub const FLUSH: [f32; 3] = [0.62, 0.76, 0.26];
/// A dead leaf's brown (sRGB), toward which every autumn colour goes after its peak.
const BROWN: [f32; 3] = [0.42, 0.28, 0.14];
/// How far a leaf in full shade is dulled toward its palette's shade colour.
const SHADE_DULL: f32 = 0.6;
/// Winter bronzing of conifer needles at full strength (a linear-light multiplier), and how
/// much of it a needle in the open takes in midwinter.
pub const BRONZE: ([f32; 3], f32) = ([1.7, 0.95, 0.62], 0.35);

/// One species' year: dates as Season values (month numbers), colours sRGB.
#[derive(Clone, Copy, Debug)]
pub struct Phenology {
    /// Keeps its leaves all year (conifers): no spring, autumn or fall, only winter bronzing.
    pub evergreen: bool,
    /// Bud burst.
    pub leaf_out: f32,
    /// Leaves at full size and colour.
    pub full_size: f32,
    /// Autumn colouring begins (leaves in the open).
    pub onset: f32,
    /// Peak colour (leaves in the open).
    pub peak: f32,
    /// The last leaves fall (leaves in the open).
    pub fall_end: f32,
    /// Autumn colours of sun leaves: each leaf is a mix of the two.
    pub sun: [[f32; 3]; 2],
    /// The duller colour shaded leaves turn toward.
    pub shade: [f32; 3],
}

const fn deciduous(dates: [f32; 5], sun: [[f32; 3]; 2], shade: [f32; 3]) -> Phenology {
    let [leaf_out, full_size, onset, peak, fall_end] = dates;
    Phenology { evergreen: false, leaf_out, full_size, onset, peak, fall_end, sun, shade }
}

/// Quaking aspen: golden yellow.
const ASPEN: Phenology =
    deciduous([4.3, 5.2, 9.6, 10.2, 10.9], [[0.95, 0.78, 0.16], [0.88, 0.66, 0.10]], [0.78, 0.70, 0.22]);
/// Maple (sugar and red maples in the open): scarlet to orange.
const MAPLE: Phenology =
    deciduous([4.4, 5.3, 9.8, 10.5, 11.3], [[0.82, 0.12, 0.06], [0.93, 0.42, 0.07]], [0.78, 0.55, 0.14]);
/// Oaks: russet and brown, held late.
const OAK: Phenology =
    deciduous([4.7, 5.6, 10.2, 10.9, 12.0], [[0.66, 0.30, 0.10], [0.56, 0.34, 0.14]], [0.50, 0.36, 0.16]);
/// Birch: yellow.
const BIRCH: Phenology =
    deciduous([4.2, 5.1, 9.6, 10.3, 11.0], [[0.93, 0.80, 0.24], [0.86, 0.70, 0.18]], [0.76, 0.68, 0.24]);
/// Ginkgo: butter yellow, then every leaf down within days.
const GINKGO: Phenology =
    deciduous([4.4, 5.3, 10.3, 10.9, 11.2], [[0.98, 0.84, 0.18], [0.95, 0.78, 0.12]], [0.82, 0.74, 0.22]);
/// Willow: yellow, late.
const WILLOW: Phenology =
    deciduous([4.0, 4.9, 10.0, 10.8, 11.6], [[0.86, 0.80, 0.30], [0.80, 0.72, 0.22]], [0.72, 0.68, 0.26]);
/// Black tupelo: crimson and purple-red, the first to turn.
const TUPELO: Phenology =
    deciduous([4.6, 5.5, 9.3, 10.0, 10.8], [[0.76, 0.09, 0.10], [0.56, 0.10, 0.20]], [0.80, 0.42, 0.14]);
/// Wild cherry: orange and red.
const CHERRY: Phenology =
    deciduous([4.2, 5.0, 9.7, 10.4, 11.0], [[0.92, 0.46, 0.10], [0.80, 0.17, 0.10]], [0.80, 0.62, 0.20]);
/// Apple: dull yellow and brown, late.
const APPLE: Phenology =
    deciduous([4.3, 5.2, 10.1, 10.8, 11.6], [[0.82, 0.72, 0.26], [0.70, 0.50, 0.18]], [0.60, 0.55, 0.25]);
/// Evergreen conifers.
const CONIFER: Phenology = Phenology { evergreen: true, ..ASPEN };

/// The calendar and palette of `kind`.
pub fn phenology(kind: LeafPhenology) -> &'static Phenology {
    match kind {
        LeafPhenology::Aspen => &ASPEN,
        LeafPhenology::Maple => &MAPLE,
        LeafPhenology::Oak => &OAK,
        LeafPhenology::Birch => &BIRCH,
        LeafPhenology::Ginkgo => &GINKGO,
        LeafPhenology::Willow => &WILLOW,
        LeafPhenology::Tupelo => &TUPELO,
        LeafPhenology::Conifer => &CONIFER,
        LeafPhenology::Cherry => &CHERRY,
        LeafPhenology::Apple => &APPLE,
    }
}

/// sRGB to linear light.
fn linear(c: f32) -> f32 {
    if c <= 0.040_45 {
        c / 12.92
    } else {
        math::pow((c + 0.055) / 1.055, 2.4)
    }
}

/// The tint multiplier that turns the texture's blade green into the sRGB colour `c`.
fn ratio(c: [f32; 3]) -> Vec3 {
    let b = crate::leaf::texture::BLADE;
    Vec3::new(linear(c[0]) / linear(b[0]), linear(c[1]) / linear(b[1]), linear(c[2]) / linear(b[2]))
}

/// The palette of one species as tint multipliers (computed once per placement).
struct Palette {
    sun: [Vec3; 2],
    shade: Vec3,
    brown: Vec3,
    flush: Vec3,
}

impl Palette {
    fn of(ph: &Phenology) -> Palette {
        Palette { sun: ph.sun.map(ratio), shade: ratio(ph.shade), brown: ratio(BROWN), flush: ratio(FLUSH) }
    }
}

/// One leaf's random numbers, uniform in `[0, 1)`.
#[derive(Clone, Copy, Debug)]
pub struct LeafDice {
    /// Shifts all its dates by up to ±[`JITTER`] months.
    pub timing: f32,
    /// Where its autumn colour lies between the palette's two sun colours.
    pub hue: f32,
    /// When it falls, from early (0) to the fall end (1).
    pub fall: f32,
}

/// What the season does to one leaf.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LeafState {
    /// Left exactly as placed.
    Summer,
    /// Not on the tree (before bud burst, or fallen).
    Absent,
    /// Scaled about its base on the stem by `scale`, its tint multiplied by `tint`.
    Changed {
        /// Length factor.
        scale: f32,
        /// Linear-light tint multiplier.
        tint: Vec3,
    },
}

/// `t` clamped to 0..1 and eased (smoothstep).
fn ease(t: f32) -> f32 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// How much of the sun a leaf that sees `sky` (0..1) of the sky takes: `√sky`. A leaf's
/// response to light saturates, and the field's sky is low all through a dense crown (the
/// median leaf of the oak preset sees 0.13, the brightest twentieth 0.57 or more), so the
/// outer leaves count as sun leaves and only the inner ones as shaded.
fn sun(sky: f32) -> f32 {
    sky.clamp(0.0, 1.0).sqrt()
}

/// The state at Season `month` of a leaf of `ph` that sees `sky` (0..1) of the sky.
fn leaf_state(ph: &Phenology, pal: &Palette, month: f32, sky: f32, dice: LeafDice) -> LeafState {
    let sky = sun(sky);
    if ph.evergreen {
        return bronze(month, sky);
    }
    let shift = (2.0 * dice.timing - 1.0) * JITTER;
    let (burst, full) = (ph.leaf_out + shift, ph.full_size + shift);
    if month < burst {
        return LeafState::Absent;
    }
    if month < full {
        let g = ease((month - burst) / (full - burst));
        let scale = SPRING_SIZE + (1.0 - SPRING_SIZE) * g;
        return LeafState::Changed { scale, tint: pal.flush.lerp(Vec3::ONE, g) };
    }
    let shade = 1.0 - sky;
    let delay = shift + SHADE_DELAY * shade;
    let (onset, peak, end) = (ph.onset + delay, ph.peak + delay, ph.fall_end + delay);
    if month < onset {
        return LeafState::Summer;
    }
    let first_fall = peak - 0.3 * (peak - onset);
    if month >= first_fall + (end - first_fall) * dice.fall {
        return LeafState::Absent;
    }
    let sun = pal.sun[0].lerp(pal.sun[1], dice.hue);
    let autumn = sun.lerp(pal.shade, SHADE_DULL * shade);
    let dead = 0.5 * ((month - peak) / (end - peak)).clamp(0.0, 1.0);
    let colour = autumn.lerp(pal.brown, dead);
    LeafState::Changed { scale: 1.0, tint: Vec3::ONE.lerp(colour, ease((month - onset) / (peak - onset))) }
}

/// An evergreen needle's winter bronzing: full from mid-December to mid-February, none from
/// mid-April to mid-October, scaled by the sun it takes ([`sun`] of its sky).
fn bronze(month: f32, sky: f32) -> LeafState {
    let d = (month - 1.5).abs();
    let from_midwinter = d.min(12.0 - d);
    let w = ease((3.0 - from_midwinter) / 2.0) * BRONZE.1 * sky;
    if w <= 0.0 {
        return LeafState::Summer;
    }
    LeafState::Changed { scale: 1.0, tint: Vec3::ONE.lerp(Vec3::from(BRONZE.0), w) }
}

/// How long (months) a fallen leaf lies before it starts to rot away, and the spread of that.
const LITTER_MONTHS: (f32, f32) = (4.0, 2.5);

/// The tint of a leaf of `ph` on the ground at `month`, or `None` when it is not there: it fell
/// this autumn (its autumn colour at its fall, browning on the ground), or last autumn while
/// the tree is bare (it lies until it rots, from [`LITTER_MONTHS`] after its fall). A leaf
/// that is absent because it has not yet left the bud this year is on the ground only as last
/// year's leaf.
fn fallen_tint(ph: &Phenology, pal: &Palette, month: f32, sky: f32, dice: LeafDice) -> Option<Vec3> {
    if ph.evergreen {
        return None;
    }
    let shift = (2.0 * dice.timing - 1.0) * JITTER;
    let delay = shift + SHADE_DELAY * (1.0 - sun(sky));
    let (onset, peak, end) = (ph.onset + delay, ph.peak + delay, ph.fall_end + delay);
    let first_fall = peak - 0.3 * (peak - onset);
    let fell = first_fall + (end - first_fall) * dice.fall;
    let down = if month >= fell {
        month - fell
    } else if month < ph.leaf_out + shift {
        month + 12.0 - fell
    } else {
        return None;
    };
    if down > LITTER_MONTHS.0 + LITTER_MONTHS.1 * dice.hue {
        return None;
    }
    let tint = match leaf_state(ph, pal, fell - 1e-3, sky, dice) {
        LeafState::Changed { tint, .. } => tint,
        _ => Vec3::ONE,
    };
    Some(tint.lerp(pal.brown, 0.6 * ease(down / 2.0)) * GROUND_SHADE)
}

/// How much darker a leaf lies on the ground, in the crown's shade, than in the open.
const GROUND_SHADE: f32 = 0.7;
/// The farthest a falling leaf drifts sideways, as a fraction of the height it falls from.
const DRIFT: f32 = 0.35;

/// The fallen leaves on the ground under the crown (**Fallen Leaves**): each lies flat at
/// `y ≈ 0` where it drifted to from its place in the crown, turned at random, in the same
/// matrices-and-tints layout as the leaves on the tree (so it is drawn with the same leaf).
#[derive(Debug, Default)]
pub struct Ground {
    /// Per-leaf 4×4 matrices, column-major.
    pub matrices: Vec<f32>,
    /// Per-leaf RGB tints.
    pub colors: Vec<f32>,
}

impl Ground {
    /// Lays the leaf of matrix `m`, centred at `centre` in the crown, tinted `tint`, by its
    /// three random numbers `drop` (drift, its direction, the leaf's turn).
    fn lay(&mut self, m: &[f32; 16], centre: Vec3, tint: Vec3, drop: [f32; 3]) {
        let col = |k: usize| Vec3::new(m[4 * k], m[4 * k + 1], m[4 * k + 2]).length();
        let (w, l, d) = (col(0), col(1), col(2));
        let a = std::f32::consts::TAU * drop[1];
        let drift = Vec3::new(math::cos(a), 0.0, math::sin(a)) * (DRIFT * centre.y.max(0.0) * drop[0]);
        let b = std::f32::consts::TAU * drop[2];
        let y = Vec3::new(math::cos(b), 0.0, math::sin(b));
        let x = y.cross(Vec3::Y);
        let at = Vec3::new(centre.x, 0.003 + 0.004 * drop[0], centre.z) + drift - y * (0.5 * l);
        for (axis, s) in [(x, w), (y, l), (Vec3::Y, d)] {
            self.matrices.extend_from_slice(&[axis.x * s, axis.y * s, axis.z * s, 0.0]);
        }
        self.matrices.extend_from_slice(&[at.x, at.y, at.z, 1.0]);
        self.colors.extend_from_slice(&tint.to_array());
    }
}

/// The leaf sites of one placement, gathered while the leaves are placed: each leaf's base on
/// its stem and its random numbers.
#[derive(Debug)]
pub struct Sites {
    rng: Rng,
    seed: u32,
    month: f32,
    kind: LeafPhenology,
    origins: Vec<Vec3>,
    dice: Vec<LeafDice>,
}

impl Sites {
    /// `None` at the default Season ([`SUMMER`]): the leaves stay exactly as placed.
    pub fn new(seed: u32, p: &FoliageParams) -> Option<Sites> {
        (p.season != SUMMER).then(|| Sites {
            rng: Rng::new(u64::from(seed), "season"),
            seed,
            month: p.season,
            kind: p.leaf_phenology,
            origins: Vec::new(),
            dice: Vec::new(),
        })
    }

    fn draw(&mut self) -> LeafDice {
        LeafDice { timing: self.rng.next_f32(), hue: self.rng.next_f32(), fall: self.rng.next_f32() }
    }

    /// A leaf placed with its petiole starting at `origin` on its stem.
    pub fn leaf(&mut self, origin: Vec3) {
        let dice = self.draw();
        self.origins.push(origin);
        self.dice.push(dice);
    }

    /// A leaf a preview leaves out: its numbers are drawn all the same.
    pub fn skip(&mut self) {
        self.draw();
    }

    /// Keeps the sites of the leaves marked in `keep` (in leaf order), as the foliage stage
    /// keeps their leaves.
    pub fn keep(&mut self, keep: &[bool]) {
        let mut k = keep.iter();
        self.origins.retain(|_| *k.next().unwrap_or(&true));
        let mut k = keep.iter();
        self.dice.retain(|_| *k.next().unwrap_or(&true));
    }

    /// Applies the season to the placed leaves (`matrices` and `colors` as [`crate::foliage`]
    /// has them, not yet darkened), reading each leaf's light in `light` (the summer crown's
    /// field; `None`: every leaf in the open). Absent leaves are removed; those that fell
    /// (this autumn, or last autumn while the tree is bare) go to `ground` when it is given
    /// ([`Ground`]). Returns whether the crown's leaf area changed (a leaf resized or
    /// removed), so its light field must be built again.
    pub fn apply(
        self,
        light: Option<&CrownLight>,
        matrices: &mut Vec<f32>,
        colors: &mut Vec<f32>,
        mut ground: Option<&mut Ground>,
    ) -> bool {
        let ph = phenology(self.kind);
        let pal = Palette::of(ph);
        let mut kept = 0usize;
        let mut area_changed = false;
        let mut litter = Rng::new(u64::from(self.seed), "fallen");
        for (i, (&origin, &dice)) in self.origins.iter().zip(&self.dice).enumerate() {
            let mut m: [f32; 16] = matrices[16 * i..16 * i + 16].try_into().expect("16 floats per leaf");
            let mut c = [colors[3 * i], colors[3 * i + 1], colors[3 * i + 2]];
            let centre = Vec3::new(m[12], m[13], m[14]) + 0.5 * Vec3::new(m[4], m[5], m[6]);
            let sky = light.map_or(1.0, |f| f.sky_at(centre));
            // Every leaf draws its place on the ground, fallen or not, so a leaf lies in the
            // same place all winter.
            let drop = [litter.next_f32(), litter.next_f32(), litter.next_f32()];
            match leaf_state(ph, &pal, self.month, sky, dice) {
                LeafState::Summer => {}
                LeafState::Absent => {
                    area_changed = true;
                    if let Some(g) = ground.as_deref_mut() {
                        if let Some(tint) = fallen_tint(ph, &pal, self.month, sky, dice) {
                            g.lay(&m, centre, Vec3::from(c) * tint, drop);
                        }
                    }
                    continue;
                }
                LeafState::Changed { scale, tint } => {
                    if scale != 1.0 {
                        area_changed = true;
                        m[..12].iter_mut().for_each(|v| *v *= scale);
                        let base = origin + (Vec3::new(m[12], m[13], m[14]) - origin) * scale;
                        m[12..15].copy_from_slice(&base.to_array());
                    }
                    c = [c[0] * tint.x, c[1] * tint.y, c[2] * tint.z];
                }
            }
            matrices[16 * kept..16 * kept + 16].copy_from_slice(&m);
            colors[3 * kept..3 * kept + 3].copy_from_slice(&c);
            kept += 1;
        }
        matrices.truncate(16 * kept);
        colors.truncate(3 * kept);
        area_changed
    }
}

#[cfg(test)]
mod tests;
