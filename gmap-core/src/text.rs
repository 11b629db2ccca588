//! Quoting user input in error messages. A leaf: it imports nothing of the crate.

/// Shortens a token for an error message: at most `max` whole characters (invalid UTF-8
/// replaced), then `…`. Every reader of the workspace quotes offending input through it, so a
/// 100 MB token is never echoed whole (the readers use at most 80 characters).
pub fn shorten(bytes: &[u8], max: usize) -> String {
    let s = String::from_utf8_lossy(bytes);
    if s.chars().count() <= max {
        s.into_owned()
    } else {
        let mut t: String = s.chars().take(max).collect();
        t.push('…');
        t
    }
}
