//! Surfaces from polygonal schemas.

use std::collections::HashMap;

use gmap_core::{Dart, DenseMap};

use super::error::{checked_darts, BuildError};

/// The surface of a polygonal schema: each word is a polygon whose edges are read in order,
/// a letter names an edge and its direction (`a`), its inverse is written `A` (upper case),
/// `a'` or `a^-1`. Words are separated by commas; letters by white space, or, in a word
/// without white space, each character is a letter (`abAB`). A letter used twice glues the
/// two edges (`alpha_2`, matching the starts of the two arrows); a letter used once is
/// boundary (2-free). Examples: `a A` sphere, `a b A B` torus, `a b a B` Klein bottle,
/// `a a` projective plane, `a b A c` cylinder, `a b a c` Möbius band; see
/// [`orientable_surface_word`] and [`nonorientable_surface_word`] for the genus-g ones.
///
/// Darts: letter `j` of a word gives darts `2j` (at its first corner) and `2j + 1` (at the
/// next corner), numbered word after word. Precondition: every word non-empty, every
/// letter at most twice. O(letters).
pub fn schema(word: &str) -> Result<DenseMap, BuildError> {
    let mut faces: Vec<Vec<(String, bool)>> = Vec::new();
    for w in word.split(',') {
        let toks: Vec<String> = if w.trim().chars().any(char::is_whitespace) {
            w.split_whitespace().map(str::to_string).collect()
        } else {
            w.trim().chars().map(|c| c.to_string()).collect()
        };
        if toks.is_empty() {
            return Err(BuildError::BadArgument(format!("empty word in schema '{word}'")));
        }
        faces.push(toks.iter().map(|t| letter(t)).collect::<Result<_, _>>()?);
    }
    let total: usize = faces.iter().map(Vec::len).sum();
    let darts = checked_darts(|| format!("the schema '{word}'"), 2, &[2, total as u64])?;
    let mut m = DenseMap::new(2, darts);
    let mut uses: HashMap<&str, Vec<(usize, bool)>> = HashMap::new();
    let mut order: Vec<&str> = Vec::new();
    let mut offset = 0usize;
    for f in &faces {
        let k = f.len();
        for (j, (name, inverse)) in f.iter().enumerate() {
            let a = offset + 2 * j;
            m.link(Dart::new(a as u32), Dart::new(a as u32 + 1), 0);
            m.link(Dart::new(a as u32 + 1), Dart::new((offset + (2 * j + 2) % (2 * k)) as u32), 1);
            let e = uses.entry(name.as_str()).or_default();
            if e.is_empty() {
                order.push(name.as_str());
            }
            e.push((a, *inverse));
        }
        offset += 2 * k;
    }
    for name in order {
        let occ = &uses[name];
        match occ.len() {
            1 => {}
            2 => {
                // the dart at the start of the arrow, then the one at its end
                let ends = |(a, inv): (usize, bool)| if inv { (a + 1, a) } else { (a, a + 1) };
                let (s1, e1) = ends(occ[0]);
                let (s2, e2) = ends(occ[1]);
                m.link(Dart::new(s1 as u32), Dart::new(s2 as u32), 2);
                m.link(Dart::new(e1 as u32), Dart::new(e2 as u32), 2);
            }
            count => return Err(BuildError::LetterUsedTooOften { letter: name.to_string(), count }),
        }
    }
    Ok(m)
}

/// A schema token → (letter name in lower case, inverse?).
fn letter(tok: &str) -> Result<(String, bool), BuildError> {
    let (body, inv_suffix) = if let Some(b) = tok.strip_suffix("^-1") {
        (b, true)
    } else if let Some(b) = tok.strip_suffix('\'') {
        (b, true)
    } else {
        (tok, false)
    };
    let first = body.chars().next().ok_or_else(|| BuildError::BadToken { token: tok.to_string() })?;
    if !first.is_alphabetic() || !body.chars().all(|c| c.is_alphanumeric() || c == '_') {
        return Err(BuildError::BadToken { token: tok.to_string() });
    }
    let upper = first.is_uppercase();
    if upper && inv_suffix {
        return Err(BuildError::BadToken { token: tok.to_string() });
    }
    Ok((body.to_lowercase(), upper || inv_suffix))
}

/// The word of the closed orientable surface of genus g: `a1 b1 A1 B1 a2 b2 A2 B2 …`,
/// and `a A` (the sphere) for g = 0.
pub fn orientable_surface_word(g: usize) -> String {
    if g == 0 {
        return "a A".to_string();
    }
    (1..=g).map(|i| format!("a{i} b{i} A{i} B{i}")).collect::<Vec<_>>().join(" ")
}

/// The word of the connected sum of k ≥ 1 projective planes: `a1 a1 a2 a2 …`
/// (k = 1 the projective plane, k = 2 the Klein bottle). Returns `a A` for k = 0.
pub fn nonorientable_surface_word(k: usize) -> String {
    if k == 0 {
        return "a A".to_string();
    }
    (1..=k).map(|i| format!("a{i} a{i}")).collect::<Vec<_>>().join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `closed`: no 2-free dart (the boundary, where there is one, is 2-free only).
    fn check(word: &str, cells: &[usize], chi: i64, orientable: bool, closed: bool) {
        let m = schema(word).unwrap();
        m.validate().unwrap();
        assert_eq!(m.cell_counts(), cells, "{word}");
        assert_eq!(m.euler_characteristic(), chi, "{word}");
        assert_eq!(m.is_orientable(), orientable, "{word}");
        assert!(m.has_complete_boundaries(), "{word}");
        assert_eq!(m.darts().all(|d| !m.is_free(d, 2)), closed, "{word}");
        m.check_cells_orientable().unwrap();
    }

    #[test]
    fn classic_surfaces() {
        check("a A", &[2, 1, 1], 2, true, true);
        check("a b A B", &[1, 2, 1], 0, true, true);
        check("abAB", &[1, 2, 1], 0, true, true);
        check("a b a B", &[1, 2, 1], 0, false, true);
        check("a a", &[1, 1, 1], 1, false, true);
        check("a b A c", &[2, 3, 1], 0, true, false);
        check("a b a c", &[2, 3, 1], 0, false, false);
        check("a b a^-1 c'", &[2, 3, 1], 0, true, false);
        check(&orientable_surface_word(2), &[1, 4, 1], -2, true, true);
        check(&orientable_surface_word(3), &[1, 6, 1], -4, true, true);
        check(&nonorientable_surface_word(3), &[1, 3, 1], -1, false, true);
        // two triangles glued along their boundary: a sphere
        check("a b c, C B A", &[3, 3, 2], 2, true, true);
        check("a b c", &[3, 3, 1], 1, true, false);
    }

    #[test]
    fn schema_errors() {
        assert_eq!(schema("a a a"), Err(BuildError::LetterUsedTooOften { letter: "a".into(), count: 3 }));
        assert_eq!(schema("a 1"), Err(BuildError::BadToken { token: "1".into() }));
        assert!(matches!(schema("a A,"), Err(BuildError::BadArgument(_))));
        assert_eq!(schema("A'  b"), Err(BuildError::BadToken { token: "A'".into() }));
    }
}
