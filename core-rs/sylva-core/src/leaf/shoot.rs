//! Conifer shoots: the leaf becomes a twig carrying many needles (pines and firs, `docs/leaves.md`; the "frond" of
//! SpeedTree and the needle cards of every real-time conifer), so a crown of a few thousand
//! shoots has the needle area of a real conifer, hundreds of thousands of needles, which
//! single needles could only reach with as many instances. Seen from a distance a fir is a
//! dark mass because of that area; with one needle per leaf it looked bare.
//!
//! * **Twig**: the shoot's axis, leaf `+y` from 0 to 1 (the shoot is one leaf length long), a
//!   strip [`TWIG_WIDTH`] wide, [`TWIG_LIFT`] in front of the leaf plane.
//! * **Needles** (Needles per Shoot `N`): needle `i` leaves the twig at
//!   `y_i = 0.04 + 0.92 (i + ½ ± ⅓) / N`, `Needle Length` times the shoot long (shorter toward
//!   both ends, `0.8 + 0.2 sin(π y_i)`, ±8 %), at `Needle Angle` to the twig (closing to 65 % of it
//!   at the tip, where the young needles point forward, ±6°). Each needle is the leaf's own
//!   needle (the blade of the Leaf parameters, or its fascicle) scaled by its length.
//!   * **Flat Shoot** on (firs, yews): the needles twist into two ranks, alternately left and
//!     right in the leaf plane, raised [`RANK_LIFT`] toward the front so the spray is a shallow V.
//!   * off (spruces, pines, cypresses): all around the twig, each [`GOLDEN`] further about it.
//! * **Texture**: the same needles projected onto the leaf plane and baked into the colour and
//!   normal textures over the shoot's box (the layout of [`super::texture`]): each needle green
//!   with a rounded cross-section (lighter and raised along its middle, its normal tilting
//!   across it) and a slightly different shade from its neighbours, so overlapping needles stay
//!   apart; then the twig, brown over their bases. The card and billboard levels show this
//!   texture, so a far shoot has the silhouette of its needles.
//!
//! Randomness: the fixed stream `"shoot"` (the leaf is a function of the Leaf parameters only).

use crate::leaf::needles::Surface;
use crate::leaf::raster::fill_rows;
use crate::leaf::texture::{self, byte, LeafTexture};
use crate::leaf::uv::UvFrame;
use crate::math;
use crate::params::LeafParams;
use crate::rng::Rng;
use glam::{Vec2, Vec3};

/// Width of the twig strip, in shoot lengths.
pub const TWIG_WIDTH: f32 = 0.018;
/// How far the twig strip sits in front of the leaf plane (shoot lengths).
pub const TWIG_LIFT: f32 = 0.008;
/// How far a flat shoot's needles rise toward the front (radians, about 16°).
pub const RANK_LIFT: f32 = 0.28;
/// Turn about the twig from one needle to the next when they are all around it (radians).
pub const GOLDEN: f32 = 2.399_963;
/// Needle colour (linear 0..1 before the per-needle shade): darker and bluer than a blade.
const NEEDLE: Vec3 = Vec3::new(0.17, 0.33, 0.14);
/// Twig colour.
const TWIG: Vec3 = Vec3::new(0.40, 0.33, 0.21);
/// How much the normal tilts across a needle at its edge.
const ROUND: f32 = 0.65;

/// One needle's place on the shoot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Where it leaves the twig (`y`, shoot lengths).
    pub y: f32,
    /// Its length (shoot lengths).
    pub length: f32,
    /// Angle to the twig (radians; negative leans to `−x`).
    pub angle: f32,
    /// Turn about the twig (radians; 0 = in the leaf plane).
    pub turn: f32,
    /// Brightness factor of its colour.
    pub shade: f32,
}

impl Placement {
    /// Needle-local point (`+y` along the needle, length 1) to shoot point.
    pub fn apply(&self, q: Vec3) -> Vec3 {
        let q = self.rotate(q * self.length);
        Vec3::new(q.x, q.y + self.y, q.z)
    }

