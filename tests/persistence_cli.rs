//! `gmap persistence`: the command's JSON equals GUDHI's recorded diagram of a sample image,
//! a valued `.facets` file is read, vertex values give the lower-star filtration, a
//! composite field and the options of images on a complex are refused, pictures are
//! written as SVG and PNG.

use std::process::Command;

use serde_json::Value;

fn gmap(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_gmap")).args(args).output().unwrap()
}

fn sorted(pairs: &Value) -> Vec<String> {
    let mut v: Vec<String> = pairs.as_array().unwrap().iter().map(|p| p.to_string()).collect();
    v.sort();
    v
}

#[test]
fn coins_equals_gudhi_in_both_constructions() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/images");
    let rec: Value = serde_json::from_str(&std::fs::read_to_string(dir.join("coins.json")).unwrap()).unwrap();
    for (cons, key) in [("T", "T_sub_n_3"), ("V", "V_sub_n_3")] {
        let out = gmap(&[
            "persistence",
            dir.join("coins.pgm").to_str().unwrap(),
            "--construction",
            cons,
            "--field",
            "3",
            "--json",
        ]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let got: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(got["field"], 3);
        assert_eq!(sorted(&got["pairs"]), sorted(&rec["diagrams"][key]), "{cons}");
    }
}

#[test]
fn valued_facets_and_refusals() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("tet.facets");
    std::fs::write(&f, "# the boundary of a tetrahedron\n1 2 3 : 1\n2 3 4 : 2\n1 3 4 : 3\n1 2 4 : 4\n").unwrap();
    let out = gmap(&["persistence", f.to_str().unwrap()]);
    assert!(out.status.success());
    // one component from 1; the sphere closes at 4
    assert_eq!(String::from_utf8_lossy(&out.stdout), "0 1 inf\n2 4 inf\n");
    let out = gmap(&["persistence", f.to_str().unwrap(), "--field", "4"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("Z/4"));
}

