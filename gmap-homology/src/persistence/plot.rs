//! Pictures of a diagram: the persistence diagram (birth against death, one colour per
//! dimension, essential classes on a line above the finite ones), the barcode, and a 2-D
//! image in grey with a chain drawn over it; as SVG text (`*_svg`, with axis labels) or as
//! an RGB [`Raster`] drawn here pixel by pixel (`*_raster`, the same marks without text), which
//! the facade encodes as PNG. No font, no renderer, no Python.

use std::fmt::Write;

use super::{CellName, Chain, Diagram};

const COLOURS: [&str; 6] = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"];
const RGB: [[u8; 3]; 6] =
    [[214, 39, 40], [31, 119, 180], [44, 160, 44], [148, 103, 189], [255, 127, 14], [140, 86, 75]];

fn colour(dim: usize) -> &'static str {
    COLOURS[dim % COLOURS.len()]
}

fn rgb(dim: usize) -> [u8; 3] {
    RGB[dim % RGB.len()]
}

/// Where the diagram's marks go in a square of `size` pixels: value to x, value to y, and
/// the height of the line of essential classes.
struct DiagramLayout {
    size: f64,
    margin: f64,
    lo: f64,
    hi: f64,
    ess: f64,
}

impl DiagramLayout {
    fn new(d: &Diagram, size: u32) -> Self {
        let (s, margin) = (size as f64, 40.0);
        let (lo, hi) = range(d);
        DiagramLayout { size: s, margin, lo, hi, ess: s - margin - (s - 2.0 * margin) * 0.97 }
    }

    fn x(&self, v: f64) -> f64 {
        self.margin + (v - self.lo) / (self.hi - self.lo) * (self.size - 2.0 * self.margin) * 0.9
    }

    fn y(&self, v: f64) -> f64 {
        if v.is_finite() {
            self.size - self.margin - (v - self.lo) / (self.hi - self.lo) * (self.size - 2.0 * self.margin) * 0.9
        } else {
            self.ess
        }
    }
}

/// Where the barcode's bars go: `width` pixels wide, one bar every 4 pixels.
struct BarLayout {
    margin: f64,
    lo: f64,
    hi: f64,
    end: f64,
    height: f64,
}

impl BarLayout {
    fn new(d: &Diagram, width: u32) -> Self {
        let (lo, hi) = range(d);
        let margin = 40.0;
        BarLayout { margin, lo, hi, end: width as f64 - margin, height: 2.0 * margin + 4.0 * d.pairs.len() as f64 }
    }

    fn x(&self, v: f64) -> f64 {
        if v.is_finite() {
            self.margin + (v - self.lo) / (self.hi - self.lo) * (self.end - self.margin) * 0.95
        } else {
            self.end
        }
    }

