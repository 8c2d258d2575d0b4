//! Where the bark's sweep ([`super::tube`]) put each stem in the mesh's buffers, handed on with
//! the mesh to the passes that read a few stems of it ([`super::holes`]).

use std::ops::Range;

/// Where the sweep put each stem in the bark's buffers (skeleton order), what
/// [`super::holes::cut`] reads besides the mesh: a pass over a few stems' faces need not read
/// every triangle of the tree. Triangle ranges count triangles (index `3 k` starts triangle `k`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Layout {
    /// Each stem's contiguous block of vertices.
    pub blocks: Vec<Range<u32>>,
    /// Each stem's own triangles (its quads, tip and base): they use only its block's vertices.
    pub tubes: Vec<Range<u32>>,
    /// The triangles joining each stem to its parent (a welded collar and zip, or a fork's
    /// patches and crotch): they use only its own block's and its parent's block's vertices.
    pub junctions: Vec<Range<u32>>,
    /// The first triangle after every stem's and every junction's (the cut ends' faces).
    pub rest: u32,
    /// The stems swept densely enough for tree holes ([`super::holes::eligible`]); empty when
    /// no holes are asked for.
    pub eligible: Vec<bool>,
}