#[test]
fn vertex_values_give_the_lower_star_filtration() {
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/persistence");
    let (cone, values) = (data.join("square_cone.facets"), data.join("square_cone.values"));
    let (cone, values) = (cone.to_str().unwrap(), values.to_str().unwrap());
    let out = gmap(&["persistence", cone, "--vertex-values", values, "--json", "--field", "3"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let got: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(got["pairs"], serde_json::json!([[0, 0.0, 1.0], [0, 0.0, "inf"], [1, 1.0, 3.0]]));

    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let refused = |args: &[&str], needle: &str| {
        let out = gmap(args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("error: ") && err.contains(needle), "{args:?}: {err}");
    };
    // the apex has no value: named with the file
    let four = write("four.values", "1 0\n2 1\n3 0\n4 1\n");
    refused(&["persistence", cone, "--vertex-values", &four], "square_cone.facets: bad input: vertex 5 has no value");
    // a bad line of the values file: named with its line
    let twice = write("twice.values", "1 0\n1 2\n");
    refused(&["persistence", cone, "--vertex-values", &twice], "twice.values: line 2: vertex 1 has a value on line 1");
    // values per facet and per vertex at once
    let valued = write("valued.facets", "1 2 : 0\n2 3 : 1\n");
    refused(&["persistence", &valued, "--vertex-values", values], "give one filtration");
    // an image's values are its pixels
    let img = data.join("../images/coins.pgm");
    refused(&["persistence", img.to_str().unwrap(), "--vertex-values", values], "vertex values are for simplicial");
    // the options only images take are refused for a complex, not ignored
    refused(&["persistence", &valued, "--periodic"], "periodic applies to images");
    refused(&["persistence", cone, "--vertex-values", values, "--periodic"], "periodic applies to images");
    refused(&["persistence", &valued, "--construction", "V"], "the V-construction applies to images");
    // superlevel sets: the upper star (the apex first, the rest joins it), and per facet a
    // face taking its facets' maximum (vertex 2 enters with the edge 2 3 at 1)
    let text = |args: &[&str]| {
        let out = gmap(args);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        String::from_utf8(out.stdout).unwrap()
    };
    assert_eq!(text(&["persistence", cone, "--vertex-values", values, "--superlevel"]), "0 3 -inf\n");
    assert_eq!(text(&["persistence", &valued, "--superlevel"]), "0 1 -inf\n");
}

#[test]
fn an_architectural_complex_filtered_by_its_labels() {
    // a floor (region 0, at 2.5) around a court: the outer square's corners at 0, the
    // court's at 1; the chain complex `gmap homology` computes (the court's edges bound
    // the floor together with the outer ones, and nothing joins the two squares)
    let court = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/persistence/court_valued.json");
    let out = gmap(&["persistence", court.to_str().unwrap(), "--cycles"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout);
    let pairs: Vec<&str> = text.lines().filter(|l| !l.starts_with(' ')).collect();
    assert_eq!(pairs, ["0 0 inf", "0 1 inf", "1 0 inf", "1 1 2.5"]);
    // the outer square's loop, by region id
    assert!(text.contains("1 0 inf\n  cycle: 1*1-region 5 + 1*1-region 6 + 1*1-region 7 + 1*1-region 8\n"), "{text}");
    let out = gmap(&["persistence", court.to_str().unwrap(), "--label", "name"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("0-region 1 has no value"));
    let out = gmap(&["persistence", court.to_str().unwrap(), "--periodic"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("an architectural complex: periodic applies to images"));
    // superlevel: the court (at 1) comes first with its loop, which the floor (lowered to
    // 0 with the outer square) never fills: the outer square's loop dies as it is born
    let out = gmap(&["persistence", court.to_str().unwrap(), "--superlevel"]);
    assert_eq!(String::from_utf8_lossy(&out.stdout), "0 0 -inf\n0 1 -inf\n1 1 -inf\n");
}

#[test]
fn an_image_past_the_memory_limit_takes_its_lower_stars_or_is_refused() {
    let images = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/images");
    let coins = images.join("coins.pgm");
    let coins = coins.to_str().unwrap();
    // 16 MiB for the program, then 51 × 64 pixels at 64 bytes each by the pixel route: past
    // 16M, the Morse route; with no room for a critical cell it is refused with the count
    let out = gmap(&["persistence", coins, "--max-memory", "16M"]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("coins.pgm: too large: the image of shape [51, 64] has more than 0 critical cells, over the memory limit of 16777216 bytes at 96 bytes each"),
        "{err}"
    );
    // with cycles, the general route's grid: 103 × 129 cells at 256 bytes; the Morse route
    // takes no cycles
    let out = gmap(&["persistence", coins, "--cycles", "--max-memory", "17M"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("a 51×64 image would take an estimated 20178688 bytes, over the memory limit of 17825792 bytes (--max-memory); past the limit an image is computed from its lower stars, which takes 1 to 4 axes and neither periodic images nor cycles"),
        "{err}"
    );
    let out = gmap(&["persistence", coins, "--periodic", "--max-memory", "16587K"]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("neither periodic images nor cycles"));
    let out = gmap(&["persistence", coins, "--max-memory", "17M"]);
    assert!(out.status.success());
    // the Morse route (16 MiB and 203 KiB: room for 2,165 critical cells, of the 1,321 to
    // 1,957 these images keep) gives GUDHI's
    // recorded diagrams, both constructions, sublevel and superlevel, over Z/2 and Z/3
    for name in ["coins", "camera", "moon"] {
        let file = images.join(format!("{name}.npy"));
        let rec: Value =
            serde_json::from_str(&std::fs::read_to_string(images.join(format!("{name}.json"))).unwrap()).unwrap();
        for cons in ["T", "V"] {
            for (level, flag) in [("sub", None), ("super", Some("--superlevel"))] {
                for p in ["2", "3"] {
                    let mut args =
                        vec!["persistence", file.to_str().unwrap(), "--construction", cons, "--field", p, "--json"];
                    args.extend(flag);
                    let whole = gmap(&args);
                    args.extend(["--max-memory", "16587K"]);
                    let morse = gmap(&args);
                    assert!(
                        morse.status.success(),
                        "{name} {cons} {level} {p}: {}",
                        String::from_utf8_lossy(&morse.stderr)
                    );
                    let got: Value = serde_json::from_slice(&morse.stdout).unwrap();
                    let key = format!("{cons}_{level}_n_{p}");
                    assert_eq!(sorted(&got["pairs"]), sorted(&rec["diagrams"][&key]), "{name} {key}");
                    assert_eq!(morse.stdout, whole.stdout, "{name} {key}");
                }
            }
        }
    }
}

/// Decodes a PNG file: (width, height, RGB bytes).
fn decode_png(path: &std::path::Path) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.color_type, info.bit_depth), (png::ColorType::Rgb, png::BitDepth::Eight));
    buf.truncate(info.buffer_size());
    (info.width, info.height, buf)
}

#[test]
fn pictures_as_png() {
    let dir = tempfile::tempdir().unwrap();
    // a ring of 1s around a 5 in a 3 × 3 image: one loop, born at 1, dead at 5
    let img = dir.path().join("ring.pgm");
    std::fs::write(&img, "P2\n3 3\n255\n1 1 1\n1 5 1\n1 1 0\n").unwrap();
    let (plot, bars, cycle, svg) =
        (dir.path().join("d.png"), dir.path().join("b.png"), dir.path().join("c.png"), dir.path().join("c.svg"));
    let out = gmap(&[
        "persistence",
        img.to_str().unwrap(),
        "--cycles",
        "--plot",
        plot.to_str().unwrap(),
        "--barcode",
        bars.to_str().unwrap(),
        "--draw-cycle",
        "1",
        cycle.to_str().unwrap(),
        "--json",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let got: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(got["pairs"], serde_json::json!([[0, 0.0, "inf"], [1, 1.0, 5.0]]));
    // the diagram: 500 × 500, white in a corner, a blue (H1) disc somewhere and a red (H0) one
    let (w, h, rgb) = decode_png(&plot);
    assert_eq!((w, h), (500, 500));
    let px = |x: u32, y: u32| [0, 1, 2].map(|k| rgb[3 * (y * w + x) as usize + k]);
    assert_eq!(px(w - 1, h - 1), [255, 255, 255]);
    let count = |c: [u8; 3]| (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).filter(|&(x, y)| px(x, y) == c).count();
    assert!(count([31, 119, 180]) >= 20, "the H1 point is drawn");
    assert!(count([214, 39, 40]) >= 20, "the H0 point is drawn");
    // the barcode: 600 wide, two bars
    let (bw, bh, brgb) = decode_png(&bars);
    assert_eq!((bw, bh), (600, 88));
    assert!(brgb.chunks(3).any(|c| c == [31, 119, 180]) && brgb.chunks(3).any(|c| c == [214, 39, 40]));
    // the image at 20 pixels a pixel, the loop in red around the middle pixel
    let (cw, ch, crgb) = decode_png(&cycle);
    assert_eq!((cw, ch), (60, 60));
    let at = |x: u32, y: u32| [0, 1, 2].map(|k| crgb[3 * (y * cw + x) as usize + k]);
    assert_eq!(at(30, 20), [255, 0, 0]);
    assert_eq!(at(30, 30), [255, 255, 255]);
    // the same picture as SVG, and a refused extension
    let out = gmap(&["persistence", img.to_str().unwrap(), "--cycles", "--draw-cycle", "1", svg.to_str().unwrap()]);
    assert!(out.status.success());
    assert!(std::fs::read_to_string(&svg).unwrap().contains("stroke=\"red\""));
    let out = gmap(&["persistence", img.to_str().unwrap(), "--plot", dir.path().join("d.gif").to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains(".png"));
}

#[test]
fn perseus_files_cubical_and_simplicial() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/persistence");
    let run = |name: &str| {
        let out = gmap(&["persistence", dir.join(name).to_str().unwrap(), "--json"]);
        (
            out.status.code(),
            serde_json::from_slice::<Value>(&out.stdout).ok(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    // GUDHI's CubicalOneSphere.txt (test_cubical_complex.py::test_dimension_file_constructor)
    let (code, json, err) = run("one_sphere.txt");
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(sorted(&json.unwrap()["pairs"]), vec![r#"[0,0.0,"inf"]"#, "[1,0.0,100.0]"]);
    // a simplicial file: the loop closes at 3.5, the vertices join at 1 and 2
    let (code, json, err) = run("hollow_triangle.txt");
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(
        sorted(&json.unwrap()["pairs"]),
        vec![r#"[0,0.0,"inf"]"#, "[0,0.0,1.0]", "[0,0.0,2.0]", r#"[1,3.5,"inf"]"#]
    );
    // a periodic one is refused with the reason (an image does not wrap)
    let (code, _, err) = run("torus.txt");
    assert_ne!(code, Some(0));
    assert!(err.contains("periodic axes [true, true]") && err.contains("torus.txt"), "{err}");
}

#[test]
fn a_valued_complex_converted_says_it_drops_the_values() {
    // no writer keeps a facet's filtration value: convert refuses, naming them, and with
    // --lossy writes the facets and says what went
    let dir = tempfile::tempdir().unwrap();
    let valued = dir.path().join("valued.facets");
    std::fs::write(&valued, "1 2 : 0\n2 3 : 1\n").unwrap();
    let out_path = dir.path().join("plain.facets");
    let (v, o) = (valued.to_str().unwrap(), out_path.to_str().unwrap());
    let out = gmap(&["convert", v, o]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("drops the facet values"), "{err}");
    assert!(!out_path.exists());
    let out = gmap(&["convert", v, o, "--lossy"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(String::from_utf8_lossy(&out.stderr).contains("drops the facet values"));
    assert_eq!(gmap(&["homology", o]).status.code(), Some(0));
}
