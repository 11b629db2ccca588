//! Text labels as written by [`crate::export`]'s mesh writers, for readers without text
//! arrays (meshio's): a cell-data integer column `name` of ranks (`-1`: no label) and a
//! field-data table `gmap:texts:name` of bytes, each text followed by a NUL byte. The
//! readers of `.vtk` and `.vtu` give their field data here, which turns each such column
//! back into texts.

use gmap_core::LabelValue;

use super::cells::DataArray;

/// The prefix of the name of a text table.
pub(crate) const TABLE_PREFIX: &str = "gmap:texts:";

/// The texts of a table's bytes, `None` when they are not UTF-8 texts each ended by NUL.
fn texts_of(table: &DataArray) -> Option<Vec<String>> {
    let bytes: Vec<u8> = table
        .values
        .iter()
        .map(|v| match v {
            Some(LabelValue::Int(b)) => u8::try_from(*b).ok(),
            _ => None,
        })
        .collect::<Option<_>>()?;
    if bytes.last() != Some(&0) {
        return None;
    }
    bytes[..bytes.len() - 1].split(|&b| b == 0).map(|t| String::from_utf8(t.to_vec()).ok()).collect()
}

/// Turns each column of `cell_data` that has a table in `field_data` into its texts.
/// Other field data are left alone. Errors: a table that is not texts, a rank outside it.
pub(crate) fn apply_text_tables(cell_data: &mut [DataArray], field_data: &[DataArray]) -> Result<(), String> {
    for table in field_data {
        let Some(name) = table.name.strip_prefix(TABLE_PREFIX) else { continue };
        let Some(column) = cell_data.iter_mut().find(|c| c.name == name) else { continue };
        let texts = texts_of(table).ok_or_else(|| format!("field data '{}' is not a table of texts", table.name))?;
        for (k, v) in column.values.iter_mut().enumerate() {
            *v = match v.take() {
                Some(LabelValue::Int(-1)) | None => None,
                Some(LabelValue::Int(r)) if r >= 0 && (r as usize) < texts.len() => {
                    Some(LabelValue::Text(texts[r as usize].clone()))
                }
                Some(other) => {
                    return Err(format!(
                        "cell {k}: '{name}' has the value {other:?}, not a rank in its {} texts",
                        texts.len()
                    ))
                }
            };
        }
    }
    Ok(())
}
