//! What a file holds, as an [`Input`], and the extension of a path; [`crate::open`] reads it by the reader of its
//! format in the registry ([`crate::formats`]: the table of extensions, readers and the kind
//! of input each makes). `.dot`, `.graphml` and `.lar.json` are written only: opening one is
//! refused with that reason. A `.vtk` is read as an unstructured grid (what the `.vtk`
//! writer writes is one), its cells sewn face to face and its data as labels.
//! The memory policy (`gmap_core::resources`) applies to every reader: a file whose
//! estimated cost is over the limit is refused before it is read.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use gmap_core::{DenseLabels, DenseMap, LabelledGMap};
use gmap_homology::arch::ArchComplex;
use gmap_ops::import::{CubicalSet, Image, SimplicialComplex};

use crate::error::{err, Error, Result};

/// What an input holds, as [`Input`]'s variants name it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Kind {
    /// a generalized map ([`Input::Map`])
    Map,
    /// a simplicial complex ([`Input::Simplicial`])
    Simplicial,
    /// a cubical set or cubical cell complex ([`Input::Cubical`])
    Cubical,
    /// a grey-value image ([`Input::Image`])
    Image,
    /// an architectural complex or incidence graph ([`Input::Arch`])
    Arch,
}

impl Kind {
    /// Every kind, in the order of [`Input`]'s variants.
    pub const ALL: [Kind; 5] = [Kind::Map, Kind::Simplicial, Kind::Cubical, Kind::Image, Kind::Arch];

    /// The name messages use: `"map"`, `"simplicial complex"`, `"cubical set"` (an image is
    /// one, at a level), `"architectural complex"`.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Map => "map",
            Kind::Simplicial => "simplicial complex",
            Kind::Cubical | Kind::Image => "cubical set",
            Kind::Arch => "architectural complex",
        }
    }

    /// The class of the Python package that holds an input of this kind.
    pub fn python_class(self) -> &'static str {
        match self {
            Kind::Map => "GMap",
            Kind::Simplicial => "SimplicialComplex",
            Kind::Cubical => "CubicalSet",
            Kind::Image => "Image",
            Kind::Arch => "ArchComplex",
        }
    }

    /// Whether an input of this kind is a cubical set (a set of cubes, or an image at a level).
    pub fn is_cubical(self) -> bool {
        matches!(self, Kind::Cubical | Kind::Image)
    }
}

/// Options of [`crate::open_with`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[non_exhaustive]
pub struct OpenOptions {
    /// refuse a map with more darts than this (default: what the memory budget holds); for
    /// a simplicial complex, the limit of its G-map, made when a route asks for it
    pub max_darts: Option<u64>,
    /// a `.json` complex with points: weld the points within this distance and split the
    /// edges and faces at T-junctions before reading it (what was done is in
    /// [`Input::notes`]); without it, a complex whose points do not conform is refused
    pub snap: Option<f64>,
}

impl OpenOptions {
    /// Options with a dart limit.
    pub fn max_darts(max_darts: Option<u64>) -> Self {
        OpenOptions { max_darts, snap: None }
    }

    /// These options, snapping `.json` points within `eps` (`None`: no snapping).
    pub fn with_snap(self, eps: Option<f64>) -> Self {
        OpenOptions { snap: eps, ..self }
    }
}

/// What an input file holds.
#[derive(Debug)]
#[non_exhaustive]
pub enum Input {
    /// a generalized map (`.gmap`, `.moka`, `.off`; `.vtk`, `.vtu`, `.msh` meshes)
    Map(MapInput),
    /// a simplicial complex (`.facets`, `.lex`): every route starts from its facets
    Simplicial(Sourced<SimplicialComplex>),
    /// a cubical set (`.cub`, `.pbm`) or cubical cell complex (`.cub`, `.cel`)
    Cubical(Sourced<CubicalSet>),
    /// a grey-value image (`.npy`, DIPHA's `.complex`): a cubical set at a level
    /// (`HomologyOptions::level`; default: the non-zero values)
    Image(Sourced<Image>),
    /// an architectural complex or incidence graph (`.json`)
    Arch(Sourced<ArchComplex>),
}

