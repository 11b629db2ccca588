//! Binary grey-value images: numpy's `.npy` and DIPHA's image files (`.complex`), read
//! through a memory map into an [`Image`]; a grey level makes an image a [`CubicalSet`]
//! (docs/FORMATS.md).
//!
//! An image of dimension d is an array of `shape[0] × … × shape[d-1]` values; its element
//! `a[i_0, …, i_{d-1}]` stands for the closed unit cube with minimal vertex `(i_0, …,
//! i_{d-1})`. A [`Level`] decides which cubes belong to the set: by default the non-zero
//! values (`true` of a boolean image), with [`Level::AtMost`] the values `≤ T` (the
//! sublevel set of the T-construction, as CubicalRipser and DIPHA read images; NaN never).
//!
//! The file is mapped, not copied: reading a 1 GB image costs its header and a map, and the
//! values are converted where they are used ([`Image::value`], [`Image::presence`]).
//!
//! * `.npy` (format versions 1.0, 2.0 and 3.0): `bool`, `i1`–`i8`, `u1`–`u8`, `f4`, `f8`,
//!   little or big endian, C or Fortran order, dimension 1 to [`MAX_DIM`]. Structured,
//!   object, string and complex arrays are refused.
//! * DIPHA's `IMAGE_DATA` file: the little-endian `i64` words `8067171840` (the magic), `1`
//!   (the file type), the number of values, the dimension d and the d sizes, then the values
//!   as little-endian `f64` with axis 0 fastest.
//!
//! ```
//! use gmap_ops::import::image::{Image, Level, Order};
//! // a 3 × 3 ring of squares, written and read back as .npy
//! let ring = Image::from_values(&[3, 3], Order::C, vec![1u8, 1, 1, 1, 0, 1, 1, 1, 1]).unwrap();
//! let dir = tempfile::tempdir().unwrap();
//! let path = dir.path().join("ring.npy");
//! ring.write_npy(&path).unwrap();
//! let back = Image::read(&path).unwrap();
//! assert_eq!(back.shape(), &[3, 3]);
//! assert_eq!(back.to_cubical_set(Level::Nonzero).unwrap().cube_count(), 8);
//! assert_eq!(back.to_cubical_set(Level::AtMost(0.0)).unwrap().cube_count(), 1);
//! ```

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use std::path::Path;

use super::{CubicalSet, FileError, ImportError};

/// The largest dimension of an image (numpy allows 64; a cubical set of dimension 9 has
/// `3^9` cells around each vertex, beyond any use here).
pub const MAX_DIM: usize = 8;

/// DIPHA's magic number, the first `i64` of its files.
pub const DIPHA_MAGIC: i64 = 8_067_171_840;
/// DIPHA's file type of an image (`IMAGE_DATA`).
pub const DIPHA_IMAGE_DATA: i64 = 1;

const NPY_MAGIC: &[u8] = b"\x93NUMPY";
/// numpy refuses headers longer than this unless told otherwise; so does this reader.
const MAX_HEADER: usize = 1 << 16;

/// The type of an image's values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Dtype {
    /// one byte, 0 or 1 (numpy's `?`)
    Bool,
    /// signed integers of 1, 2, 4, 8 bytes
    I8,
    /// `i2`
    I16,
    /// `i4`
    I32,
    /// `i8`
    I64,
    /// unsigned integers of 1, 2, 4, 8 bytes
    U8,
    /// `u2`
    U16,
    /// `u4`
    U32,
    /// `u8`
    U64,
    /// IEEE single
    F32,
    /// IEEE double
    F64,
}

impl Dtype {
    /// Bytes per value.
    pub fn size(self) -> usize {
        match self {
            Dtype::Bool | Dtype::I8 | Dtype::U8 => 1,
            Dtype::I16 | Dtype::U16 => 2,
            Dtype::I32 | Dtype::U32 | Dtype::F32 => 4,
            Dtype::I64 | Dtype::U64 | Dtype::F64 => 8,
        }
    }

