//! The Weber & Penn growth of a tree's stems ([`build_with_crown`]): the trunk, then each
//! stem's record traced ([`super::trace`]), its children placed along it and its split clones
//! grown after them, depth first, so records are pushed parents first; then the roots. The
//! paper's formulas (lengths, radii, angles, branch counts with error diffusion, pruning) are
//! each in the step that uses them.

use super::trace::{inside_prune_envelope, trace, StemStart};
use super::trunk::{add_roots, guide_curve};
use super::{budget_error, drawn_crown, min_vertices, taper_radius, Points, Skeleton, Stem, StemKind};
use super::{MIN_LENGTH, MIN_RADIUS};
use crate::edits::crown::DrawnCrown;
use crate::error::SylvaError;
use crate::math::{self, pow, rad, unit_or};
use crate::params::{Crown, CrownShape, GrowthMode, SkeletonParams};
use crate::rng::Rng;
use glam::{Quat, Vec3};

/// [`build`](super::build) with a crown drawn by hand: with Crown Shape *Drawn*, the level-1
/// branch lengths follow `crown`'s outline ([`DrawnCrown::ratio_at_height`] at each attachment
/// point's height); without a crown (or with another shape) the tree is
/// [`build`](super::build)'s.
pub fn build_with_crown(p: &SkeletonParams, crown: Option<&Crown>) -> Result<Skeleton, SylvaError> {
    let mut rng = Rng::new(u64::from(p.seed), "skeleton");
    let scale = (p.scale + rng.var(p.scale_v)).max(0.1);
    let l0 = &p.level[0];
    let length = ((l0.length + rng.var(l0.length_v)) * scale).max(MIN_LENGTH);
    let radius = (length * p.ratio * (p.scale0 + rng.var(p.scale0_v))).max(MIN_RADIUS);
    let mut b = Builder {
        p,
        stems: Vec::new(),
        carry: [0.0; 4],
        split_carry: [0.0; 4],
        vertex_floor: 0,
        scale,
        crown_base: p.base_size * length,
        drawn: drawn_crown(p, crown),
        clone_lists: Vec::new(),
        unit: Vec::new(),
    };
    b.grow(StemStart {
        level: 0,
        parent: None,
        offset: 0.0,
        base: Vec3::ZERO,
        frame: Quat::IDENTITY,
        length,
        radius,
        down_angle: 0.0,
        first_seg: 0,
        correction: 0.0,
        rng,
    })?;
    add_roots(p, &mut b.stems);
    Ok(Skeleton::of(p, GrowthMode::Parametric, b.stems, scale, b.crown_base))
}

struct Builder<'a> {
    p: &'a SkeletonParams,
    stems: Vec<Stem>,
    /// Error-diffusion remainders of fractional branch counts, per level.
    carry: [f32; 4],
    /// Error-diffusion remainders of fractional segment splits, per level.
    split_carry: [f32; 4],
    vertex_floor: u64,
    scale: f32,
    crown_base: f32,
    /// The drawn crown when Crown Shape is Drawn and a crown edit gives the outline.
    drawn: Option<DrawnCrown>,
    /// Emptied lists for [`trace()`]'s clones, for the next stems ([`Builder::grow`]).
    clone_lists: Vec<Vec<StemStart>>,
    /// [`Builder::pruned_length`]'s trace, kept for the next stem.
    unit: Vec<Vec3>,
}