/// A generalized map with the file it came from.
#[derive(Debug)]
pub struct MapInput {
    map: DenseMap,
    source: Source,
    /// the map with the labels of its cells: read when first asked for (`.gmap`), or kept
    /// from the reading (meshes)
    labelled: OnceLock<std::result::Result<Box<LabelledGMap>, Error>>,
    /// the simplicial complex the map is the G-map of ([`MapInput::of_complex`]), whose
    /// vertex labels name the cells of its generators
    complex: Option<std::sync::Arc<Sourced<SimplicialComplex>>>,
}

/// What a file held, with the file it came from (messages name it). Derefs to the value.
#[derive(Debug)]
pub struct Sourced<T> {
    value: T,
    source: Source,
}

/// Where an input came from: the file (for messages), the dart limit it was opened with,
/// and whether the file carries labels read on demand ([`MapInput::labelled`]).
#[derive(Clone, Debug, Default)]
pub(crate) struct Source {
    path: PathBuf,
    max_darts: Option<u64>,
    labels_in_file: bool,
    /// what reading changed (a snapped complex's welds and splits), one line each
    notes: Vec<String>,
    /// the values a `.facets` file gives its facets (`: VALUE`), in the complex's facet
    /// order: a filtration, which [`crate::persistence()`] reads
    facet_values: Option<std::sync::Arc<[f64]>>,
}

impl Source {
    /// The file `path` opened with `opts`.
    pub(crate) fn file(path: &Path, opts: &OpenOptions) -> Self {
        Source {
            path: path.to_path_buf(),
            max_darts: opts.max_darts,
            labels_in_file: false,
            notes: Vec::new(),
            facet_values: None,
        }
    }

    /// This source, with the values its file gives the facets of its complex.
    pub(crate) fn valued(self, facet_values: Option<Vec<f64>>) -> Self {
        Source { facet_values: facet_values.map(Into::into), ..self }
    }

    /// This source, with what reading changed.
    pub(crate) fn noting(self, notes: Vec<String>) -> Self {
        Source { notes, ..self }
    }

    /// A `.gmap` file, whose labels are read when first asked for.
    pub(crate) fn labelled_file(path: &Path, opts: &OpenOptions) -> Self {
        Source { labels_in_file: true, ..Source::file(path, opts) }
    }

    /// `value`, read from this source.
    pub(crate) fn holding<T>(self, value: T) -> Sourced<T> {
        Sourced { value, source: self }
    }
}

impl Input {
    /// A map read from `source`.
    pub(crate) fn map_from(map: DenseMap, source: Source) -> Self {
        Input::Map(MapInput { map, source, labelled: OnceLock::new(), complex: None })
    }

    /// A map read from `source` with its labels and points (a mesh).
    pub(crate) fn labelled_map_from(g: LabelledGMap, source: Source) -> Self {
        let map = g.to_dense_map();
        Input::Map(MapInput { map, source, labelled: OnceLock::from(Ok(Box::new(g))), complex: None })
    }

    /// What the input holds, as the format registry names it.
    pub fn input_kind(&self) -> Kind {
        match self {
            Input::Map(_) => Kind::Map,
            Input::Simplicial(_) => Kind::Simplicial,
            Input::Cubical(_) => Kind::Cubical,
            Input::Image(_) => Kind::Image,
            Input::Arch(_) => Kind::Arch,
        }
    }

    /// The dimension of what the input holds.
    pub fn dim(&self) -> usize {
        match self {
            Input::Map(m) => m.map.dim(),
            Input::Simplicial(s) => s.dim(),
            Input::Cubical(c) => c.dim(),
            Input::Image(i) => i.dim(),
            Input::Arch(x) => x.dim(),
        }
    }