    /// numpy's type code without the byte order (`b1`, `u1`, `f8`, …).
    pub fn code(self) -> &'static str {
        match self {
            Dtype::Bool => "b1",
            Dtype::I8 => "i1",
            Dtype::I16 => "i2",
            Dtype::I32 => "i4",
            Dtype::I64 => "i8",
            Dtype::U8 => "u1",
            Dtype::U16 => "u2",
            Dtype::U32 => "u4",
            Dtype::U64 => "u8",
            Dtype::F32 => "f4",
            Dtype::F64 => "f8",
        }
    }

    fn from_code(kind: u8, size: &str) -> Option<Dtype> {
        Some(match (kind, size) {
            (b'b', "1") | (b'?', "") => Dtype::Bool,
            (b'i', "1") => Dtype::I8,
            (b'i', "2") => Dtype::I16,
            (b'i', "4") => Dtype::I32,
            (b'i', "8") => Dtype::I64,
            (b'u', "1") => Dtype::U8,
            (b'u', "2") => Dtype::U16,
            (b'u', "4") => Dtype::U32,
            (b'u', "8") => Dtype::U64,
            (b'f', "4") => Dtype::F32,
            (b'f', "8") => Dtype::F64,
            _ => return None,
        })
    }

    fn is_integer(self) -> bool {
        !matches!(self, Dtype::F32 | Dtype::F64)
    }
}

/// How an array's values are laid out.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Order {
    /// the last axis fastest (numpy's default)
    C,
    /// the first axis fastest (`fortran_order: True`; DIPHA's layout)
    Fortran,
}

/// Which cubes of an image belong to its cubical set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Level {
    /// the non-zero values (`true` of a boolean image)
    Nonzero,
    /// the values `≤ T` (never NaN): the sublevel set at `T`
    AtMost(f64),
}

/// A value type an image can be made of in memory ([`Image::from_values`]).
pub trait Element: Copy + sealed::Sealed {
    /// its dtype
    const DTYPE: Dtype;
    /// its little-endian bytes
    fn put_le(self, out: &mut Vec<u8>);
}

mod sealed {
    pub trait Sealed {}
}

macro_rules! element {
    ($t:ty, $d:expr) => {
        impl sealed::Sealed for $t {}
        impl Element for $t {
            const DTYPE: Dtype = $d;
            fn put_le(self, out: &mut Vec<u8>) {
                out.extend_from_slice(&self.to_le_bytes());
            }
        }
    };
}
element!(i8, Dtype::I8);
element!(i16, Dtype::I16);
element!(i32, Dtype::I32);
element!(i64, Dtype::I64);
element!(u8, Dtype::U8);
element!(u16, Dtype::U16);
element!(u32, Dtype::U32);
element!(u64, Dtype::U64);
element!(f32, Dtype::F32);
element!(f64, Dtype::F64);
impl sealed::Sealed for bool {}
impl Element for bool {
    const DTYPE: Dtype = Dtype::Bool;
    fn put_le(self, out: &mut Vec<u8>) {
        out.push(self as u8);
    }
}

enum Storage {
    Mapped(memmap2::Mmap),
    Owned(Vec<u8>),
}

/// A d-dimensional array of grey values, mapped from a file or held in memory.
pub struct Image {
    shape: Vec<usize>,
    order: Order,
    dtype: Dtype,
    big_endian: bool,
    storage: Storage,
    /// where the values start in the storage
    offset: usize,
    len: usize,
}

impl std::fmt::Debug for Image {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Image")
            .field("shape", &self.shape)
            .field("order", &self.order)
            .field("dtype", &self.dtype)
            .field("big_endian", &self.big_endian)
            .finish()
    }
}

fn format(m: impl Into<String>) -> ImportError {
    ImportError::Format(m.into())
}

/// The number of values of a shape, checked: `None` past `usize` or past `bytes / size`.
fn checked_len(shape: &[usize], size: usize) -> Option<(usize, usize)> {
    let n = shape.iter().try_fold(1usize, |v, &s| v.checked_mul(s))?;
    Some((n, n.checked_mul(size)?))
}

fn shape_text(shape: &[usize]) -> String {
    shape.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(" × ")
}

impl Image {
    /// An image held in memory: `values` in the given order (`Order::C`: the last axis
    /// fastest). Refuses a dimension outside `1..=MAX_DIM` or a length other than the shape's.
    pub fn from_values<T: Element>(shape: &[usize], order: Order, values: Vec<T>) -> Result<Image, ImportError> {
        check_dim(shape.len())?;
        let Some((n, bytes)) = checked_len(shape, T::DTYPE.size()) else {
            return Err(format(format!("the shape {} overflows", shape_text(shape))));
        };
        if n != values.len() {
            return Err(format(format!("{} values for the shape {}", values.len(), shape_text(shape))));
        }
        let mut data = Vec::with_capacity(bytes);
        for v in values {
            v.put_le(&mut data);
        }
        Ok(Image {
            shape: shape.to_vec(),
            order,
            dtype: T::DTYPE,
            big_endian: false,
            storage: Storage::Owned(data),
            offset: 0,
            len: n,
        })
    }

