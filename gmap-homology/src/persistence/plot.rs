//! Pictures of a diagram as SVG text: the persistence diagram (birth against death, one
//! colour per dimension, essential classes on a line above the finite ones), the barcode,
//! and a 2-D image in grey with a chain drawn over it.

use std::fmt::Write;

use super::{CellName, Chain, Diagram};

const COLOURS: [&str; 6] = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"];

fn colour(dim: usize) -> &'static str {
    COLOURS[dim % COLOURS.len()]
}

/// The finite range of the values, with room for the essential line.
fn range(d: &Diagram) -> (f64, f64) {
    let vals = d.pairs.iter().flat_map(|p| [p.birth, p.death]).filter(|x| x.is_finite());
    let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    if lo > hi {
        (0.0, 1.0)
    } else if lo == hi {
        (lo - 0.5, hi + 0.5)
    } else {
        (lo, hi)
    }
}

fn legend(s: &mut String, d: &Diagram, x: f64, y: f64) {
    let top = d.pairs.iter().map(|p| p.dim).max().unwrap_or(0);
    for k in 0..=top {
        let yy = y + 16.0 * k as f64;
        let _ = writeln!(
            s,
            r#"<circle cx="{x}" cy="{}" r="4" fill="{}"/><text x="{}" y="{yy}" font-size="12">H{k}</text>"#,
            yy - 4.0,
            colour(k),
            x + 8.0
        );
    }
}

