//! The classic objects of `gmap demo`, one table row each: dimension, darts, cells, Euler
//! characteristic, orientability, integer homology, and whether the cellular and simplicial
//! methods agree.
//!
//! The objects come from [`gmap_ops::build::demo_objects`]; the table is a list of
//! [`Column`]s, each a header and a function from the map to the text of its cell, so a new
//! column is one entry in [`columns`].

use gmap_core::DenseMap;
use gmap_homology::{cellular_complex, homology_z, simplicial_complex, PreconditionError};

/// One column of the demo table.
pub struct Column {
    /// the header
    pub header: &'static str,
    /// the text of the column for one map
    pub cell: fn(&DenseMap) -> String,
}

/// The columns, in order (the name column comes first and is not listed).
pub fn columns() -> Vec<Column> {
    vec![
        Column { header: "dim", cell: |m| m.dim().to_string() },
        Column { header: "darts", cell: |m| m.dart_count().to_string() },
        Column {
            header: "cells (0..n)",
            cell: |m| m.cell_counts().iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" "),
        },
        Column { header: "chi", cell: |m| m.euler_characteristic().to_string() },
        Column { header: "orientable", cell: |m| if m.is_orientable() { "yes" } else { "no" }.to_string() },
        Column { header: "homology", cell: demo_homology },
        Column { header: "cellular = simplicial", cell: demo_agreement },
    ]
}

/// Integer homology written as `(Z, Z + Z/2, 0)`, by the cellular method where C1 and C2
/// hold, else by the simplicial one (marked `*`).
pub fn demo_homology(m: &DenseMap) -> String {
    let cell = cellular_complex(m).ok().map(|c| homology_z(&c.chain));
    match cell {
        Some(Ok(h)) => h.to_string(),
        Some(Err(e)) => format!("error: {e}"),
        None => match homology_z(&simplicial_complex(m)) {
            Ok(h) => format!("{h}*"),
            Err(e) => format!("error: {e}"),
        },
    }
}

/// `yes`, `NO`, or `n/a` with the condition that keeps the cellular method from applying.
pub fn demo_agreement(m: &DenseMap) -> String {
    let s = homology_z(&simplicial_complex(m));
    match cellular_complex(m) {
        Err(PreconditionError::C1(_)) => "n/a (C1)".to_string(),
        Err(PreconditionError::C2 { .. }) => "n/a (C2)".to_string(),
        Err(PreconditionError::SelfBending(_)) => "n/a (self-bending)".to_string(),
        Err(e) => format!("n/a ({e})"),
        Ok(c) => match (homology_z(&c.chain), s) {
            (Ok(a), Ok(b)) if a == b => "yes".to_string(),
            _ => "NO".to_string(),
        },
    }
}

/// Formats rows of text as a table: columns left-aligned to their widest entry, two spaces
/// apart, a dashed rule under the header.
pub fn format_table(header: &[String], rows: &[Vec<String>]) -> String {
    let mut width: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for r in rows {
        for (w, c) in width.iter_mut().zip(r) {
            *w = (*w).max(c.chars().count());
        }
    }
    let line = |cells: &[String]| {
        let parts: Vec<String> = cells.iter().zip(&width).map(|(c, &w)| format!("{c:<w$}")).collect();
        parts.join("  ").trim_end().to_string()
    };
    let mut out = line(header);
    out.push('\n');
    let rule: Vec<String> = width.iter().map(|&w| "-".repeat(w)).collect();
    out.push_str(&rule.join("  "));
    out.push('\n');
    for r in rows {
        out.push_str(&line(r));
        out.push('\n');
    }
    out
}

/// The demo table: the classic objects, one row each.
pub fn demo_table() -> String {
    let cols = columns();
    let mut header = vec!["object".to_string()];
    header.extend(cols.iter().map(|c| c.header.to_string()));
    let rows: Vec<Vec<String>> = gmap_ops::build::demo_objects()
        .into_iter()
        .map(|(name, m)| {
            let mut row = vec![name];
            row.extend(cols.iter().map(|c| (c.cell)(&m)));
            row
        })
        .collect();
    format_table(&header, &rows)
}
