//! Words in the fundamental group of a surface, as [`crate::curves::homotopy`] reads a
//! path: letters `±(g + 1)` for generator `g` and its inverse.
//!
//! * free groups (surfaces with boundary): free reduction, cyclic reduction, and cyclic
//!   words compared up to rotation (Knuth–Morris–Pratt on the doubled word);
//! * the surface group of a one-vertex one-face polygon of `4g` sides, `g ≥ 2`: Dehn's
//!   algorithm. Two sides of the polygon that follow each other meet at a corner of the
//!   single vertex, and two different corners with the same two half-edges would make the
//!   vertex of degree 2; so two letters that follow each other occur at one place only of
//!   the relator and its inverse (the pieces have one letter), the presentation is
//!   `C'(1/7)`, and a freely reduced word equal to 1 holds more than half of the relator
//!   (Greendlinger's lemma, Lyndon–Schupp V.4.5), which Dehn's algorithm replaces by the
//!   shorter rest until none is left.

use std::collections::HashMap;

/// A letter: `g + 1` for generator `g`, `-(g + 1)` for its inverse.
pub type Letter = i32;

/// Appends `w` to the freely reduced word `stack`, reducing.
pub fn push_reduced(stack: &mut Vec<Letter>, w: impl IntoIterator<Item = Letter>) {
    for x in w {
        if stack.last() == Some(&-x) {
            stack.pop();
        } else {
            stack.push(x);
        }
    }
}

/// The inverse word.
pub fn inverse(w: &[Letter]) -> Vec<Letter> {
    w.iter().rev().map(|&x| -x).collect()
}

/// The cyclic reduction of a freely reduced word: the middle left once its first and last
/// letters stop cancelling (a conjugate).
pub fn cyclically_reduced(w: &[Letter]) -> &[Letter] {
    let (mut i, mut j) = (0, w.len());
    while j >= i + 2 && w[i] == -w[j - 1] {
        i += 1;
        j -= 1;
    }
    &w[i..j]
}

/// Whether `b` is a rotation of `a` (same length and a substring of `a a`). O(|a|).
pub fn is_rotation(a: &[Letter], b: &[Letter]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    if a.is_empty() {
        return true;
    }
    // failure function of b
    let mut fail = vec![0usize; b.len()];
    let mut k = 0;
    for i in 1..b.len() {
        while k > 0 && b[i] != b[k] {
            k = fail[k - 1];
        }
        if b[i] == b[k] {
            k += 1;
        }
        fail[i] = k;
    }
    let mut k = 0;
    for i in 0..2 * a.len() - 1 {
        let x = a[i % a.len()];
        while k > 0 && x != b[k] {
            k = fail[k - 1];
        }
        if x == b[k] {
            k += 1;
            if k == b.len() {
                return true;
            }
        }
    }
    false
}

/// The exponent sum of each of `n` generators in `w` (its class in the abelianisation).
pub fn exponent_sums(w: &[Letter], n: usize) -> Vec<i64> {
    let mut s = vec![0i64; n];
    for &x in w {
        s[x.unsigned_abs() as usize - 1] += i64::from(x.signum());
    }
    s
}

/// Dehn's algorithm for the group of one relator whose pieces have one letter and whose
/// length is at least 8.
#[derive(Clone, Debug)]
pub struct Dehn {
    /// the relator (index 0) and its inverse (index 1)
    words: [Vec<Letter>; 2],
    /// where each pair of letters that follow each other occurs: (word, index of the first)
    pairs: HashMap<(Letter, Letter), (u8, u32)>,
}

impl Dehn {
    /// The solver of `<generators | relator>`. Refuses (`Err` with the reason) a relator
    /// shorter than 8 or whose pieces are longer than one letter.
    pub fn new(relator: Vec<Letter>) -> Result<Self, String> {
        let m = relator.len();
        if m < 8 {
            return Err(format!("a relator of {m} letters: Dehn's algorithm needs at least 8"));
        }
        let inv = inverse(&relator);
        let mut pairs = HashMap::with_capacity(2 * m);
        for (k, w) in [&relator, &inv].into_iter().enumerate() {
            for i in 0..m {
                let p = (w[i], w[(i + 1) % m]);
                if p.0 == -p.1 {
                    return Err(format!("the relator is not cyclically reduced at letter {i}"));
                }
                if pairs.insert(p, (k as u8, i as u32)).is_some() {
                    return Err(format!("letters {} {} occur twice in the relator and its inverse", p.0, p.1));
                }
            }
        }
        Ok(Dehn { words: [relator, inv], pairs })
    }

    /// The relator's length.
    pub fn relator_len(&self) -> usize {
        self.words[0].len()
    }