    /// The rotation alone (for normals): `angle` about `z` toward `x`, then `turn` about `y`.
    pub fn rotate(&self, q: Vec3) -> Vec3 {
        let (sa, ca) = (math::sin(self.angle), math::cos(self.angle));
        let (x, y) = (q.x * ca + q.y * sa, -q.x * sa + q.y * ca);
        let (st, ct) = (math::sin(self.turn), math::cos(self.turn));
        Vec3::new(x * ct - q.z * st, y, x * st + q.z * ct)
    }
}

/// The needles of the shoot (see the module docs).
pub fn placements(p: &LeafParams) -> Vec<Placement> {
    let n = p.leaf_shoot as usize;
    let mut rng = Rng::new(0, "shoot");
    let theta = math::rad(p.leaf_shoot_angle);
    (0..n)
        .map(|i| {
            let y = 0.04 + 0.92 * ((i as f32 + 0.5 + rng.var(1.0 / 3.0)) / n as f32);
            let y = y.clamp(0.0, 1.0);
            let length =
                p.leaf_shoot_needle * (0.8 + 0.2 * math::sin(std::f32::consts::PI * y)) * (1.0 + rng.var(0.08));
            let angle = theta * (1.0 - 0.35 * y * y) + math::rad(6.0) * rng.var(1.0);
            let shade = 0.9 + 0.16 * rng.next_f32();
            let (angle, turn) = if p.leaf_shoot_flat {
                let s = if i % 2 == 0 { 1.0 } else { -1.0 };
                (s * angle, s * RANK_LIFT)
            } else {
                (angle, GOLDEN * i as f32)
            };
            Placement { y, length, angle, turn, shade }
        })
        .collect()
}

/// The shoot's needle outlines projected onto the leaf plane, in drawing order; a fascicle of
/// `k` needles is drawn as `k` outlines fanned by the fascicle's splay.
pub fn projected(placements: &[Placement], needle: &[Vec2], fascicle: u32) -> Vec<Vec<Vec2>> {
    let k = fascicle.max(1);
    let mut out = Vec::with_capacity(placements.len() * k as usize);
    for pl in placements {
        for j in 0..k {
            let fan = (j as f32 - 0.5 * (k - 1) as f32) * 2.0 * crate::leaf::needles::SPLAY;
            let pj = Placement { angle: pl.angle + fan, ..*pl };
            out.push(needle.iter().map(|q| pj.apply(Vec3::new(q.x, q.y, 0.0)).truncate()).collect());
        }
    }
    out
}

/// The twig strip from `−petiole` to the tip, as a polygon in the leaf plane.
pub fn twig(petiole: f32) -> [Vec2; 4] {
    let h = 0.5 * TWIG_WIDTH;
    [Vec2::new(-h, -petiole), Vec2::new(h, -petiole), Vec2::new(h, 1.0), Vec2::new(-h, 1.0)]
}

/// The shoot's geometry: every needle of `needle` (in needle units) placed on the twig, plus
/// the twig strip, UVs projected into `frame`.
pub fn surface(placements: &[Placement], needle: &Surface, frame: &UvFrame) -> Surface {
    let mut s = Surface::default();
    let per = needle.positions.len();
    s.positions.reserve(placements.len() * per + 4);
    for pl in placements {
        let first = s.positions.len() as u32;
        s.positions.extend(needle.positions.iter().map(|&q| pl.apply(q)));
        s.normals.extend(needle.normals.iter().map(|&n| pl.rotate(n)));
        s.triangles.extend(needle.triangles.iter().map(|t| t.map(|v| v + first)));
    }
    let first = s.positions.len() as u32;
    // A hair in front of the needles' bases, which leave it at its sides.
    s.positions.extend(twig(0.0).map(|c| c.extend(TWIG_LIFT)));
    s.normals.extend([Vec3::Z; 4]);
    s.triangles.extend([[first, first + 1, first + 2], [first, first + 2, first + 3]]);
    s.uvs = s.positions.iter().map(|q| frame.uv(q.truncate())).collect();
    s
}