    /// Reads an image by its content: DIPHA's magic number or numpy's.
    pub fn read(path: &Path) -> Result<Image, FileError> {
        let map = map_file(path)?;
        let bytes = storage_bytes(&map);
        let head = &bytes[..bytes.len().min(8)];
        let (npy, dipha) = (head.starts_with(NPY_MAGIC), head == DIPHA_MAGIC.to_le_bytes());
        let r = if npy {
            parse_npy(map)
        } else if dipha {
            parse_dipha(map)
        } else {
            Err(format(format!(
                "not an image: the file starts with {head:02x?}, neither numpy's magic \\x93NUMPY nor DIPHA's {DIPHA_MAGIC}"
            )))
        };
        r.map_err(|e| FileError::new(path, e))
    }

    /// Reads a `.npy` file.
    pub fn read_npy(path: &Path) -> Result<Image, FileError> {
        parse_npy(map_file(path)?).map_err(|e| FileError::new(path, e))
    }

    /// Reads a DIPHA image file.
    pub fn read_dipha(path: &Path) -> Result<Image, FileError> {
        parse_dipha(map_file(path)?).map_err(|e| FileError::new(path, e))
    }

    /// Parses the bytes of a `.npy` file held in memory.
    pub fn parse_npy(bytes: Vec<u8>) -> Result<Image, ImportError> {
        parse_npy(Storage::Owned(bytes))
    }

    /// Parses the bytes of a DIPHA image file held in memory.
    pub fn parse_dipha(bytes: Vec<u8>) -> Result<Image, ImportError> {
        parse_dipha(Storage::Owned(bytes))
    }

    /// The sizes along the axes, axis 0 first (numpy's `shape`).
    pub fn shape(&self) -> &[usize] {
        &self.shape
    }

    /// The dimension d.
    pub fn dim(&self) -> usize {
        self.shape.len()
    }

    /// The layout of the values.
    pub fn order(&self) -> Order {
        self.order
    }

    /// The type of the values.
    pub fn dtype(&self) -> Dtype {
        self.dtype
    }

    /// Whether the values are stored big-endian.
    pub fn is_big_endian(&self) -> bool {
        self.big_endian
    }

    /// The number of values.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the image has no value (a size 0 along some axis).
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The sizes in the order of the layout, fastest first: the shape of the set that
    /// [`Image::presence`] describes with axis 0 fastest (the image's axes reversed for C
    /// order). Homology does not see the difference.
    pub fn memory_shape(&self) -> Vec<usize> {
        match self.order {
            Order::Fortran => self.shape.clone(),
            Order::C => self.shape.iter().rev().copied().collect(),
        }
    }

    /// The raw bytes of the values, in layout order.
    pub fn raw(&self) -> &[u8] {
        let all: &[u8] = match &self.storage {
            Storage::Mapped(m) => m,
            Storage::Owned(v) => v,
        };
        &all[self.offset..self.offset + self.len * self.dtype.size()]
    }

    /// The i-th value in layout order, as `f64` (exact up to 2^53 for 64-bit integers).
    /// Panics if `i ≥ len()`.
    pub fn value(&self, i: usize) -> f64 {
        let s = self.dtype.size();
        let b = &self.raw()[i * s..(i + 1) * s];
        macro_rules! get {
            ($t:ty) => {{
                let a = b.try_into().unwrap();
                (if self.big_endian { <$t>::from_be_bytes(a) } else { <$t>::from_le_bytes(a) }) as f64
            }};
        }
        match self.dtype {
            Dtype::Bool => (b[0] != 0) as u8 as f64,
            Dtype::I8 => get!(i8),
            Dtype::I16 => get!(i16),
            Dtype::I32 => get!(i32),
            Dtype::I64 => get!(i64),
            Dtype::U8 => get!(u8),
            Dtype::U16 => get!(u16),
            Dtype::U32 => get!(u32),
            Dtype::U64 => get!(u64),
            Dtype::F32 => get!(f32),
            Dtype::F64 => get!(f64),
        }
    }

