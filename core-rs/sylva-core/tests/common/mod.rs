//! Mesh invariant checks shared by the integration tests (standing rule 6).

use sylva_core::Generated;

pub use sylva_core::mesh::topology::edge_uses;

/// Assert every geometric invariant of standing rule 6 on a generated tree.
pub fn assert_mesh_invariants(g: &Generated, name: &str) {
    let m = &g.mesh;
    let n = m.vertex_count();
    assert!(n > 0, "{name}: empty mesh");
    assert_eq!(m.positions.len(), n * 3, "{name}: positions length");
    assert_eq!(m.normals.len(), n * 3, "{name}: normals length");
    assert_eq!(m.uvs.len(), n * 2, "{name}: uvs length");
    assert_eq!(m.indices.len() % 3, 0, "{name}: indices not triangles");
    assert!(m.indices.iter().all(|&i| (i as usize) < n), "{name}: index out of range");
    assert!(m.positions.iter().chain(&m.normals).chain(&m.uvs).all(|v| v.is_finite()), "{name}: non-finite value");
    for (i, nm) in m.normals.chunks_exact(3).enumerate() {
        let len = (nm[0] * nm[0] + nm[1] * nm[1] + nm[2] * nm[2]).sqrt();
        assert!((len - 1.0).abs() < 1e-3, "{name}: normal {i} has length {len}");
    }
    let covered: u32 = m.groups.iter().map(|g| g.count).sum();
    assert_eq!(covered as usize, m.indices.len(), "{name}: groups do not cover the indices");
    let p = |i: u32| {
        let k = i as usize * 3;
        glam::Vec3::new(m.positions[k], m.positions[k + 1], m.positions[k + 2])
    };
    let nrm = |i: u32| {
        let k = i as usize * 3;
        glam::Vec3::new(m.normals[k], m.normals[k + 1], m.normals[k + 2])
    };
    let mut inverted = 0usize;
    for (ti, t) in m.indices.chunks_exact(3).enumerate() {
        let (a, b, c) = (p(t[0]), p(t[1]), p(t[2]));
        let cross = (b - a).cross(c - a);
        assert!(cross.length() > 0.0, "{name}: triangle {ti} is degenerate");
        // Winding: counter-clockwise from outside = geometric normal agrees with the vertex normals.
        if cross.dot(nrm(t[0]) + nrm(t[1]) + nrm(t[2])) <= 0.0 {
            inverted += 1;
        }
    }
    assert_eq!(inverted, 0, "{name}: {inverted} triangles wound against their normals");
    // Continuous bark: no triangle crosses a stem's texture seam (u near 0 with u near 1, which
    // squeezes the whole bark texture into one triangle); zips and forks that straddle a seam
    // use copies of their vertices a whole turn on.
    let crossing = m
        .indices
        .chunks_exact(3)
        .filter(|t| sylva_core::mesh::seam_shifts([t[0], t[1], t[2]].map(|i| m.uvs[i as usize * 2])) != [0; 3])
        .count();
    assert_eq!(crossing, 0, "{name}: {crossing} triangles cross a bark seam");
    // Standing on the ground: nothing below it except roots that dive on purpose, and those only
    // as deep as their skeleton says.
    let deepest = g
        .skeleton
        .stems
        .iter()
        .flat_map(|st| {
            st.points.iter().enumerate().map(move |(i, q)| q.y - st.radius_at(i as f32 / (st.points.len() - 1) as f32))
        })
        .fold(0.0f32, f32::min);
    let b = g.bounds;
    assert!(b.min[1] >= deepest - 1e-3 && b.max[1] > 0.0, "{name}: tree not standing on the ground: {b:?}");
}
