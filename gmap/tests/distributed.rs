//! One image cut into K slabs (`gmap::distributed`, computed in this process through the
//! messages the MPI ranks send): the groups of `gmap homology` on the whole image, in
//! dimensions 1 to 4, for every K; the per-rank figures; refusals.

use gmap::distributed::{run_in_process, DistributedOptions, SlabRoute};
use gmap::HomologyOptions;
use gmap_ops::import::image::{Image, Order};

/// A uint8 image of `shape` (C order), each value 1 with probability `density` percent.
fn random_image(dir: &std::path::Path, name: &str, shape: &[usize], density: u64, seed: u64) -> std::path::PathBuf {
    let mut s = seed;
    let values: Vec<u8> = (0..shape.iter().product::<usize>())
        .map(|_| {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((s >> 33) % 100 < density) as u8
        })
        .collect();
    let path = dir.join(name);
    Image::from_values(shape, Order::C, values).unwrap().write_npy(&path).unwrap();
    path
}

#[test]
fn slabs_give_the_groups_of_one_process() {
    let dir = tempfile::tempdir().unwrap();
    let shapes: [&[usize]; 6] = [&[40], &[23, 31], &[9, 12, 10], &[14, 6, 5], &[4, 5, 3, 6], &[5, 3, 4, 4]];
    for (i, shape) in shapes.iter().enumerate() {
        for density in [30, 50, 70] {
            let path = random_image(dir.path(), &format!("{i}-{density}.npy"), shape, density, 7 * i as u64 + density);
            let one = gmap::homology_file(&path, &HomologyOptions::default()).unwrap();
            for k in 1..=4 {
                let d = run_in_process(&path, k, &DistributedOptions::default()).unwrap();
                assert_eq!(d.report.groups, one.groups, "{shape:?} at {density}% in {k} slabs");
                assert_eq!(d.ranks.len(), k);
                let route = if shape.len() == 3 { SlabRoute::OnePass } else { SlabRoute::Complex };
                assert_eq!(d.route, route);
                // the slabs cover the slowest axis (the first of a C-order image) in order
                assert_eq!(d.ranks[0].layers.start, 0);
                assert_eq!(d.ranks[k - 1].layers.end, shape[0]);
                assert!(d.ranks.windows(2).all(|w| w[0].layers.end == w[1].layers.start));
                let v = d.to_json();
                assert_eq!(v["betti"], serde_json::json!(one.groups.betti));
                assert_eq!(v["mpi"]["ranks"].as_array().unwrap().len(), k);
                assert!(v["mpi"]["ranks"][0]["bytes_sent"].as_u64().unwrap() > 0);
            }
        }
    }
}

#[test]
fn refusals_name_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = random_image(dir.path(), "thin.npy", &[3, 50], 50, 1);
    let e = run_in_process(&path, 4, &DistributedOptions::default()).unwrap_err();
    assert!(e.to_string().contains("4 processes for an image of 3 layers along its slowest axis: at most 3"), "{e}");
    assert!(e.to_string().starts_with(&path.display().to_string()), "{e}");
    let e = run_in_process(&dir.path().join("missing.npy"), 2, &DistributedOptions::default()).unwrap_err();
    assert!(e.to_string().contains("missing.npy"), "{e}");
}