    /// The value at `index` (axis 0 first), as `f64`. Panics outside the shape.
    pub fn get(&self, index: &[usize]) -> f64 {
        assert_eq!(index.len(), self.dim(), "an index of the image's dimension");
        let mut m = 0usize;
        let axes: Box<dyn Iterator<Item = usize>> = match self.order {
            Order::C => Box::new(0..self.dim()),
            Order::Fortran => Box::new((0..self.dim()).rev()),
        };
        for a in axes {
            assert!(index[a] < self.shape[a], "index out of the shape");
            m = m * self.shape[a] + index[a];
        }
        self.value(m)
    }

    /// Writes into `out` one byte per value (1: the cube is in the set at `level`, else 0)
    /// for the values `start .. start + out.len()` in layout order. O(out.len()), no
    /// allocation: the streaming passes read the image a slab at a time through it.
    /// Panics if the range passes the end.
    pub fn presence(&self, level: Level, start: usize, out: &mut [u8]) {
        let s = self.dtype.size();
        let raw = &self.raw()[start * s..(start + out.len()) * s];
        let be = self.big_endian;
        macro_rules! run {
            ($t:ty, $test:expr) => {{
                let test = $test;
                for (o, c) in out.iter_mut().zip(raw.chunks_exact(s)) {
                    let a = c.try_into().unwrap();
                    let v = if be { <$t>::from_be_bytes(a) } else { <$t>::from_le_bytes(a) };
                    *o = test(v) as u8;
                }
            }};
        }
        match (level, self.dtype) {
            (Level::Nonzero, Dtype::Bool | Dtype::U8 | Dtype::I8) => {
                for (o, &b) in out.iter_mut().zip(raw) {
                    *o = (b != 0) as u8;
                }
            }
            (Level::Nonzero, Dtype::I16 | Dtype::U16) => run!(u16, |v: u16| v != 0),
            (Level::Nonzero, Dtype::I32 | Dtype::U32) => run!(u32, |v: u32| v != 0),
            (Level::Nonzero, Dtype::I64 | Dtype::U64) => run!(u64, |v: u64| v != 0),
            (Level::Nonzero, Dtype::F32) => run!(f32, |v: f32| v != 0.0),
            (Level::Nonzero, Dtype::F64) => run!(f64, |v: f64| v != 0.0),
            (Level::AtMost(t), d) if d.is_integer() => {
                // v ≤ t exactly: v ≤ ⌊t⌋ for integers, clamped to the type's range
                if t.is_nan() {
                    out.fill(0);
                    return;
                }
                let f = t.floor();
                let lim = if f >= 1.8e19 {
                    i128::MAX
                } else if f <= -1.8e19 {
                    i128::MIN
                } else {
                    f as i128
                };
                match d {
                    Dtype::Bool => {
                        for (o, &b) in out.iter_mut().zip(raw) {
                            *o = (((b != 0) as i128) <= lim) as u8;
                        }
                    }
                    Dtype::I8 => run!(i8, |v: i8| (v as i128) <= lim),
                    Dtype::U8 => {
                        // the common case: a table of the 256 answers
                        let table: Vec<u8> = (0..=255u8).map(|v| ((v as i128) <= lim) as u8).collect();
                        for (o, &b) in out.iter_mut().zip(raw) {
                            *o = table[b as usize];
                        }
                    }
                    Dtype::I16 => run!(i16, |v: i16| (v as i128) <= lim),
                    Dtype::U16 => run!(u16, |v: u16| (v as i128) <= lim),
                    Dtype::I32 => run!(i32, |v: i32| (v as i128) <= lim),
                    Dtype::U32 => run!(u32, |v: u32| (v as i128) <= lim),
                    Dtype::I64 => run!(i64, |v: i64| (v as i128) <= lim),
                    _ => run!(u64, |v: u64| (v as i128) <= lim),
                }
            }
            (Level::AtMost(t), Dtype::F32) => run!(f32, |v: f32| (v as f64) <= t),
            (Level::AtMost(t), _) => run!(f64, |v: f64| v <= t),
        }
    }