impl Builder<'_> {
    /// Grow one stem record (tracing its segments, splitting off clones), then its children and
    /// its clones. Records are pushed parents first.
    fn grow(&mut self, s: StemStart) -> Result<(), SylvaError> {
        let p = self.p;
        let lp = &p.level[s.level];
        self.vertex_floor += min_vertices(lp.curve_res);
        if self.vertex_floor > u64::from(p.max_vertices) {
            return Err(budget_error(p.growth_mode, p.max_vertices, "at least ", self.vertex_floor));
        }
        let mut rng = s.rng.clone();
        let mut length = s.length;
        if p.prune_ratio > 0.0 && s.level >= 1 && s.first_seg == 0 {
            length = self.pruned_length(&s);
            if length < (2.0 * s.radius).max(MIN_LENGTH) {
                return Ok(()); // pruned to a stub that would sit inside its parent
            }
        }
        let mut carry = self.split_carry[s.level];
        let trunk = s.level == 0 && s.parent.is_none();
        let mut points = Points::with_capacity(p.level[s.level].curve_res as usize + 1);
        // The clones' list from a pool, one per level of recursion: no allocation per stem.
        let mut clones = self.clone_lists.pop().unwrap_or_default();
        trace(p, &s, length, &mut rng, Some(&mut carry), &mut clones, &mut |q| {
            points.push(q);
            true
        });
        self.split_carry[s.level] = carry;
        if trunk && p.guide_xy > 0.0 {
            guide_curve(p, &mut points);
        }
        let segs = lp.curve_res as usize;
        let z0 = s.first_seg as f32 / segs as f32;
        let index = self.stems.len() as u32;
        let record_len = length * (1.0 - z0);
        let kind = if s.first_seg > 0 {
            StemKind::SplitClone
        } else if trunk {
            StemKind::Trunk
        } else {
            StemKind::Branch
        };
        self.stems.push(Stem {
            kind,
            level: s.level as u8,
            parent: s.parent,
            offset: s.offset,
            base_normal: s.frame * Vec3::X,
            points,
            length: record_len.max(MIN_LENGTH),
            radius: taper_radius(s.radius, lp.taper, length, z0).max(MIN_RADIUS),
            taper: lp.taper,
            flare: if s.level == 0 { p.flare } else { 0.0 },
            down_angle: s.down_angle,
            chain_length: length,
            chain_radius: s.radius,
            chain_start: z0,
            lobed: trunk,
            radii: None,
            cut_end: false,
            callus: 0.0,
            born: 0.0,
            tip_year: 0.0,
        });
        if s.level + 1 < p.levels as usize {
            self.grow_children(s.level, index, &mut rng)?;
        }
        for mut c in clones.drain(..) {
            c.parent = Some(index);
            c.offset = (c.first_seg - s.first_seg) as f32 * length / segs as f32;
            c.length = length;
            self.grow(c)?;
        }
        self.clone_lists.push(clones);
        Ok(())
    }

    /// Weber & Penn pruning: the longest length at which the stem stays inside the pruning
    /// envelope (bisection), then `L - (L - L_fit) * PruneRatio`. A stem's shape does not depend
    /// on its length (bends are per segment), so one unit-length trace, scaled, answers every
    /// trial length.
    fn pruned_length(&mut self, s: &StemStart) -> f32 {
        let mut unit = std::mem::take(&mut self.unit);
        unit.clear();
        let length = self.fit_length(s, &mut unit);
        self.unit = unit;
        length
    }

    /// [`Builder::pruned_length`] with its buffer for the unit-length trace (empty on entry).
    fn fit_length(&self, s: &StemStart, unit: &mut Vec<Vec3>) -> f32 {
        let p = self.p;
        trace(p, s, 1.0, &mut s.rng.clone(), None, &mut Vec::new(), &mut |q| {
            unit.push(q - s.base);
            true
        });
        // From the tip down: a stem too long leaves the envelope at its tip first, most often.
        let fits = |len: f32| unit.iter().rev().all(|&d| inside_prune_envelope(p, self.scale, s.base + d * len));
        if fits(s.length) {
            return s.length;
        }
        let (mut lo, mut hi) = (0.0f32, s.length);
        for _ in 0..10 {
            let mid = 0.5 * (lo + hi);
            if fits(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        s.length - (s.length - lo) * p.prune_ratio
    }

    fn grow_children(&mut self, level: usize, index: u32, rng: &mut Rng) -> Result<(), SylvaError> {
        let p = self.p;
        let child = level + 1;
        let cp = &p.level[child];
        let stem = self.stems[index as usize].clone();
        // Weber & Penn reason about whole stems: a clone's children use its stem's length.
        let stem_len = stem.chain_length;
        let chain_offset = stem.chain_start * stem_len;
        let (parent_len, parent_offset) = match stem.parent {
            Some(i) => {
                let parent = &self.stems[i as usize];
                (parent.chain_length, parent.chain_start * parent.chain_length + stem.offset)
            }
            None => (stem_len, 0.0),
        };
        // How many children (Weber & Penn 1995, §4.3), fractional counts carried over by error diffusion.
        let wanted = match child {
            1 => cp.branches as f32,
            2 => {
                let max_child = (p.level[1].length + p.level[1].length_v).max(1e-6);
                cp.branches as f32 * (0.2 + 0.8 * (stem_len / parent_len) / max_child)
            }
            _ => cp.branches as f32 * (1.0 - 0.5 * parent_offset / parent_len),
        }
        .max(0.0)
            * (stem.length / stem_len);
        let exact = wanted + self.carry[child];
        let count = exact.floor().max(0.0);
        self.carry[child] = exact - count;
        let count = count as usize;
        if count == 0 {
            return Ok(());
        }
        let start = if level == 0 { (self.crown_base - chain_offset).clamp(0.0, stem.length) } else { 0.0 };
        let mut rot = 0.0f32;
        for i in 0..count {
            let mut crng = rng.split();
            let offset = start + (stem.length - start) * (i as f32 + 0.5) / count as f32;
            let along = chain_offset + offset;
            // Crown position r: 1 at the crown base, 0 at the top (as in `crate::crown`).
            let crown_span = stem_len - self.crown_base;
            let crown_r = if crown_span > 0.0 { (stem_len - along) / crown_span } else { 0.0 };
            let length = if child == 1 {
                let ratio = match &self.drawn {
                    Some(d) => d.ratio_at_height(stem.point(offset / stem.length).y),
                    None => p.shape.ratio(crown_r),
                };
                stem_len * (cp.length + crng.var(cp.length_v)) * ratio
            } else {
                (cp.length + crng.var(cp.length_v)) * (stem_len - 0.6 * along)
            };
            let mut down = if cp.down_angle_v >= 0.0 {
                cp.down_angle + crng.var(cp.down_angle_v)
            } else {
                let r = (stem_len - along) / stem_len;
                cp.down_angle + cp.down_angle_v * (1.0 - 2.0 * CrownShape::Conical.ratio(r))
            };
            if child == 1 {
                down += p.angle_spread * (2.0 * CrownShape::Conical.ratio(crown_r) - 1.0);
            }
            rot = if cp.rotate >= 0.0 {
                rot + cp.rotate + crng.var(cp.rotate_v)
            } else {
                let side = if i % 2 == 0 { 1.0 } else { -1.0 };
                side * (180.0 + cp.rotate) + crng.var(cp.rotate_v)
            };
            let radius = (stem.chain_radius * pow(length / stem_len, p.ratio_power))
                .min(stem.radius_at(offset / stem.length))
                .max(MIN_RADIUS);
            if length < (2.0 * radius).max(MIN_LENGTH) {
                continue; // shorter than its own thickness: it would sit inside the parent
            }
            let (pos, dir) = stem.point_at(offset);
            // Parent frame at the attachment point: its +Y along `dir`, +X transported from the base.
            let x = unit_or(stem.base_normal - dir * stem.base_normal.dot(dir), || dir.any_orthonormal_vector());
            let parent_frame = Quat::from_mat3(&glam::Mat3::from_cols(x, dir, x.cross(dir)));
            let frame = (parent_frame * math::quat_rotation_y(rad(rot)) * math::quat_rotation_x(rad(down))).normalize();
            self.grow(StemStart {
                level: child,
                parent: Some(index),
                offset,
                base: pos,
                frame,
                length,
                radius,
                down_angle: down,
                first_seg: 0,
                correction: 0.0,
                rng: crng,
            })?;
        }
        Ok(())
    }
}
