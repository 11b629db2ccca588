//! Checks shared by the fuzz targets: the homology routes of a cubical set and of a
//! simplicial complex, and the condition under which the G-map route must agree with the
//! direct one (every face's star joined through facets sharing a ridge that contains it).

#![allow(dead_code)] // each target uses a part

use std::collections::BTreeMap;

use gmap_core::union_find::UnionFind;
use gmap_core::DenseMap;
use gmap_homology::cubical::cubical_complex_with;
use gmap_homology::{cellular_complex, check_preconditions, homology_z, Homology};
use gmap_ops::import::CubicalSet;

/// Whether, for every face key, the cells listed with it are joined by chains of `adjacent`
/// pairs among themselves. `incidences` holds (face, cell) pairs; O(Σ s²) for stars of size s.
pub fn stars_connected<K: Ord>(incidences: Vec<(K, u32)>, adjacent: impl Fn(u32, u32) -> bool) -> bool {
    let mut stars: BTreeMap<K, Vec<u32>> = BTreeMap::new();
    for (k, c) in incidences {
        stars.entry(k).or_default().push(c);
    }
    stars.values().all(|star| {
        let mut uf = UnionFind::new(star.len());
        for i in 0..star.len() {
            for j in i + 1..star.len() {
                if adjacent(star[i], star[j]) {
                    uf.union(i as u32, j as u32);
                }
            }
        }
        uf.class_count() == 1
    })
}

/// The homology of a map by the cellular method, `None` when C1 or C2 fails.
pub fn cellular(m: &DenseMap) -> Option<Homology> {
    check_preconditions(m).ok()?;
    let c = cellular_complex(m).expect("the preconditions hold");
    Some(homology_z(&c.chain).expect("the cellular complex has homology"))
}

/// The homology of a map by its simplicial counterpart, when that is small.
pub fn simplicial(m: &DenseMap) -> Option<Homology> {
    if m.dart_count() > 1024 || m.dim() > 6 {
        return None;
    }
    Some(homology_z(&gmap_homology::simplicial_complex(m)).expect("the simplicial counterpart has homology"))
}

/// What `gmap homology --simplify` computes: the cellular homology of the simplified map
/// when C1 and C2 hold and the simplification keeps the components; it must equal the
/// cellular homology of the map itself.
pub fn check_simplify_keeps_the_groups(m: &DenseMap, cellular_groups: &Homology) {
    let small = gmap_ops::euler::simplify(m).0;
    assert!(small.validate().is_ok(), "the simplified map is valid");
    if small.component_count() != m.component_count() {
        return;
    }
    let after = cellular(&small).expect("a simplified map keeps C1 and C2");
    assert_eq!(&after, cellular_groups, "--simplify changed the groups");
}

/// A map's routes: cellular, simplicial counterpart and `--simplify` agree where they apply
/// (the last two on maps of at most 1,024 darts: they are the slow ones, and small maps
/// keep the executions fast). Returns the cellular groups.
pub fn check_map_routes(m: &DenseMap) -> Option<Homology> {
    assert!(m.validate().is_ok());
    let cell = cellular(m);
    if let (Some(a), Some(b)) = (&cell, &simplicial(m)) {
        assert_eq!(a, b, "cellular and simplicial homology differ");
    }
    if let (Some(a), true) = (&cell, m.dart_count() <= 1024) {
        check_simplify_keeps_the_groups(m, a);
    }
    cell
}

/// The cubes of a set in `.cub` text, in the input's coordinates.
pub fn cub_text(s: &CubicalSet) -> String {
    s.cubes().map(|c| format!("({})\n", c.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(","))).collect()
}

/// Invariants of any accepted set: a non-empty box within the limit, a 0/1 bitmap of its
/// volume, the count of its ones.
pub fn check_set(s: &CubicalSet) {
    assert!(s.dim() >= 1);
    assert_eq!(s.min().len(), s.dim());
    let volume = s.shape().iter().try_fold(1u64, |v, &l| v.checked_mul(l as u64)).expect("the volume fits");
    assert!((1..=gmap_ops::import::cubical::MAX_BOX_CUBES).contains(&volume));
    assert_eq!(s.bits().len() as u64, volume);
    assert!(s.bits().iter().all(|&b| b <= 1));
    assert_eq!(s.cube_count(), s.bits().iter().filter(|&&b| b == 1).count());
}

