//! The HTML viewer (`gmap_ops::export::html`) in a real browser: each page is opened in
//! headless Chromium with the network off and runs its self test (`#selftest`): every view
//! drawn and read back, the legends, each generator hidden in turn, a dart selected and its
//! 2-cell highlighted. Checked here: no console error, no blank canvas, the legend of the
//! building's rooms, pixels that change with each generator, no http(s) request (page
//! source, the page's resource list and the browser's network log). Skipped, with a notice,
//! when no Chromium is installed (`apt-get install chromium`).
//!
//! `GMAP_VIEW_OUT=DIR` keeps the pages in `DIR`.

#[path = "../examples/building.rs"]
#[allow(dead_code)]
mod building;
#[path = "common/chromium.rs"]
mod chromium;

use std::path::PathBuf;

use gmap_core::{to_dense_labels, DenseMap};
use gmap_homology::{cellular_complex, generators::generators};
use gmap_ops::export::html::{html_string, HtmlOptions, Scene, ViewGenerator};
use serde_json::Value;

/// Writes a page to `$GMAP_VIEW_OUT` or a temporary folder (kept alive by the returned
/// guard) and returns its path.
fn write_page(name: &str, page: &str) -> (PathBuf, Option<tempfile::TempDir>) {
    assert!(!page.contains("http://") && !page.contains("https://"), "{name}: the page names an http(s) address");
    match std::env::var_os("GMAP_VIEW_OUT") {
        Some(dir) => {
            std::fs::create_dir_all(&dir).unwrap();
            let p = PathBuf::from(dir).join(format!("{name}.html"));
            std::fs::write(&p, page).unwrap();
            (p, None)
        }
        None => {
            let t = tempfile::tempdir().unwrap();
            let p = t.path().join(format!("{name}.html"));
            std::fs::write(&p, page).unwrap();
            (p, Some(t))
        }
    }
}

/// The generators of a map's cellular homology, in the map's cell numbering.
fn map_generators(m: &DenseMap) -> Vec<ViewGenerator> {
    let c = cellular_complex(m).unwrap();
    let gens = generators(&c.chain, None).unwrap();
    let mut count = vec![0usize; m.dim() + 1];
    gens.iter()
        .map(|g| {
            let part = m.cells(g.dim);
            let cells = g.chain.iter().map(|&(j, _)| part.of[c.reps[g.dim][j as usize].index()]).collect();
            count[g.dim] += 1;
            let order = if g.order.to_u64() == Some(0) { "Z".to_string() } else { format!("Z/{}", g.order) };
            ViewGenerator { name: format!("H{} #{} ({order})", g.dim, count[g.dim] - 1), dim: g.dim, cells }
        })
        .collect()
}

/// Opens a page and checks what every page must show; returns the self test's results.
fn check(name: &str, scene: &Scene, opts: &HtmlOptions) -> Option<(Value, chromium::Run)> {
    let browser = chromium::chromium()?;
    let page = html_string(scene, opts).unwrap();
    let (path, _guard) = write_page(name, &page);
    let run = chromium::run_selftest(&browser, &path);
    let r = run.selftest.clone();
    assert_eq!(r["errors"], serde_json::json!([]), "{name}: errors {}", r["errors"]);
    assert!(run.console_errors.is_empty(), "{name}: {:?}", run.console_errors);
    assert_eq!(r["resources"], serde_json::json!([]), "{name}: resources loaded");
    assert_eq!(r["domUrls"], serde_json::json!([]), "{name}: addresses in the document");
    assert!(run.page_requests.is_empty(), "{name}: network requests {:?}", run.page_requests);
    if scene.dart_count() > 0 && scene.dart_count() <= opts.dart_limit {
        assert_eq!(r["cellCounts"], serde_json::json!(scene.counts()), "{name}: the page's cells");
        assert_eq!(r["numberedBySmallestDart"], true, "{name}");
    }
    let (w, h) = (r["canvas"][0].as_u64().unwrap(), r["canvas"][1].as_u64().unwrap());
    assert!(w >= 800 && h >= 600, "{name}: canvas {w}×{h}");
    for (v, s) in r["views"].as_object().unwrap() {
        let lit = s["nonBlank"].as_u64().unwrap();
        assert!(lit > 500, "{name}: the {v} view drew {lit} pixels");
    }
    eprintln!(
        "{name}: {} darts, first frame {:.0} ms after the script started, browser run {:.2} s{}",
        r["darts"],
        r["setupMs"].as_f64().unwrap_or(f64::NAN),
        run.wall.as_secs_f64(),
        if run.isolated {
            ", in a network namespace without network"
        } else {
            ", network off by proxy and resolver rules"
        }
    );
    Some((r, run))
}