    /// The name of what the input holds: `"map"`, `"simplicial complex"`, `"cubical set"`,
    /// `"architectural complex"`.
    pub fn kind(&self) -> &'static str {
        self.input_kind().name()
    }

    /// The file the input was read from (empty for one built in memory).
    pub fn path(&self) -> &Path {
        match self {
            Input::Map(m) => m.path(),
            Input::Simplicial(s) => s.path(),
            Input::Cubical(c) => c.path(),
            Input::Image(i) => i.path(),
            Input::Arch(x) => x.path(),
        }
    }

    /// What reading changed, one line each: the points welded and the cells split by
    /// [`OpenOptions::snap`] (empty for anything else).
    pub fn notes(&self) -> &[String] {
        match self {
            Input::Map(m) => &m.source.notes,
            Input::Simplicial(s) => &s.source.notes,
            Input::Cubical(c) => &c.source.notes,
            Input::Image(i) => &i.source.notes,
            Input::Arch(x) => &x.source.notes,
        }
    }

    /// The G-map of the input: the map itself, or the G-map of a simplicial complex's facets
    /// (a pure pseudo-manifold; refused with the reason otherwise). Cubical sets and
    /// architectural complexes have none here.
    pub fn to_map(&self) -> Result<std::borrow::Cow<'_, DenseMap>> {
        match self {
            Input::Map(m) => Ok(std::borrow::Cow::Borrowed(&m.map)),
            Input::Simplicial(s) => s.to_gmap().map(std::borrow::Cow::Owned),
            other => Err(err!(Precondition, "a {} is not a G-map", other.kind())),
        }
    }
}

impl MapInput {
    /// A map built in memory (no file).
    pub fn new(map: DenseMap) -> Self {
        MapInput { map, source: Source::default(), labelled: OnceLock::new(), complex: None }
    }

    /// A map with points and labels built in memory (no file): the labels are kept for
    /// [`MapInput::labelled`] (the page of [`crate::view()`] colours cells by them).
    pub fn from_labelled(g: LabelledGMap) -> Self {
        let map = g.to_dense_map();
        MapInput { map, source: Source::default(), labelled: OnceLock::from(Ok(Box::new(g))), complex: None }
    }

    /// The G-map of a simplicial complex's facets ([`Sourced::to_gmap`], refused with the
    /// reason when the complex has none) that keeps the complex: the cellular route names
    /// the cells of its generators by the complex's vertex labels, as the complex's own
    /// G-map route does (`Via::Gmap`); the other routes name them by darts. The map reads
    /// the complex's file, if it has one.
    pub fn of_complex(complex: std::sync::Arc<Sourced<SimplicialComplex>>) -> Result<Self> {
        let map = complex.to_gmap()?;
        let source = complex.source.clone();
        Ok(MapInput { map, source, labelled: OnceLock::new(), complex: Some(complex) })
    }

    /// The simplicial complex the map is the G-map of, when it was made from one
    /// ([`MapInput::of_complex`]).
    pub fn complex(&self) -> Option<&SimplicialComplex> {
        self.complex.as_deref().map(Sourced::get)
    }

    /// The map.
    pub fn map(&self) -> &DenseMap {
        &self.map
    }

    /// The map, taken out.
    pub fn into_map(self) -> DenseMap {
        self.map
    }

    /// The file the map was read from (empty for a map built in memory).
    pub fn path(&self) -> &Path {
        &self.source.path
    }

    /// The map with its points and the labels of every dimension, when it was read from a
    /// `.gmap` file (which carries them; read again from the file the first time it is asked
    /// for, so that opening a map for its groups pays nothing for labels) or from a mesh
    /// (`.vtk`, `.vtu`, `.msh`: its data); `None` for other sources.
    pub fn labelled(&self) -> Option<Result<&LabelledGMap>> {
        if let Some(read) = self.labelled.get() {
            return Some(read.as_ref().map(|g| &**g).map_err(Clone::clone));
        }
        if !self.source.labels_in_file {
            return None;
        }
        let read = self.labelled.get_or_init(|| {
            let opts = gmap_core::io::ReadOptions { max_darts: self.source.max_darts };
            gmap_core::io::read_labelled_gmap_with(&self.source.path, &opts)
                .map(Box::new)
                .map_err(|e| limit_hint(e.into()))
        });
        Some(read.as_ref().map(|g| &**g).map_err(Clone::clone))
    }