    /// `w` reduced: freely, and with no subword longer than half the relator (Dehn's
    /// algorithm, letter by letter on a stack: a new long subword can only end at the top).
    /// Empty exactly when `w` is 1 in the group. O(|w| m²) for a relator of m letters.
    pub fn reduce(&self, w: &[Letter]) -> Vec<Letter> {
        let m = self.relator_len();
        let mut stack: Vec<Letter> = Vec::with_capacity(w.len());
        // letters still to push, the next last
        let mut todo: Vec<Letter> = w.iter().rev().copied().collect();
        while let Some(x) = todo.pop() {
            if stack.last() == Some(&-x) {
                stack.pop();
                continue;
            }
            stack.push(x);
            let n = stack.len();
            if n < 2 {
                continue;
            }
            let Some(&(k, i)) = self.pairs.get(&(stack[n - 2], stack[n - 1])) else { continue };
            let rel = &self.words[k as usize];
            // the longest run ending at the top that follows the relator backwards from
            // i + 1
            let i = i as usize;
            let mut len = 2;
            while len < m && len < n && stack[n - 1 - len] == rel[(i + m + 1 - len) % m] {
                len += 1;
            }
            if 2 * len > m {
                // the run u is rel[s..s+len]; rel = u v cyclically, so u = v⁻¹
                let s = (i + m + 1 - (len - 1)) % m;
                stack.truncate(n - len);
                // push v⁻¹ = inverse of rel[s+len..s+m]: its letters in order are
                // -rel[s+m-1], -rel[s+m-2], …; todo pops the last first
                for t in 0..(m - len) {
                    todo.push(-rel[(s + len + t) % m]);
                }
            }
        }
        stack
    }

    /// A cyclically Dehn-reduced conjugate of `w`: reduced, cyclically freely reduced, and
    /// with no cyclic subword longer than half the relator. Each replacement shortens the
    /// word by 2 or more and costs a scan of the cyclic word: O(|w|² m) at worst.
    pub fn cyclic_reduce(&self, w: &[Letter]) -> Vec<Letter> {
        let m = self.relator_len();
        let mut cur = cyclically_reduced(&self.reduce(w)).to_vec();
        'replace: loop {
            let l = cur.len();
            if 2 * l <= m {
                return cur;
            }
            for p in 0..l {
                let Some(&(k, i)) = self.pairs.get(&(cur[p], cur[(p + 1) % l])) else { continue };
                let rel = &self.words[k as usize];
                let i = i as usize;
                let mut len = 2;
                while len < m && len < l && cur[(p + len) % l] == rel[(i + len) % m] {
                    len += 1;
                }
                if 2 * len > m {
                    // rotate the run u = rel[i..i+len] to the front and put v⁻¹ there
                    // (rel = u v)
                    let mut next: Vec<Letter> = (0..m - len).map(|t| -rel[(i + m - 1 - t) % m]).collect();
                    next.extend((len..l).map(|t| cur[(p + t) % l]));
                    cur = cyclically_reduced(&self.reduce(&next)).to_vec();
                    continue 'replace;
                }
            }
            return cur;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// a b a⁻¹ b⁻¹ c d c⁻¹ d⁻¹, the genus-2 relator
    fn genus2() -> Dehn {
        Dehn::new(vec![1, 2, -1, -2, 3, 4, -3, -4]).unwrap()
    }

    #[test]
    fn dehn_reduces_relators_and_their_conjugates() {
        let d = genus2();
        assert!(d.reduce(&[1, 2, -1, -2, 3, 4, -3, -4]).is_empty());
        // a conjugate of the relator's inverse
        assert!(d.reduce(&[2, 4, 3, -4, -3, 2, 1, -2, -1, -2]).is_empty());
        // five letters of the relator become the other three, inverted
        assert_eq!(d.reduce(&[1, 2, -1, -2, 3]), vec![4, 3, -4]);
        assert_eq!(d.reduce(&[1, 2]), vec![1, 2]);
        assert_eq!(d.reduce(&[1, -1, 2, -2]), Vec::<Letter>::new());
    }

    #[test]
    fn dehn_refuses_long_pieces() {
        // the torus relator is too short; x y … y⁻¹ x⁻¹ has a piece of two letters
        assert!(Dehn::new(vec![1, 2, -1, -2]).is_err());
        assert!(Dehn::new(vec![1, 2, 3, 4, -2, -1, -3, -4]).is_err());
    }

    #[test]
    fn rotations_and_reductions() {
        assert!(is_rotation(&[1, 2, 3], &[3, 1, 2]));
        assert!(!is_rotation(&[1, 2, 3], &[3, 2, 1]));
        assert!(!is_rotation(&[1, 2], &[1, 2, 3]));
        assert_eq!(cyclically_reduced(&[2, 1, 3, -2]), &[1, 3]);
        let mut s = vec![1, 2];
        push_reduced(&mut s, [-2, -1, 3]);
        assert_eq!(s, vec![3]);
        assert_eq!(exponent_sums(&[1, 2, -1, 1], 2), vec![1, 1]);
        let d = genus2();
        // seven letters of the relator are the inverse of the eighth
        assert_eq!(d.cyclic_reduce(&[1, 2, -1, -2, 3, 4, -3]), vec![4]);
        // six letters of the relator, consecutive only cyclically (from -2 round to 1),
        // are the inverse of the other two, 2 -1
        assert_eq!(d.cyclic_reduce(&[-2, 3, 4, -3, -4, 1]), vec![1, -2]);
        assert!(d.cyclic_reduce(&[4, -3, -4, 1, 2, -1, -2, 3]).is_empty());
    }
}