    /// The cubical set at `level`: cube `(i_0, …, i_{d-1})` of the box `[0, shape)` for each
    /// value `a[i_0, …, i_{d-1}]` in the set. The box is the whole image, whatever the
    /// values; the memory limit is checked before the bitmap is allocated. O(len).
    pub fn to_cubical_set(&self, level: Level) -> Result<CubicalSet, ImportError> {
        let volume = super::cubical::box_checked(&self.shape)? as usize;
        let mut bits = Vec::new();
        bits.try_reserve_exact(volume)
            .map_err(|_| ImportError::OutOfMemory { what: "the bitmap".into(), bytes: volume as u64 })?;
        bits.resize(volume, 0u8);
        match self.order {
            Order::Fortran => self.presence(level, 0, &mut bits),
            Order::C => {
                // layout index m walks the last axis fastest; the bitmap wants axis 0 fastest
                let d = self.dim();
                let mut stride = vec![1usize; d];
                for a in 1..d {
                    stride[a] = stride[a - 1] * self.shape[a - 1];
                }
                let row = self.shape[d - 1];
                let mut buf = vec![0u8; row];
                let mut idx = vec![0usize; d];
                let (last_stride, rows) = (stride[d - 1], volume / row);
                for r in 0..rows {
                    self.presence(level, r * row, &mut buf);
                    let base: usize = (0..d - 1).map(|a| idx[a] * stride[a]).sum();
                    for (k, &b) in buf.iter().enumerate() {
                        bits[base + k * last_stride] = b;
                    }
                    // the next row: axes d-2 … 0, the one before the last fastest
                    for a in (0..d - 1).rev() {
                        idx[a] += 1;
                        if idx[a] < self.shape[a] {
                            break;
                        }
                        idx[a] = 0;
                    }
                }
            }
        }
        CubicalSet::new(vec![0; self.dim()], self.shape.clone(), bits)
    }

    /// An image of the cubes of a set: a `bool` array over the set's box in Fortran order,
    /// `true` for the cubes of the set (`a[x_0 - min_0, …]`).
    pub fn from_cubical_set(set: &CubicalSet) -> Image {
        Image {
            shape: set.shape().to_vec(),
            order: Order::Fortran,
            dtype: Dtype::Bool,
            big_endian: false,
            storage: Storage::Owned(set.bits().to_vec()),
            offset: 0,
            len: set.bits().len(),
        }
    }

    /// The `.npy` header of this image (version 1.0, or 2.0 past 65535 bytes), padded so the
    /// values start at a multiple of 64 bytes, as numpy writes it.
    pub fn npy_header(&self) -> Vec<u8> {
        let endian = if self.dtype.size() == 1 {
            '|'
        } else if self.big_endian {
            '>'
        } else {
            '<'
        };
        let shape = match self.shape.len() {
            1 => format!("({},)", self.shape[0]),
            _ => format!("({})", self.shape.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(", ")),
        };
        let dict = format!(
            "{{'descr': '{endian}{}', 'fortran_order': {}, 'shape': {shape}, }}",
            self.dtype.code(),
            if self.order == Order::Fortran { "True" } else { "False" }
        );
        let (version, pre) = if dict.len() + 1 + 10 < 65536 { (1u8, 10) } else { (2u8, 12) };
        let total = (pre + dict.len() + 1).div_ceil(64) * 64;
        let hlen = total - pre;
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(NPY_MAGIC);
        out.extend_from_slice(&[version, 0]);
        if version == 1 {
            out.extend_from_slice(&(hlen as u16).to_le_bytes());
        } else {
            out.extend_from_slice(&(hlen as u32).to_le_bytes());
        }
        out.extend_from_slice(dict.as_bytes());
        out.resize(total - 1, b' ');
        out.push(b'\n');
        out
    }

    /// Writes the image as `.npy`, its values as they are (dtype, byte order, layout),
    /// through a temporary file and a rename.
    pub fn write_npy(&self, path: &Path) -> std::io::Result<()> {
        gmap_core::io::write_atomic_with(path, |w| {
            w.write_all(&self.npy_header())?;
            w.write_all(self.raw())
        })
    }

