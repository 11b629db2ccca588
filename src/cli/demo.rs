//! `gmap demo`: the classic objects, one table row each.
//!
//! The objects come from [`gmap_ops::build::demo_objects`]; the table is a list of
//! [`Column`]s, each a header and a function from the map to the text of its cell, so a new
//! column is one entry in [`columns`].

use anyhow::Result;
use gmap_core::DenseMap;

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
        Column { header: "homology", cell: super::homology::demo_homology },
        Column { header: "cellular = simplicial", cell: super::homology::demo_agreement },
    ]
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

/// Runs `gmap demo`: builds the objects and prints the table on stdout.
pub fn run() -> Result<()> {
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
    out!("{}", format_table(&header, &rows))?;
    Ok(())
}