    fn y(&self, i: usize) -> f64 {
        self.margin + 4.0 * i as f64
    }
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
    let l = DiagramLayout::new(d, size);
    let (s, m, lo, hi, ess) = (l.size, l.margin, l.lo, l.hi, l.ess);
    let px = |v: f64| l.x(v);
    let py = |v: f64| l.y(v);
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
        let y = py(p.death);
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
    let l = BarLayout::new(d, width);
    let (lo, hi, m, h) = (l.lo, l.hi, l.margin, l.height);
    let px = |v: f64| l.x(v);
    let mut out = String::new();
    let _ = writeln!(out, r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#);
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    for (i, p) in d.pairs.iter().enumerate() {
        let y = l.y(i);
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

/// The grey level (0 black to 255 white) of each value of an image, its lowest value black
/// and its highest white (a constant image black).
fn greys(values: &[f64]) -> Vec<u8> {
    let (lo, hi) = values.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
    let span = if hi > lo { hi - lo } else { 1.0 };
    values.iter().map(|&v| ((v - lo) / span * 255.0).round() as u8).collect()
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
    let grey = greys(values);
    let (w, h) = (cols as f64 * sc, rows as f64 * sc);
    let mut out = String::new();
    let _ = writeln!(out, r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#);
    for r in 0..rows {
        for c in 0..cols {
            let g = grey[r * cols + c];
            let _ = writeln!(
                out,
                r#"<rect x="{}" y="{}" width="{sc}" height="{sc}" fill="rgb({g},{g},{g})"/>"#,
                c as f64 * sc,
                r as f64 * sc
            );
        }
    }
    for mark in chain_marks(chain, vertex_centred, sc) {
        let _ = match mark {
            Mark::Dot { x, y, r } => writeln!(out, r#"<circle cx="{x}" cy="{y}" r="{r}" fill="red"/>"#),
            Mark::Square { x, y, side } => {
                writeln!(out, r#"<rect x="{x}" y="{y}" width="{side}" height="{side}" fill="red" fill-opacity="0.4"/>"#)
            }
            Mark::Segment { x1, y1, x2, y2, width } => {
                writeln!(out, r#"<line x1="{x1}" y1="{y1}" x2="{x2}" y2="{y2}" stroke="red" stroke-width="{width}"/>"#)
            }
        };
    }
    out.push_str("</svg>\n");
    out
}

/// A cell of a chain drawn over an image, in picture units.
enum Mark {
    Dot { x: f64, y: f64, r: f64 },
    Square { x: f64, y: f64, side: f64 },
    Segment { x1: f64, y1: f64, x2: f64, y2: f64, width: f64 },
}

/// The marks of a chain's 2-D grid cells at `sc` picture units per pixel: vertices as dots,
/// edges as segments, squares filled.
fn chain_marks(chain: &Chain, vertex_centred: bool, sc: f64) -> Vec<Mark> {
    // a doubled coordinate t maps to pixel units: pixel i spans [i, i+1], its centre i + 1/2
    let at = |t: usize| if vertex_centred { (t as f64 / 2.0 + 0.5) * sc } else { t as f64 / 2.0 * sc };
    let mut marks = Vec::new();
    for (cell, _) in chain {
        let CellName::Grid(x) = cell else { continue };
        if x.len() != 2 {
            continue;
        }
        let (r, c) = (x[0], x[1]);
        let width = sc / 5.0;
        marks.push(match (r % 2, c % 2) {
            (0, 0) => Mark::Dot { x: at(c), y: at(r), r: sc / 4.0 },
            (1, 1) => Mark::Square { x: at(c - 1), y: at(r - 1), side: sc },
            (1, 0) => Mark::Segment { x1: at(c), y1: at(r - 1), x2: at(c), y2: at(r + 1), width },
            _ => Mark::Segment { x1: at(c - 1), y1: at(r), x2: at(c + 1), y2: at(r), width },
        });
    }
    marks
}

/// An RGB picture, row by row from the top, 3 bytes per pixel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Raster {
    /// width in pixels
    pub width: u32,
    /// height in pixels
    pub height: u32,
    /// `3 · width · height` bytes
    pub rgb: Vec<u8>,
}

impl Raster {
    /// A white picture. Sizes are clamped to at least one pixel.
    pub fn new(width: u32, height: u32) -> Self {
        let (width, height) = (width.max(1), height.max(1));
        Raster { width, height, rgb: vec![255; 3 * width as usize * height as usize] }
    }

    /// The colour at `(x, y)`.
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        let i = 3 * (y as usize * self.width as usize + x as usize);
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    /// Blends `c` with opacity `a` into pixel `(x, y)`, if inside.
    fn blend(&mut self, x: i64, y: i64, c: [u8; 3], a: f64) {
        if x < 0 || y < 0 || x >= self.width as i64 || y >= self.height as i64 {
            return;
        }
        let i = 3 * (y as usize * self.width as usize + x as usize);
        for (px, &ck) in self.rgb[i..i + 3].iter_mut().zip(&c) {
            let old = *px as f64;
            *px = (old + (ck as f64 - old) * a).round() as u8;
        }
    }

    /// Fills the axis-aligned rectangle `[x0, x1) × [y0, y1)`.
    fn rect(&mut self, x0: f64, y0: f64, x1: f64, y1: f64, c: [u8; 3], a: f64) {
        for y in y0.round() as i64..y1.round() as i64 {
            for x in x0.round() as i64..x1.round() as i64 {
                self.blend(x, y, c, a);
            }
        }
    }

    /// A filled disc.
    fn disc(&mut self, cx: f64, cy: f64, r: f64, c: [u8; 3], a: f64) {
        let (x0, x1) = ((cx - r).floor() as i64, (cx + r).ceil() as i64);
        let (y0, y1) = ((cy - r).floor() as i64, (cy + r).ceil() as i64);
        for y in y0..=y1 {
            for x in x0..=x1 {
                let (dx, dy) = (x as f64 + 0.5 - cx, y as f64 + 0.5 - cy);
                if dx * dx + dy * dy <= r * r {
                    self.blend(x, y, c, a);
                }
            }
        }
    }

    /// A segment `width` pixels thick; with `dash`, drawn `dash` on and `dash` off.
    #[allow(clippy::too_many_arguments)]
    fn segment(&mut self, x1: f64, y1: f64, x2: f64, y2: f64, width: f64, c: [u8; 3], dash: Option<f64>) {
        let len = (x2 - x1).hypot(y2 - y1);
        let steps = (len * 2.0).ceil().max(1.0) as usize;
        let half = (width / 2.0).max(0.5);
        for s in 0..=steps {
            let t = s as f64 / steps as f64;
            if dash.is_some_and(|d| (t * len / d) as usize % 2 == 1) {
                continue;
            }
            let (x, y) = (x1 + (x2 - x1) * t, y1 + (y2 - y1) * t);
            self.rect(x - half, y - half, x + half, y + half, c, 1.0);
        }
    }
}

const GREY: [u8; 3] = [128, 128, 128];

/// The persistence diagram as a `size`-pixel square picture: the diagonal, the dashed line
/// of essential classes, a disc per pair coloured by dimension (the colours of the SVG, no
/// text).
pub fn diagram_raster(d: &Diagram, size: u32) -> Raster {
    let l = DiagramLayout::new(d, size);
    let mut r = Raster::new(size, size);
    r.segment(l.x(l.lo), l.y(l.lo), l.x(l.hi), l.y(l.hi), 1.0, GREY, None);
    r.segment(l.margin, l.ess, l.size - l.margin, l.ess, 1.0, GREY, Some(4.0));
    for p in &d.pairs {
        r.disc(l.x(p.birth), l.y(p.death), 3.0, rgb(p.dim), 1.0);
    }
    r
}

/// The barcode as a picture `width` pixels wide: one bar per pair, grouped by dimension.
pub fn barcode_raster(d: &Diagram, width: u32) -> Raster {
    let l = BarLayout::new(d, width);
    let mut r = Raster::new(width, l.height.ceil() as u32);
    for (i, p) in d.pairs.iter().enumerate() {
        let (a, b) = (l.x(p.birth.min(p.death)), l.x(p.birth.max(p.death)));
        let y = l.y(i);
        r.rect(a, y - 1.5, b.max(a + 1.0), y + 1.5, rgb(p.dim), 1.0);
    }
    r
}

/// The 2-D image in grey at `scale` pixels per value with `chain` drawn over it in red, as
/// [`image_with_chain_svg`] draws it.
pub fn image_with_chain_raster(
    rows: usize,
    cols: usize,
    values: &[f64],
    chain: &Chain,
    vertex_centred: bool,
    scale: u32,
) -> Raster {
    let sc = scale as f64;
    let grey = greys(values);
    let mut r = Raster::new(cols as u32 * scale, rows as u32 * scale);
    for i in 0..rows {
        for j in 0..cols {
            let g = grey[i * cols + j];
            r.rect(j as f64 * sc, i as f64 * sc, (j + 1) as f64 * sc, (i + 1) as f64 * sc, [g, g, g], 1.0);
        }
    }
    const RED: [u8; 3] = [255, 0, 0];
    for mark in chain_marks(chain, vertex_centred, sc) {
        match mark {
            Mark::Dot { x, y, r: rad } => r.disc(x, y, rad.max(1.0), RED, 1.0),
            Mark::Square { x, y, side } => r.rect(x, y, x + side, y + side, RED, 0.4),
            Mark::Segment { x1, y1, x2, y2, width } => r.segment(x1, y1, x2, y2, width.max(1.0), RED, None),
        }
    }
    r
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
    fn rasters_have_their_size_and_marks_where_the_points_are() {
        let d = ring();
        let r = diagram_raster(&d, 200);
        assert_eq!((r.width, r.height, r.rgb.len()), (200, 200, 3 * 200 * 200));
        let l = DiagramLayout::new(&d, 200);
        for p in &d.pairs {
            let (x, y) = (l.x(p.birth) as u32, l.y(p.death) as u32);
            let c = r.pixel(x, y);
            assert_eq!(c, rgb(p.dim), "pair {p:?} at ({x}, {y})");
        }
        // far from the marks the picture is white
        assert_eq!(r.pixel(199, 199), [255, 255, 255]);
        let b = barcode_raster(&d, 300);
        let bl = BarLayout::new(&d, 300);
        assert_eq!((b.width, b.height), (300, bl.height.ceil() as u32));
        for (i, p) in d.pairs.iter().enumerate() {
            let x = ((bl.x(p.birth.min(p.death)) + bl.x(p.birth.max(p.death))) / 2.0) as u32;
            assert_ne!(b.pixel(x, bl.y(i) as u32), [255, 255, 255], "bar {i}");
        }
        let k = d.pairs.iter().position(|p| p.dim == 1).unwrap();
        let values = [1.0, 1.0, 1.0, 1.0, 5.0, 1.0, 1.0, 1.0, 0.0];
        let img = image_with_chain_raster(3, 3, &values, &d.cycles[k], false, 10);
        assert_eq!((img.width, img.height), (30, 30));
        // the loop runs around the middle pixel: red on its border, white-ish grey inside
        assert_eq!(img.pixel(15, 10), [255, 0, 0]);
        assert_eq!(img.pixel(15, 15), [255, 255, 255]);
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