    /// Writes the image as a DIPHA image file: its values as `f64`, axis 0 fastest (an image
    /// in C order is transposed on the way, a row at a time).
    pub fn write_dipha(&self, path: &Path) -> std::io::Result<()> {
        gmap_core::io::write_atomic_with(path, |w| {
            for word in [DIPHA_MAGIC, DIPHA_IMAGE_DATA, self.len as i64, self.dim() as i64] {
                w.write_all(&word.to_le_bytes())?;
            }
            for &s in &self.shape {
                w.write_all(&(s as i64).to_le_bytes())?;
            }
            let mut buf: Vec<u8> = Vec::with_capacity(8 * self.shape[0]);
            match self.order {
                Order::Fortran => {
                    for i in 0..self.len {
                        w.write_all(&self.value(i).to_le_bytes())?;
                    }
                }
                Order::C => {
                    // axis 0 fastest: for each index of the other axes, the values along axis 0
                    let d = self.dim();
                    let mut cstride = vec![1usize; d];
                    for a in (0..d - 1).rev() {
                        cstride[a] = cstride[a + 1] * self.shape[a + 1];
                    }
                    let mut idx = vec![0usize; d];
                    for _ in 0..self.len / self.shape[0].max(1) {
                        let base: usize = (1..d).map(|a| idx[a] * cstride[a]).sum();
                        buf.clear();
                        for i in 0..self.shape[0] {
                            buf.extend_from_slice(&self.value(base + i * cstride[0]).to_le_bytes());
                        }
                        w.write_all(&buf)?;
                        for a in 1..d {
                            idx[a] += 1;
                            if idx[a] < self.shape[a] {
                                break;
                            }
                            idx[a] = 0;
                        }
                    }
                }
            }
            Ok(())
        })
    }
}

fn check_dim(d: usize) -> Result<(), ImportError> {
    if d == 0 || d > MAX_DIM {
        return Err(format(format!("an image of dimension {d}: dimensions 1 to {MAX_DIM} are read")));
    }
    Ok(())
}

/// Refuses an image with no pixels (a size 0 along an axis), one message for every command
/// that reads it, the axes in the file's order.
fn check_not_empty(shape: &[usize]) -> Result<(), ImportError> {
    match shape.iter().position(|&s| s == 0) {
        Some(axis) => Err(format(format!(
            "an empty image: the shape {} has no pixels (size 0 along axis {axis})",
            shape_text(shape)
        ))),
        None => Ok(()),
    }
}

/// Maps a file read-only.
fn map_file(path: &Path) -> Result<Storage, FileError> {
    let f = std::fs::File::open(path).map_err(|e| FileError::new(path, e.into()))?;
    let len = f.metadata().map_err(|e| FileError::new(path, e.into()))?.len();
    if len == 0 {
        return Ok(Storage::Owned(Vec::new()));
    }
    // SAFETY: the map is only ever read as plain bytes (`&[u8]`, every bit pattern valid;
    // values are decoded with `from_le_bytes`/`from_be_bytes`). What `Mmap::map` cannot rule
    // out is another process truncating or rewriting the file while it is mapped: the reader
    // then sees the new bytes or, past a truncation, the process gets SIGBUS; the same holds
    // for numpy's `np.load(mmap_mode='r')`. Copying instead would double a 1 GB image's
    // memory and cost a pass over it (docs/PERFORMANCE.md, the 1024³ table).
    let map = unsafe { memmap2::Mmap::map(&f) }.map_err(|e| FileError::new(path, e.into()))?;
    #[cfg(unix)]
    {
        // the passes read the values front to back
        let _ = map.advise(memmap2::Advice::Sequential);
    }
    Ok(Storage::Mapped(map))
}

fn storage_bytes(s: &Storage) -> &[u8] {
    match s {
        Storage::Mapped(m) => m,
        Storage::Owned(v) => v,
    }
}

