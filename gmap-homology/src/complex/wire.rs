//! The bytes a block of a cut box is sent as between processes: LEB128 varints (signed
//! values zigzagged), and runs of equal values for the per-cube label arrays. A reader of
//! such bytes never panics: a short or malformed message is an error naming what was
//! being read.

use super::cubical::CubicalError;

/// Appends values to a message.
#[derive(Default)]
pub(crate) struct Writer {
    pub(crate) bytes: Vec<u8>,
}

impl Writer {
    pub(crate) fn u64(&mut self, mut v: u64) {
        loop {
            let b = (v & 0x7f) as u8;
            v >>= 7;
            if v == 0 {
                self.bytes.push(b);
                return;
            }
            self.bytes.push(b | 0x80);
        }
    }

    pub(crate) fn i64(&mut self, v: i64) {
        self.u64(((v << 1) ^ (v >> 63)) as u64);
    }

    /// `v` as runs `(value, length)`, preceded by its length.
    pub(crate) fn runs(&mut self, v: &[u32]) {
        self.u64(v.len() as u64);
        let mut i = 0;
        while i < v.len() {
            let j = i + v[i..].iter().position(|&x| x != v[i]).unwrap_or(v.len() - i);
            self.u64(v[i] as u64);
            self.u64((j - i) as u64);
            i = j;
        }
    }
}

/// Reads values back from a message.
pub(crate) struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
    /// what the message holds, for the errors
    what: &'static str,
}

impl<'a> Reader<'a> {
    pub(crate) fn new(bytes: &'a [u8], what: &'static str) -> Self {
        Reader { bytes, at: 0, what }
    }

    pub(crate) fn error(&self, why: &str) -> CubicalError {
        CubicalError::BadMessage(format!("{} at byte {}: {why}", self.what, self.at))
    }

    pub(crate) fn u64(&mut self) -> Result<u64, CubicalError> {
        let mut v = 0u64;
        for shift in (0..64).step_by(7) {
            let Some(&b) = self.bytes.get(self.at) else {
                return Err(self.error("the message ends inside a number"));
            };
            self.at += 1;
            v |= ((b & 0x7f) as u64) << shift;
            if b & 0x80 == 0 {
                return Ok(v);
            }
        }
        Err(self.error("a number of more than 64 bits"))
    }

    pub(crate) fn i64(&mut self) -> Result<i64, CubicalError> {
        let z = self.u64()?;
        Ok((z >> 1) as i64 ^ -((z & 1) as i64))
    }

    /// A number that indexes memory: at most `limit`.
    pub(crate) fn usize(&mut self, limit: usize) -> Result<usize, CubicalError> {
        let v = self.u64()?;
        usize::try_from(v).ok().filter(|&v| v <= limit).ok_or_else(|| self.error(&format!("{v} is over {limit}")))
    }

    pub(crate) fn u32(&mut self) -> Result<u32, CubicalError> {
        let v = self.u64()?;
        u32::try_from(v).map_err(|_| self.error(&format!("{v} is not a 32-bit number")))
    }

    /// What [`Writer::runs`] wrote; at most `limit` values.
    pub(crate) fn runs(&mut self, limit: usize) -> Result<Vec<u32>, CubicalError> {
        let n = self.usize(limit)?;
        let mut v = Vec::with_capacity(n);
        while v.len() < n {
            let x = self.u32()?;
            let len = self.usize(n - v.len())?;
            if len == 0 {
                return Err(self.error("an empty run"));
            }
            v.resize(v.len() + len, x);
        }
        Ok(v)
    }

    /// Fails unless every byte was read.
    pub(crate) fn finish(&self) -> Result<(), CubicalError> {
        if self.at != self.bytes.len() {
            return Err(self.error(&format!("{} bytes left over", self.bytes.len() - self.at)));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_runs_round_trip() {
        let mut w = Writer::default();
        for v in [0u64, 1, 127, 128, 300, u64::MAX] {
            w.u64(v);
        }
        for v in [0i64, -1, 1, -64, 64, i64::MIN, i64::MAX] {
            w.i64(v);
        }
        w.runs(&[7, 7, 7, u32::MAX, 0, 0, 7]);
        w.runs(&[]);
        let mut r = Reader::new(&w.bytes, "a test");
        for v in [0u64, 1, 127, 128, 300, u64::MAX] {
            assert_eq!(r.u64().unwrap(), v);
        }
        for v in [0i64, -1, 1, -64, 64, i64::MIN, i64::MAX] {
            assert_eq!(r.i64().unwrap(), v);
        }
        assert_eq!(r.runs(10).unwrap(), vec![7, 7, 7, u32::MAX, 0, 0, 7]);
        assert_eq!(r.runs(10).unwrap(), Vec::<u32>::new());
        r.finish().unwrap();
        // cut anywhere: an error, never a panic
        let read_all = |bytes: &[u8]| -> Result<(), CubicalError> {
            let mut r = Reader::new(bytes, "a test");
            for _ in 0..6 {
                r.u64()?;
            }
            for _ in 0..7 {
                r.i64()?;
            }
            r.runs(10)?;
            r.runs(10)?;
            r.finish()
        };
        assert!(read_all(&w.bytes).is_ok());
        for end in 0..w.bytes.len() {
            assert!(read_all(&w.bytes[..end]).is_err(), "cut at {end}");
        }
        assert!(Reader::new(&[0xff; 11], "a test").u64().is_err());
    }
}