#[test]
fn the_building_shows_its_rooms_in_the_legend() {
    let g = building::building().unwrap();
    let (m, labels, _) = to_dense_labels(&g);
    let scene = Scene::from_map(&m, Some(&labels), "building");
    let Some((r, _)) = check("building", &scene, &HtmlOptions::default()) else { return };
    let legend: Vec<&str> = r["legendCells"].as_array().unwrap().iter().map(|v| v.as_str().unwrap()).collect();
    for room in ["hall", "living", "kitchen", "study", "landing", "bedroom", "bathroom", "office"] {
        assert!(legend.contains(&room), "legend {legend:?} lacks {room}");
    }
    // the darts view's legend: a colour per involution and the free darts
    let darts: Vec<&str> = r["legendDarts"].as_array().unwrap().iter().map(|v| v.as_str().unwrap()).collect();
    assert!(darts.contains(&"α3 link") && darts.iter().any(|l| l.starts_with("free dart")), "{darts:?}");
    // the selected dart 0: its involutions and cells, and the highlight drew something
    let sel = r["selection"].as_str().unwrap();
    assert!(sel.starts_with("dart 0\nα0 = "), "{sel}");
    assert!(sel.contains("3-cell 0: name=\""), "{sel}");
    assert!(r["highlightChanged"].as_u64().unwrap() > 50);
}

#[test]
fn each_generator_of_the_torus_changes_pixels() {
    let t = gmap_ops::build::placed::torus_with_points(16, 8, 2.0, 0.75).unwrap();
    let gens = map_generators(&t);
    let h1: Vec<_> = gens.into_iter().filter(|g| g.dim == 1).collect();
    assert_eq!(h1.len(), 2);
    let mut scene = Scene::from_map(&t, None, "torus");
    for g in h1 {
        scene.add_generator(g).unwrap();
    }
    let Some((r, _)) = check("torus", &scene, &HtmlOptions::default()) else { return };
    let toggles: Vec<u64> = r["generatorToggle"].as_array().unwrap().iter().map(|v| v.as_u64().unwrap()).collect();
    assert_eq!(toggles.len(), 2);
    assert!(toggles.iter().all(|&c| c > 100), "{toggles:?}");
}

#[test]
fn the_moebius_band_without_points_is_laid_out() {
    let m = gmap_ops::build::schema("a b a c").unwrap();
    assert!(!m.has_points());
    let mut scene = Scene::from_map(&m, None, "Moebius band");
    assert!(scene.placement().contains("pivot MDS"));
    for g in map_generators(&m) {
        scene.add_generator(g).unwrap();
    }
    let Some((r, _)) = check("moebius", &scene, &HtmlOptions::default()) else { return };
    assert!(r["generatorToggle"].as_array().unwrap().iter().all(|v| v.as_u64().unwrap() > 0));
}

#[test]
fn a_three_manifold_from_facets_is_laid_out() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lutz/poincare.facets");
    let m = gmap_ops::import::read_facets(&path, None).unwrap();
    assert_eq!(m.dim(), 3);
    let scene = Scene::from_map(&m, None, "poincare.facets");
    let Some((r, _)) = check("poincare", &scene, &HtmlOptions::default()) else { return };
    assert!(r["selection"].as_str().unwrap().contains("3-cell"));
}