fn parse_npy(storage: Storage) -> Result<Image, ImportError> {
    let bytes = storage_bytes(&storage);
    if !bytes.starts_with(NPY_MAGIC) {
        let head = &bytes[..bytes.len().min(6)];
        return Err(format(format!("not a .npy file: magic {head:02x?}, expected \\x93NUMPY")));
    }
    let (major, minor) = match bytes.get(6..8) {
        Some(v) => (v[0], v[1]),
        None => return Err(format("a .npy file truncated in its preamble")),
    };
    let (hlen, start) = match (major, minor) {
        (1, 0) => match bytes.get(8..10) {
            Some(b) => (u16::from_le_bytes([b[0], b[1]]) as usize, 10),
            None => return Err(format("a .npy file truncated in its preamble")),
        },
        (2 | 3, 0) => match bytes.get(8..12) {
            Some(b) => (u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize, 12),
            None => return Err(format("a .npy file truncated in its preamble")),
        },
        _ => return Err(format(format!(".npy format version {major}.{minor}: versions 1.0, 2.0 and 3.0 are read"))),
    };
    if hlen > MAX_HEADER {
        return Err(format(format!("a .npy header of {hlen} bytes, over the limit of {MAX_HEADER}")));
    }
    let Some(header) = bytes.get(start..start + hlen) else {
        return Err(format(format!(
            "a .npy file truncated in its header: {} bytes after the preamble, the header has {hlen}",
            bytes.len() - start
        )));
    };
    let text = std::str::from_utf8(header)
        .ok()
        .filter(|t| major == 3 || t.is_ascii())
        .ok_or_else(|| format("the .npy header is not ASCII (UTF-8 in version 3)"))?;
    let h = parse_header_dict(text)?;
    let descr = h.descr.ok_or_else(|| format("the .npy header has no 'descr'"))?;
    let fortran = h.fortran.ok_or_else(|| format("the .npy header has no 'fortran_order'"))?;
    let shape = h.shape.ok_or_else(|| format("the .npy header has no 'shape'"))?;
    let (dtype, big_endian) = parse_descr(&descr)?;
    check_dim(shape.len())?;
    check_not_empty(&shape)?;
    let offset = start + hlen;
    let Some((len, need)) = checked_len(&shape, dtype.size()) else {
        return Err(format(format!("the shape {} overflows the address space", shape_text(&shape))));
    };
    let have = bytes.len() - offset;
    if have < need {
        return Err(format(format!(
            "truncated data: the shape {} of {} needs {need} bytes, the file has {have} after the header",
            shape_text(&shape),
            descr
        )));
    }
    Ok(Image { shape, order: if fortran { Order::Fortran } else { Order::C }, dtype, big_endian, storage, offset, len })
}

/// Refuses a numpy dtype (its `descr`, `'<f2'`) the `.npy` reader does not read, with the
/// reader's message: the one rule for files and for arrays given in memory (the Python
/// package).
pub fn check_dtype(descr: &str) -> Result<(), ImportError> {
    parse_descr(descr).map(drop)
}

fn parse_descr(descr: &str) -> Result<(Dtype, bool), ImportError> {
    let b = descr.as_bytes();
    let bad = || {
        format(format!(
            "dtype '{descr}' is not read: bool, integers (i1–i8, u1–u8) and floats (f4, f8) are; \
             object, string, complex and structured arrays are not"
        ))
    };
    let (order, rest) = match b.first() {
        Some(c @ (b'<' | b'>' | b'|' | b'=')) => (*c, &descr[1..]),
        _ => (b'=', descr),
    };
    let kind = *rest.as_bytes().first().ok_or_else(bad)?;
    let dtype = Dtype::from_code(kind, &rest[1..]).ok_or_else(bad)?;
    let big = match order {
        b'>' => dtype.size() > 1,
        b'=' => cfg!(target_endian = "big") && dtype.size() > 1,
        _ => false,
    };
    Ok((dtype, big))
}

#[derive(Default)]
struct Header {
    descr: Option<String>,
    fortran: Option<bool>,
    shape: Option<Vec<usize>>,
}

/// Parses numpy's header: a Python dict literal with the keys `descr` (a string; a list is
/// a structured dtype, refused), `fortran_order` (`True`/`False`) and `shape` (a tuple of
/// integers), then spaces and a newline.
fn parse_header_dict(text: &str) -> Result<Header, ImportError> {
    let bad =
        |m: &str| format(format!("bad .npy header {}: {m}", gmap_core::io::shorten(text.trim_end().as_bytes(), 120)));
    let mut p = Parser { s: text.as_bytes(), i: 0 };
    let mut h = Header::default();
    p.ws();
    if !p.eat(b'{') {
        return Err(bad("expected a dict '{…}'"));
    }
    loop {
        p.ws();
        if p.eat(b'}') {
            break;
        }
        let key = p.string().ok_or_else(|| bad("expected a quoted key"))?;
        p.ws();
        if !p.eat(b':') {
            return Err(bad("expected ':' after a key"));
        }
        p.ws();
        match key.as_str() {
            "descr" => {
                if p.peek() == Some(b'[') {
                    return Err(bad("a structured dtype (a list of fields) is not read"));
                }
                h.descr = Some(p.string().ok_or_else(|| bad("'descr' is not a string"))?);
            }
            "fortran_order" => {
                h.fortran = Some(if p.word("True") {
                    true
                } else if p.word("False") {
                    false
                } else {
                    return Err(bad("'fortran_order' is neither True nor False"));
                })
            }
            "shape" => h.shape = Some(p.tuple().ok_or_else(|| bad("'shape' is not a tuple of integers"))?),
            other => return Err(bad(&format!("unknown key '{other}'"))),
        }
        p.ws();
        if p.eat(b',') {
            continue;
        }
        p.ws();
        if p.eat(b'}') {
            break;
        }
        return Err(bad("expected ',' or '}'"));
    }
    p.ws();
    if p.i != p.s.len() {
        return Err(bad("text after the dict"));
    }
    Ok(h)
}