/// The persistence diagram as an SVG document of `size` pixels square.
pub fn diagram_svg(d: &Diagram, size: u32) -> String {
    let s = size as f64;
    let (m, lo, hi) = (40.0, range(d).0, range(d).1);
    let span = hi - lo;
    let inner = s - 2.0 * m;
    let px = |v: f64| m + (v - lo) / span * inner * 0.9;
    let py = |v: f64| s - m - (v - lo) / span * inner * 0.9;
    let ess = s - m - inner * 0.97; // the line of essential classes
    let mut out = String::new();
    let _ = writeln!(out, r#"<svg xmlns="http://www.w3.org/2000/svg" width="{s}" height="{s}" viewBox="0 0 {s} {s}">"#);
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(out, r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="grey"/>"#, px(lo), py(lo), px(hi), py(hi));
    let _ =
        writeln!(out, r#"<line x1="{m}" y1="{ess}" x2="{}" y2="{ess}" stroke="grey" stroke-dasharray="4"/>"#, s - m);
    let _ = writeln!(out, r#"<text x="{}" y="{}" font-size="12">+inf</text>"#, 4.0, ess + 4.0);
    let _ = writeln!(
        out,
        r#"<text x="{}" y="{}" font-size="12">{lo}</text><text x="{}" y="{}" font-size="12">{hi}</text>"#,
        m,
        s - m + 16.0,
        px(hi) - 10.0,
        s - m + 16.0
    );
    let _ = writeln!(out, r#"<text x="{}" y="{}" font-size="12">birth</text>"#, s / 2.0, s - 8.0);
    let _ = writeln!(
        out,
        r#"<text x="8" y="{}" font-size="12" transform="rotate(-90 8 {})">death</text>"#,
        s / 2.0,
        s / 2.0
    );
    for p in &d.pairs {
        let y = if p.death.is_finite() { py(p.death) } else { ess };
        let _ = writeln!(
            out,
            r#"<circle cx="{:.2}" cy="{:.2}" r="3" fill="{}" fill-opacity="0.7"/>"#,
            px(p.birth),
            y,
            colour(p.dim)
        );
    }
    legend(&mut out, d, s - m - 30.0, m + 20.0);
    out.push_str("</svg>\n");
    out
}

/// The barcode: one bar per pair, grouped by dimension, `width` pixels wide.
pub fn barcode_svg(d: &Diagram, width: u32) -> String {
    let w = width as f64;
    let (lo, hi) = range(d);
    let m = 40.0;
    let end = w - m;
    let px = |v: f64| {
        if v.is_finite() {
            m + (v - lo) / (hi - lo) * (end - m) * 0.95
        } else {
            end
        }
    };
    let h = 2.0 * m + 4.0 * d.pairs.len() as f64;
    let mut out = String::new();
    let _ = writeln!(out, r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#);
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    for (i, p) in d.pairs.iter().enumerate() {
        let y = m + 4.0 * i as f64;
        let (a, b) = (px(p.birth.min(p.death)), px(p.birth.max(p.death)));
        let _ = writeln!(
            out,
            r#"<line x1="{a:.2}" y1="{y}" x2="{b:.2}" y2="{y}" stroke="{}" stroke-width="3"/>"#,
            colour(p.dim)
        );
    }
    let _ = writeln!(
        out,
        r#"<text x="{m}" y="{}" font-size="12">{lo}</text><text x="{}" y="{}" font-size="12">{hi}</text>"#,
        h - 12.0,
        px(hi) - 10.0,
        h - 12.0
    );
    legend(&mut out, d, w - m - 30.0, 20.0);
    out.push_str("</svg>\n");
    out
}

/// A 2-D image (`rows × cols` values, row-major) in grey, `scale` pixels per value, with
/// the cells of `chain` (doubled-grid names of the V- or T-construction of the same image)
/// drawn over it in red: vertices as dots, edges as segments, squares filled.
pub fn image_with_chain_svg(
    rows: usize,
    cols: usize,
    values: &[f64],
    chain: &Chain,
    vertex_centred: bool,
    scale: u32,
) -> String {
    let sc = scale as f64;
    let (lo, hi) = values.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
    let span = if hi > lo { hi - lo } else { 1.0 };
    let (w, h) = (cols as f64 * sc, rows as f64 * sc);
    let mut out = String::new();
    let _ = writeln!(out, r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#);
    for r in 0..rows {
        for c in 0..cols {
            let g = ((values[r * cols + c] - lo) / span * 255.0).round() as u8;
            let _ = writeln!(
                out,
                r#"<rect x="{}" y="{}" width="{sc}" height="{sc}" fill="rgb({g},{g},{g})"/>"#,
                c as f64 * sc,
                r as f64 * sc
            );
        }
    }
    // a doubled coordinate t maps to pixel units: pixel i spans [i, i+1], its centre i + 1/2
    let at = |t: usize| if vertex_centred { (t as f64 / 2.0 + 0.5) * sc } else { t as f64 / 2.0 * sc };
    for (cell, _) in chain {
        let CellName::Grid(x) = cell else { continue };
        if x.len() != 2 {
            continue;
        }
        let (r, c) = (x[0], x[1]);
        match (r % 2, c % 2) {
            (0, 0) => {
                let _ = writeln!(out, r#"<circle cx="{}" cy="{}" r="{}" fill="red"/>"#, at(c), at(r), sc / 4.0);
            }
            (1, 1) => {
                let _ = writeln!(
                    out,
                    r#"<rect x="{}" y="{}" width="{sc}" height="{sc}" fill="red" fill-opacity="0.4"/>"#,
                    at(c - 1),
                    at(r - 1)
                );
            }
            (1, 0) => {
                let _ = writeln!(
                    out,
                    r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="red" stroke-width="{}"/>"#,
                    at(c),
                    at(r - 1),
                    at(c),
                    at(r + 1),
                    sc / 5.0
                );
            }
            _ => {
                let _ = writeln!(
                    out,
                    r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="red" stroke-width="{}"/>"#,
                    at(c - 1),
                    at(r),
                    at(c + 1),
                    at(r),
                    sc / 5.0
                );
            }
        }
    }
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::persistence::{cubical_persistence, CubicalOptions};

    fn ring() -> Diagram {
        // a ring of low pixels around a high one: one loop, dying at 5
        let values = [1.0, 1.0, 1.0, 1.0, 5.0, 1.0, 1.0, 1.0, 0.0];
        cubical_persistence(&[3, 3], &values, &CubicalOptions { cycles: true, ..Default::default() }).unwrap()
    }

    #[test]
    fn one_mark_per_pair() {
        let d = ring();
        assert_eq!(d.pairs.len(), 2);
        let svg = diagram_svg(&d, 300);
        assert!(svg.starts_with("<svg") && svg.ends_with("</svg>\n"));
        // the pairs' marks and the legend's two dots
        assert_eq!(svg.matches("<circle").count(), d.pairs.len() + 2);
        let bars = barcode_svg(&d, 400);
        assert_eq!(bars.matches("stroke-width=\"3\"").count(), d.pairs.len());
    }

    #[test]
    fn the_loop_is_drawn_over_the_image() {
        let d = ring();
        let k = d.pairs.iter().position(|p| p.dim == 1).unwrap();
        let values = [1.0, 1.0, 1.0, 1.0, 5.0, 1.0, 1.0, 1.0, 0.0];
        let svg = image_with_chain_svg(3, 3, &values, &d.cycles[k], false, 10);
        // nine pixels, and one segment per edge of the loop (at least the middle pixel's four)
        assert_eq!(svg.matches("<rect").count(), 9);
        assert!(d.cycles[k].len() >= 4);
        assert_eq!(svg.matches("<line").count(), d.cycles[k].len());
    }
}
