//! A pass over a JSON text that refuses an object with the same key twice.
//!
//! JSON (RFC 8259 §4) leaves the meaning of a repeated key to the reader, and the usual
//! readers keep the last value silently: `{"id": 0, "dim": 0, "dim": 1}` would be a 1-cell
//! to one tool and a 0-cell to another. The `.json` reader refuses such a text instead,
//! whatever the object and whether or not the key is one it knows.
//!
//! One pass, O(length of the text): an object of `k` keys costs O(k²) comparisons up to
//! 16 keys and O(k) hashing beyond.

use std::cell::RefCell;
use std::collections::HashSet;
use std::fmt;

use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};

/// A key found twice in one object, and where (just after its second occurrence).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Duplicate {
    /// the key, at most 80 characters of it
    pub key: String,
    /// 1-based line
    pub line: usize,
    /// 1-based column
    pub column: usize,
}

/// The first key repeated in an object of `text`, if any. A text that is not JSON has
/// none here (the reader reports its syntax error).
pub(crate) fn find_duplicate(text: &str) -> Option<Duplicate> {
    let found = RefCell::new(None);
    let mut de = serde_json::Deserializer::from_str(text);
    // serde_json's depth limit (128) bounds the recursion of `Any`
    let e = Any { found: &found }.deserialize(&mut de).err()?;
    let key = found.into_inner()?;
    Some(Duplicate { key, line: e.line(), column: e.column() })
}

/// Any JSON value, visited for its objects' keys; the first repeated key goes to `found`.
#[derive(Clone, Copy)]
struct Any<'a> {
    found: &'a RefCell<Option<String>>,
}

impl<'de> DeserializeSeed<'de> for Any<'_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Any<'_> {
    type Value = ();

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("any JSON value")
    }

    fn visit_bool<E>(self, _: bool) -> Result<(), E> {
        Ok(())
    }
    fn visit_i64<E>(self, _: i64) -> Result<(), E> {
        Ok(())
    }
    fn visit_u64<E>(self, _: u64) -> Result<(), E> {
        Ok(())
    }
    fn visit_f64<E>(self, _: f64) -> Result<(), E> {
        Ok(())
    }
    fn visit_str<E>(self, _: &str) -> Result<(), E> {
        Ok(())
    }
    fn visit_unit<E>(self) -> Result<(), E> {
        Ok(())
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        while seq.next_element_seed(self)?.is_some() {}
        Ok(())
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        // a linear scan while the object is small (the usual 2 or 3 keys), a hash set beyond
        let mut few: Vec<String> = Vec::new();
        let mut many: HashSet<String> = HashSet::new();
        while let Some(key) = map.next_key::<String>()? {
            let seen = if many.is_empty() && few.len() < 16 {
                let seen = few.contains(&key);
                few.push(key.clone());
                seen
            } else {
                many.extend(few.drain(..));
                !many.insert(key.clone())
            };
            if seen {
                *self.found.borrow_mut() = Some(gmap_core::io::shorten(key.as_bytes(), 80));
                return Err(de::Error::custom("duplicate key"));
            }
            map.next_value_seed(self)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn repeated_keys_are_found_anywhere() {
        assert_eq!(find_duplicate(r#"{"a": 1, "b": [{"c": 2}, {"c": 3}], "n": 123456789012345678901234567890}"#), None);
        let d = find_duplicate(r#"{"id":0,"dim":0,"dim":1}"#).unwrap();
        assert_eq!((d.key.as_str(), d.line), ("dim", 1));
        let d = find_duplicate("{\"regions\": [],\n \"regions\": []}").unwrap();
        assert_eq!((d.key.as_str(), d.line), ("regions", 2));
        let keys: Vec<String> = (0..40).map(|i| format!("\"k{i}\": {i}")).collect();
        assert_eq!(find_duplicate(&format!("{{{}}}", keys.join(","))), None);
        assert_eq!(find_duplicate(&format!("{{{}, \"k39\": 0}}", keys.join(","))).unwrap().key, "k39");
        assert_eq!(find_duplicate("[1, 2"), None);
        let long = "x".repeat(1000);
        assert_eq!(find_duplicate(&format!("{{\"{long}\": 1, \"{long}\": 2}}")).unwrap().key.chars().count(), 81);
    }
}