#[test]
fn a_cubical_set_with_a_generator_made_of_cubes() {
    // a ring of eight cubes around a hole: H1 = Z
    let text = "(0,0,0)\n(1,0,0)\n(2,0,0)\n(0,1,0)\n(2,1,0)\n(0,2,0)\n(1,2,0)\n(2,2,0)\n";
    let set = gmap_ops::import::cubical::parse_cub(text.as_bytes()).unwrap();
    let mut scene = Scene::from_cubical(&set, "ring of cubes");
    let c = gmap_homology::cubical::cubical_complex_with(set.shape(), set.bits(), false, true).unwrap();
    let gens = generators(&c.chain, None).unwrap();
    let h1: Vec<_> = gens.iter().filter(|g| g.dim == 1).collect();
    assert_eq!(h1.len(), 1);
    for g in h1 {
        let mut cells = Vec::new();
        for &(i, _) in &g.chain {
            let x = c.coordinates(1, i as usize);
            let min: Vec<i64> = x.iter().zip(set.min()).map(|(&x, &m)| m + (x / 2) as i64).collect();
            let ext: Vec<u8> = x.iter().map(|&x| (x % 2) as u8).collect();
            cells.push(scene.add_cube(&min, &ext).unwrap());
        }
        scene.add_generator(ViewGenerator { name: "H1 #0 (Z)".into(), dim: 1, cells }).unwrap();
    }
    let Some((r, _)) = check("cubical", &scene, &HtmlOptions::default()) else { return };
    assert!(r["views"].get("darts").is_none());
    assert!(r["generatorToggle"][0].as_u64().unwrap() > 100, "{}", r["generatorToggle"]);
}

#[test]
fn a_four_map_states_its_rule() {
    let m = gmap_ops::build::cube(4).unwrap();
    let scene = Scene::from_map(&m, None, "tesseract");
    let page = html_string(&scene, &HtmlOptions::default()).unwrap();
    assert!(page.contains("drawn in 3-D by a projection"));
    let Some((r, _)) = check("tesseract", &scene, &HtmlOptions::default()) else { return };
    let legend: Vec<&str> = r["legendDarts"].as_array().unwrap().iter().map(|v| v.as_str().unwrap()).collect();
    assert!(legend.contains(&"α4 link"), "{legend:?}");
}

/// About 1.5 M darts: the 32³ grid of cubes (1,572,864 darts; the 25³ grid has 750,000)
/// renders within 5 s of the page's start, the darts view thinned.
#[test]
fn a_grid_of_a_million_and_a_half_darts_renders_within_five_seconds() {
    let m = gmap_ops::build::placed::grid_with_points(&[32, 32, 32], &[false; 3]).unwrap();
    assert_eq!(m.dart_count(), 1_572_864);
    let scene = Scene::from_map(&m, None, "grid 32³");
    let page = html_string(&scene, &HtmlOptions::default()).unwrap();
    let per_dart = page.len() as f64 / m.dart_count() as f64;
    eprintln!("grid 32³: page of {} bytes, {per_dart:.1} bytes per dart", page.len());
    assert!(per_dart < 23.0, "{per_dart}");
    let Some((r, run)) = check("grid32", &scene, &HtmlOptions::default()) else { return };
    let first = r["firstFrameMs"].as_f64().unwrap();
    assert!(first < 5000.0, "first frame after {first} ms");
    assert!(r["message"].as_str().unwrap().contains("above the darts view's limit"), "{}", r["message"]);
    eprintln!(
        "grid 32³: first frame {first:.0} ms after navigation, phases {}, browser run {:.2} s",
        r["marks"],
        run.wall.as_secs_f64()
    );
}