struct Parser<'a> {
    s: &'a [u8],
    i: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<u8> {
        self.s.get(self.i).copied()
    }
    fn ws(&mut self) {
        while self.peek().is_some_and(|c| c.is_ascii_whitespace()) {
            self.i += 1;
        }
    }
    fn eat(&mut self, c: u8) -> bool {
        let ok = self.peek() == Some(c);
        self.i += ok as usize;
        ok
    }
    fn word(&mut self, w: &str) -> bool {
        let ok = self.s[self.i..].starts_with(w.as_bytes());
        if ok {
            self.i += w.len();
        }
        ok
    }
    fn string(&mut self) -> Option<String> {
        let q = self.peek().filter(|&c| c == b'\'' || c == b'"')?;
        let start = self.i + 1;
        let end = start + self.s[start..].iter().position(|&c| c == q)?;
        self.i = end + 1;
        String::from_utf8(self.s[start..end].to_vec()).ok()
    }
    fn tuple(&mut self) -> Option<Vec<usize>> {
        if !self.eat(b'(') {
            return None;
        }
        let mut out = Vec::new();
        loop {
            self.ws();
            if self.eat(b')') {
                return Some(out);
            }
            let start = self.i;
            while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                self.i += 1;
            }
            // Python 2 wrote long integers as 10L
            let n = std::str::from_utf8(&self.s[start..self.i]).ok()?.parse::<usize>().ok()?;
            self.eat(b'L');
            out.push(n);
            self.ws();
            if !self.eat(b',') {
                self.ws();
                return self.eat(b')').then_some(out);
            }
        }
    }
}

fn parse_dipha(storage: Storage) -> Result<Image, ImportError> {
    let bytes = storage_bytes(&storage);
    let word = |k: usize| -> Result<i64, ImportError> {
        bytes
            .get(8 * k..8 * k + 8)
            .map(|b| i64::from_le_bytes(b.try_into().unwrap()))
            .ok_or_else(|| format(format!("a DIPHA file truncated in its header (word {k})")))
    };
    let magic = word(0)?;
    if magic != DIPHA_MAGIC {
        return Err(format(format!("not a DIPHA file: magic number {magic}, expected {DIPHA_MAGIC}")));
    }
    let kind = word(1)?;
    if kind != DIPHA_IMAGE_DATA {
        return Err(format(format!(
            "DIPHA file type {kind}: only images (IMAGE_DATA, type {DIPHA_IMAGE_DATA}) are read"
        )));
    }
    let n = word(2)?;
    let d = word(3)?;
    if !(1..=MAX_DIM as i64).contains(&d) {
        return Err(format(format!("a DIPHA image of dimension {d}: dimensions 1 to {MAX_DIM} are read")));
    }
    let d = d as usize;
    let mut shape = Vec::with_capacity(d);
    for k in 0..d {
        let s = word(4 + k)?;
        let s = usize::try_from(s).map_err(|_| format(format!("a DIPHA image with size {s} along axis {k}")))?;
        shape.push(s);
    }
    check_not_empty(&shape)?;
    let Some((len, need)) = checked_len(&shape, 8) else {
        return Err(format(format!("the DIPHA shape {} overflows the address space", shape_text(&shape))));
    };
    if n < 0 || n as u64 != len as u64 {
        return Err(format(format!("the DIPHA header counts {n} values, its shape {} has {len}", shape_text(&shape))));
    }
    let offset = 8 * (4 + d);
    let have = bytes.len() - offset.min(bytes.len());
    if have < need {
        return Err(format(format!(
            "truncated data: the DIPHA shape {} needs {need} bytes of values, the file has {have}",
            shape_text(&shape)
        )));
    }
    Ok(Image { shape, order: Order::Fortran, dtype: Dtype::F64, big_endian: false, storage, offset, len })
}
