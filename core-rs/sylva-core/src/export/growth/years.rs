//! The growth as one GLB per year, zipped: for tools without glTF animation. Each year's tree
//! is generated cold at that Age, so each file is exactly the tree the studio shows at that
//! Age, written as the ordinary GLB with the same options.

use crate::export::{to_glb, ExportOptions};
use crate::{generate, SylvaError, TreeParams};

/// The years of [`years_zip`] for a tree of Age `age`: every whole year from 1 up to `age`, and
/// `age` itself when it is not whole.
pub fn growth_years(age: f32) -> Vec<f32> {
    let mut years: Vec<f32> = (1..=age.floor() as u32).map(|y| y as f32).collect();
    if age.fract() > 0.0 {
        years.push(age);
    }
    years
}

/// The zip name of the file of `year`: `year_007.glb`, `year_012.5.glb`.
fn name(year: f32) -> String {
    if year.fract() == 0.0 {
        format!("year_{:03}.glb", year as u32)
    } else {
        format!("year_{:03}.{}.glb", year.floor() as u32, ((year.fract() * 10.0).round() as u32).min(9))
    }
}

/// A zip of the tree of `params` at every year of [`growth_years`] of its Age, each an ordinary
/// GLB ([`to_glb`] with `opts`) named `year_NNN.glb`, in year order.
pub fn years_zip(params: &TreeParams, opts: &ExportOptions) -> Result<Vec<u8>, SylvaError> {
    let mut files = Vec::new();
    for y in growth_years(params.skeleton.age) {
        let mut p = params.clone();
        p.skeleton.age = y;
        files.push((name(y), to_glb(&generate(&p)?, opts)));
    }
    crate::export::zip::zip(&files).map_err(|message| SylvaError::Input { message })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn years_and_names() {
        assert_eq!(growth_years(3.0), vec![1.0, 2.0, 3.0]);
        assert_eq!(growth_years(2.5), vec![1.0, 2.0, 2.5]);
        assert_eq!(name(7.0), "year_007.glb");
        assert_eq!(name(12.5), "year_012.5.glb");
    }
}