/// Whether every face of the closure has its cubes joined through shared facets (the G-map
/// of the set then has the closure's cells). Periodic boxes need 3 cubes an axis here.
fn cube_stars_connected(s: &CubicalSet, periodic: bool) -> bool {
    let shape = s.shape();
    let d = shape.len();
    let cubes: Vec<Vec<usize>> =
        s.cubes().map(|c| c.iter().zip(s.min()).map(|(&x, &m)| (x - m) as usize).collect()).collect();
    let mut incidences = Vec::new();
    for (k, c) in cubes.iter().enumerate() {
        // a face: per axis the lower end, the interval or the upper end (doubled coordinates)
        for mut code in 0..3usize.pow(d as u32) {
            let mut face = Vec::with_capacity(d);
            for a in 0..d {
                let p = 2 * c[a] + code % 3;
                code /= 3;
                face.push(if periodic { p % (2 * shape[a]) } else { p });
            }
            incidences.push((face, k as u32));
        }
    }
    stars_connected(incidences, |i, j| {
        let (a, b) = (&cubes[i as usize], &cubes[j as usize]);
        let mut differ = 0;
        for ax in 0..d {
            let l = shape[ax];
            let diff = (a[ax] + l - b[ax]) % l;
            if diff == 1 || diff + 1 == l {
                differ += 1;
            } else if diff != 0 {
                return false;
            }
        }
        differ == 1
    })
}

/// The routes of a small cubical set: the CLI's (the collapsed cubical complex) equals the
/// plain complex of the closure, whose `∂∂ = 0` and χ match; the G-map of the union agrees
/// wherever every face's star is joined through facets, with `--simplify` and the
/// simplicial counterpart on that map too.
pub fn check_cubical_routes(s: &CubicalSet) {
    let volume = s.bits().len();
    if volume > 1 << 12 || s.dim() > 4 {
        return;
    }
    for periodic in [false, true] {
        let collapsed = cubical_complex_with(s.shape(), s.bits(), periodic, true).expect("a small box");
        let plain = cubical_complex_with(s.shape(), s.bits(), periodic, false).expect("a small box");
        plain.chain.check_dd().expect("∂∂ = 0 on the plain cubical complex");
        collapsed.chain.check_dd().expect("∂∂ = 0 after the collapses");
        let h = homology_z(&plain.chain).expect("homology of the plain complex");
        assert_eq!(
            homology_z(&collapsed.chain).expect("homology after collapses"),
            h,
            "the collapses changed the groups"
        );
        assert_eq!(h.euler_characteristic(), plain.chain.euler_characteristic());
        for k in 0..collapsed.cells.len() {
            for i in 0..collapsed.cells[k].len() {
                assert_eq!(collapsed.coordinates(k, i).iter().filter(|&&x| x % 2 == 1).count(), k);
            }
        }
        let darts_per_cube = (1usize << s.dim()) * (1..=s.dim()).product::<usize>();
        // a set with lower cells of its own has no G-map (it holds top cubes only; the
        // reader refuses to drop them): the cubical complex only
        let applies = s.is_full()
            && s.cube_count() > 0
            && volume * darts_per_cube <= 1 << 12
            && (!periodic || s.shape().iter().all(|&l| l >= 3))
            && cube_stars_connected(s, periodic);
        if applies {
            let m = s.gmap(periodic).expect("a small box has a G-map");
            let by_map = check_map_routes(&m).expect("a union glued through facets meets C1 and C2");
            assert_eq!(by_map, h, "the G-map of the union and the cubical complex differ (periodic {periodic})");
        }
    }
}

