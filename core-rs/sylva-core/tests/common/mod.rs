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
    assert_rings(g, name);
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

/// `TreeMesh::rings` as documented: sorted, disjoint runs of `sides + 1 >= 4` vertices inside the
/// mesh, `u = j / sides` along the run (1 on the last, the seam twin, at the first's exact
/// position), one `v` for the whole ring.
pub fn assert_rings(g: &Generated, name: &str) {
    let m = &g.mesh;
    let mut end = 0;
    for (i, &[first, count]) in m.rings.iter().enumerate() {
        assert!(first >= end && count >= 4, "{name}: ring {i} {first}+{count} after {end}");
        end = first + count;
        assert!(end as usize <= m.vertex_count(), "{name}: ring {i} past the vertices");
        let (f, sides) = (first as usize, count as usize - 1);
        assert_eq!(
            m.positions[3 * f..3 * f + 3],
            m.positions[3 * (f + sides)..3 * (f + sides) + 3],
            "{name}: ring {i} seam"
        );
        for j in 0..=sides {
            let u = if j == sides { 1.0 } else { j as f32 / sides as f32 };
            assert_eq!(m.uvs[2 * (f + j)], u, "{name}: ring {i} u of vertex {j}");
            assert_eq!(m.uvs[2 * (f + j) + 1], m.uvs[2 * f + 1], "{name}: ring {i} v of vertex {j}");
        }
    }
}