    /// The labels of the map's cells numbered as [`DenseMap::cells`] numbers them, with the
    /// map they number (the labelled file's own dense map); `None` for sources without labels.
    pub fn dense_labels(&self) -> Option<Result<(DenseMap, DenseLabels)>> {
        self.labelled().map(|g| {
            g.map(|g| {
                let (m, labels, _) = gmap_core::to_dense_labels(g);
                (m, labels)
            })
        })
    }
}

impl<T> Sourced<T> {
    /// A value built in memory (no file).
    pub fn new(value: T) -> Self {
        Sourced { value, source: Source::default() }
    }

    /// The value.
    pub fn get(&self) -> &T {
        &self.value
    }

    /// The value, taken out.
    pub fn into_inner(self) -> T {
        self.value
    }

    /// The file the value was read from (empty for one built in memory).
    pub fn path(&self) -> &Path {
        &self.source.path
    }
}

impl<T> Sourced<T> {
    /// Another value from the same file.
    pub(crate) fn with_value<U>(&self, value: U) -> Sourced<U> {
        Sourced { value, source: self.source.clone() }
    }
}

impl<T> std::ops::Deref for Sourced<T> {
    type Target = T;
    fn deref(&self) -> &T {
        &self.value
    }
}

impl Sourced<SimplicialComplex> {
    /// A complex built in memory with a value per facet (in the order of its facets) as
    /// its filtration; refuses a count of values other than the facets'.
    pub fn with_facet_values(sc: SimplicialComplex, values: Vec<f64>) -> Result<Self> {
        let facets = sc.facets().count();
        if values.len() != facets {
            return Err(Error::new(
                crate::error::ErrorKind::Usage,
                format!("{} values for {facets} facets: give one value per facet", values.len()),
            ));
        }
        Ok(Source::default().valued(Some(values)).holding(sc))
    }

    /// The values the complex's file gives its facets (`: VALUE` after each facet of a
    /// `.facets` file), in the order of [`SimplicialComplex::facets`]; `None` for a file
    /// without values. [`crate::persistence()`] filters the complex by them.
    pub fn facet_values(&self) -> Option<&[f64]> {
        self.source.facet_values.as_deref()
    }

    /// The G-map of the facets (a pure pseudo-manifold), refused past the dart limit the
    /// input was opened with (default: what the memory budget holds) and with the reason
    /// when the complex has none (a ridge in three facets, mixed dimensions).
    pub fn to_gmap(&self) -> Result<DenseMap> {
        self.to_gmap_within(self.source.max_darts)
    }

    /// [`Sourced::to_gmap`] with another dart limit (`None`: what the memory budget holds).
    pub fn to_gmap_within(&self, max_darts: Option<u64>) -> Result<DenseMap> {
        self.value
            .to_gmap_within(max_darts)
            .map_err(|e| limit_hint(gmap_ops::import::FileError::new(&self.source.path, e).into()))
    }
}

/// Adds the option that raises the limit to a refusal for darts.
pub(crate) fn limit_hint(e: Error) -> Error {
    if e.is_dart_limit() && !e.is_hard_limit() {
        e.flattened("; raise the limit with --max-darts N")
    } else {
        e
    }
}

/// The lower-cased extension of a path. A `#` belongs to the file name (`run#3.gmap`) unless
/// the path names a `.lex` complex, `FILE.lex#name`, and no file has the whole path (see
/// [`split_lex_name`]): the extension is taken from the real path when it exists.
pub fn extension(path: &Path) -> String {
    let (file, name) = split_lex_name(path);
    let base = if name.is_some() && !path.exists() { file.as_path() } else { path };
    base.extension().map(|e| e.to_string_lossy().to_lowercase()).unwrap_or_default()
}

/// Splits `FILE.lex#name` into the file and the complex name (none without `#`). The split
/// is at the first `#` after `.lex`, so names that hold `#` themselves (Lutz's
/// `manifold_lex_d3_n5_#1`) stay whole.
pub fn split_lex_name(path: &Path) -> (PathBuf, Option<String>) {
    let s = path.to_string_lossy();
    match s.to_ascii_lowercase().find(".lex#") {
        Some(k) => {
            let name = &s[k + 5..];
            (PathBuf::from(&s[..k + 4]), (!name.is_empty()).then(|| name.to_string()))
        }
        None => (path.to_path_buf(), None),
    }
}