/// The routes of a small pure simplicial complex: the direct chain complex of its faces, and
/// the G-map route wherever the complex is a pseudo-manifold glued through ridges.
pub fn check_simplicial_routes(sc: &gmap_ops::import::SimplicialComplex) {
    let facets: Vec<Vec<u64>> = sc.all_facets().iter().map(|f| f.to_vec()).collect();
    if facets.len() > 64 || sc.dim() > 4 {
        return;
    }
    let direct = gmap_homology::simplices::face_complex(&facets, 1 << 16).expect("a small complex");
    direct.chain.check_dd().expect("∂∂ = 0 on the faces");
    let h = homology_z(&direct.chain).expect("homology of the faces");
    let Ok(m) = sc.to_gmap(1 << 14) else { return };
    let n = sc.dim();
    let mut incidences = Vec::new();
    for (k, f) in facets.iter().enumerate() {
        for mask in 1u32..(1 << f.len()) {
            let face: Vec<u64> = (0..f.len()).filter(|&i| mask & (1 << i) != 0).map(|i| f[i]).collect();
            incidences.push((face, k as u32));
        }
    }
    let ridge = |i: u32, j: u32| {
        let (a, b) = (&facets[i as usize], &facets[j as usize]);
        a.iter().filter(|v| b.contains(v)).count() == n
    };
    let by_map = check_map_routes(&m);
    if stars_connected(incidences, ridge) {
        let by_map = by_map.expect("a pseudo-manifold glued through ridges meets C1 and C2");
        assert_eq!(by_map, h, "the direct and the G-map routes differ");
    }
}

/// The checks of the mesh readers' targets: an accepted mesh makes a valid map (or is
/// refused with an error) whose points and labels are consistent, and the map written back
/// as legacy `.vtk` with its labels reads to a map with the same cells and labels.
pub fn check_mesh(mesh: &gmap_ops::mesh::Mesh) {
    let Ok(g) = mesh.to_gmap(1 << 14) else { return };
    assert!(g.validate().is_ok(), "the map and its labels are consistent");
    let (dense, labels, _) = gmap_core::to_dense_labels(&g);
    assert!(dense.validate().is_ok());
    let Ok(text) = gmap_ops::export::vtk_string_with_labels(&dense, &labels) else { return };
    let back = gmap_ops::import::parse_vtk(text.as_bytes()).expect("the writer's .vtk parses");
    let back = back.to_gmap(1 << 16).expect("the writer's .vtk makes a map");
    let (dense2, labels2, _) = gmap_core::to_dense_labels(&back);
    assert_eq!(dense.cell_counts(), dense2.cell_counts(), "the .vtk round trip keeps the cells");
    // each cell's labels as a sorted list (the writer orders the columns its own way)
    let texts = |l: &gmap_core::Labels| -> String {
        let mut t: Vec<String> = l.iter().map(|(n, v)| format!("{n:?}={v}")).collect();
        t.sort();
        t.join(" ")
    };
    for i in 0..labels.of.len() {
        let mut a: Vec<String> = labels.of[i].iter().map(texts).collect();
        let mut b: Vec<String> = labels2.of[i].iter().map(texts).collect();
        a.sort();
        b.sort();
        assert_eq!(a, b, "the .vtk round trip keeps the labels of dimension {i}");
    }
}

/// What every grey raster reader's image must be: 2-D, rows × columns with none empty, in C
/// order, `u8` or `u16` values. Returns the rows, the columns and whether it has 16 bits.
pub fn check_grey_raster(img: &gmap_ops::import::image::Image, format: &str) -> (usize, usize, bool) {
    use gmap_ops::import::image::{Dtype, Order};
    let (h, w) = match img.shape() {
        &[h, w] => (h, w),
        s => panic!("a {format} image of shape {s:?}"),
    };
    assert!(h > 0 && w > 0);
    assert_eq!(img.order(), Order::C);
    let sixteen = match img.dtype() {
        Dtype::U8 => false,
        Dtype::U16 => true,
        d => panic!("a {format} image of {d:?}"),
    };
    assert_eq!(img.len(), h * w);
    (h, w, sixteen)
}

/// On a small image (at most 2^10 pixels), the cubical set of its non-zero pixels has
/// agreeing routes.
pub fn check_small_raster_routes(img: &gmap_ops::import::image::Image) {
    if img.len() <= 1 << 10 {
        if let Ok(set) = img.to_cubical_set(gmap_ops::import::Level::Nonzero) {
            check_set(&set);
            check_cubical_routes(&set);
        }
    }
}