/// The box of the shoot: its needles, its twig and its petiole.
pub fn frame(outlines: &[Vec<Vec2>], petiole: f32) -> UvFrame {
    let mut all: Vec<Vec2> = outlines.iter().flatten().copied().collect();
    all.extend(twig(petiole));
    UvFrame::of(&all)
}

/// Bakes the shoot's textures (layout of [`super::texture`]): `2^level` rows over `frame`.
pub fn bake(
    placements: &[Placement],
    outlines: &[Vec<Vec2>],
    fascicle: u32,
    petiole: f32,
    frame: &UvFrame,
    level: u32,
) -> LeafTexture {
    let (w, h) = texture::size(level, frame);
    let texel = frame.size / Vec2::new(w as f32, h as f32);
    let mut color = vec![0u8; w * h * 4];
    // Outside the needles: the flat normal, no height (as the blade's texture has).
    let mut normal = [128u8, 128, 255, 0].repeat(w * h);
    // Fills the texels whose centres are inside `poly` with `paint(centre) -> (rgb, normal, height)`.
    let mut fill = |poly: &[Vec2], paint: &dyn Fn(Vec2) -> (Vec3, Vec3, f32)| {
        let (lo, hi) = crate::leaf::geom::bounds(poly);
        let i0 = (((lo.x - frame.lo.x) / texel.x).floor().max(0.0) as usize).min(w - 1);
        let j0 = (((lo.y - frame.lo.y) / texel.y).floor().max(0.0) as usize).min(h - 1);
        let i1 = (((hi.x - frame.lo.x) / texel.x).ceil().max(0.0) as usize).min(w);
        let j1 = (((hi.y - frame.lo.y) / texel.y).ceil().max(0.0) as usize).min(h);
        if i1 <= i0 || j1 <= j0 {
            return;
        }
        let (sw, sh) = (i1 - i0, j1 - j0);
        let origin = frame.lo + Vec2::new(i0 as f32, j0 as f32) * texel;
        let inside = fill_rows(poly, origin, texel, sw, sh);
        for (k, _) in inside.iter().enumerate().filter(|(_, &b)| b) {
            let (x, y) = (i0 + k % sw, j0 + k / sw);
            let centre = frame.lo + (Vec2::new(x as f32, y as f32) + 0.5) * texel;
            let (rgb, n, ht) = paint(centre);
            let t = 4 * (y * w + x);
            color[t..t + 4].copy_from_slice(&[byte(rgb.x), byte(rgb.y), byte(rgb.z), 255]);
            normal[t..t + 4].copy_from_slice(&[
                byte(0.5 * n.x + 0.5),
                byte(0.5 * n.y + 0.5),
                byte(0.5 * n.z + 0.5),
                byte(ht),
            ]);
        }
    };
    let k = fascicle.max(1) as usize;
    for (o, poly) in outlines.iter().enumerate() {
        let pl = placements[o / k];
        let base = Vec2::new(0.0, pl.y);
        // The needle's direction and its half-width, projected like its outline.
        let tip = pl.apply(Vec3::Y).truncate();
        let along = (tip - base).try_normalize().unwrap_or(Vec2::Y);
        let across = along.perp();
        let half = poly.iter().map(|&q| (q - base).dot(across).abs()).fold(1e-6f32, f32::max);
        let lean = if k > 1 { (o % k) as f32 / k as f32 * 0.06 } else { 0.0 };
        fill(poly, &|c: Vec2| {
            let u = ((c - base).dot(across) / half).clamp(-1.0, 1.0);
            let crown = 1.0 - u * u;
            let rgb = NEEDLE * (pl.shade * (0.82 + 0.22 * crown) + lean);
            let tilt = across * (ROUND * u);
            let n = Vec3::new(tilt.x, tilt.y, (1.0 - tilt.length_squared()).max(0.0).sqrt());
            (rgb, n, crown)
        });
    }
    // The twig last: the needles leave it at its sides, so from the front it shows between them.
    fill(&twig(petiole), &|_| (TWIG, Vec3::Z, 0.5));
    LeafTexture { width: w as u32, height: h as u32, color, normal }
}
