//! Surface topology of a mesh, with vertices welded by position (bit-identical positions are one
//! vertex, so duplicated UV seams and material splits do not count as openings): how many edges
//! are open (used by one triangle) or non-manifold (used by more than two). `sylva generate
//! --report mesh` prints these, and the invariant tests check them.

use super::TreeMesh;
use std::collections::HashMap;

/// Edge counts of a welded mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Topology {
    /// Distinct welded edges.
    pub edges: usize,
    /// Edges used by exactly one triangle (openings: buried stem bases, holes).
    pub boundary_edges: usize,
    /// Edges used by more than two triangles.
    pub non_manifold_edges: usize,
}

/// Welded edge → number of triangles using it. Vertex ids are the first index with that position.
pub fn edge_uses(mesh: &TreeMesh) -> HashMap<(u32, u32), u32> {
    let mut weld: HashMap<[u32; 3], u32> = HashMap::with_capacity(mesh.vertex_count());
    let ids: Vec<u32> = mesh
        .positions
        .chunks_exact(3)
        .enumerate()
        .map(|(i, p)| *weld.entry([p[0].to_bits(), p[1].to_bits(), p[2].to_bits()]).or_insert(i as u32))
        .collect();
    let mut edges = HashMap::with_capacity(mesh.indices.len());
    for t in mesh.indices.chunks_exact(3) {
        for k in 0..3 {
            let (a, b) = (ids[t[k] as usize], ids[t[(k + 1) % 3] as usize]);
            *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    edges
}

/// Count the edges of `mesh` by how many triangles use them.
pub fn topology(mesh: &TreeMesh) -> Topology {
    let uses = edge_uses(mesh);
    Topology {
        edges: uses.len(),
        boundary_edges: uses.values().filter(|&&u| u == 1).count(),
        non_manifold_edges: uses.values().filter(|&&u| u > 2).count(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_tetrahedron_has_no_open_edges_and_an_open_one_has_three() {
        let positions = vec![0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
        let mut mesh = TreeMesh { positions, indices: vec![0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2], ..TreeMesh::default() };
        assert_eq!(topology(&mesh), Topology { edges: 6, boundary_edges: 0, non_manifold_edges: 0 });
        mesh.indices.truncate(9);
        assert_eq!(topology(&mesh).boundary_edges, 3);
    }
}
