//! The HTML viewer (`gmap_ops::export::html`) in Firefox: the building's page opened from
//! `file://` in headless Firefox with the network off runs its self test (`#selftest`: every
//! view drawn and read back, the legends, a dart selected and its 2-cell highlighted).
//! Checked: no JavaScript error, no blank view, the legend of the building's rooms, no
//! resource loaded, a screenshot written. Skipped, with a notice, when no Firefox is
//! installed (`apt-get install firefox-esr`). `GMAP_VIEW_OUT=DIR` keeps the page in `DIR`.

#[path = "../examples/building.rs"]
#[allow(dead_code)]
mod building;
#[path = "common/chromium.rs"]
mod chromium;
#[path = "common/firefox.rs"]
mod firefox;

use gmap_core::to_dense_labels;
use gmap_ops::export::html::{html_string, HtmlOptions, Scene};

#[test]
fn the_building_opens_from_file_in_firefox() {
    let Some(browser) = firefox::firefox() else { return };
    let g = building::building().unwrap();
    let (m, labels, _) = to_dense_labels(&g);
    let scene = Scene::from_map(&m, Some(&labels), "building");
    let page = html_string(&scene, &HtmlOptions::default()).unwrap();
    let dir = std::env::var_os("GMAP_VIEW_OUT").map(std::path::PathBuf::from);
    let tmp = tempfile::tempdir().unwrap();
    let dir = dir.unwrap_or_else(|| tmp.path().to_path_buf());
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("building-firefox.html");
    std::fs::write(&path, &page).unwrap();

    let run = firefox::run_selftest(&browser, &path);
    let r = &run.selftest;
    assert!(run.page_errors.is_empty(), "JavaScript errors: {:?}", run.page_errors);
    assert_eq!(r["errors"], serde_json::json!([]), "errors {}", r["errors"]);
    assert_eq!(r["resources"], serde_json::json!([]), "resources loaded");
    assert_eq!(r["domUrls"], serde_json::json!([]), "addresses in the document");
    assert_eq!(r["cellCounts"], serde_json::json!(scene.counts()), "the page's cells");
    for (v, s) in r["views"].as_object().unwrap() {
        let lit = s["nonBlank"].as_u64().unwrap();
        assert!(lit > 500, "the {v} view drew {lit} pixels");
    }
    let legend: Vec<&str> = r["legendCells"].as_array().unwrap().iter().map(|v| v.as_str().unwrap()).collect();
    for room in ["hall", "living", "kitchen", "study", "landing", "bedroom", "bathroom", "office"] {
        assert!(legend.contains(&room), "legend {legend:?} lacks {room}");
    }
    let sel = r["selection"].as_str().unwrap();
    assert!(sel.starts_with("dart 0\nα0 = "), "{sel}");
    assert!(r["highlightChanged"].as_u64().unwrap() > 50);
    assert!(run.screenshot_bytes > 1000, "screenshot of {} bytes", run.screenshot_bytes);
    eprintln!(
        "building in Firefox: {} darts, first frame {:.0} ms after the script started, browser run {:.2} s{}",
        r["darts"],
        r["setupMs"].as_f64().unwrap_or(f64::NAN),
        run.wall.as_secs_f64(),
        if run.isolated { ", in a network namespace without network" } else { ", network off by proxy" }
    );
}
