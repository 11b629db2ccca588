//! Regions named as the file names them: its ids (integers or strings) and the `name`
//! label, in every message ([`ArchError::named`], [`RegionNames`]).

use std::collections::HashMap;
use std::fmt;

use gmap_core::LabelValue;

use super::model::{ArchComplex, ArchError, RegionId};

/// How messages name regions: the file's string id or the numeric id, followed by the
/// region's `name` label in parentheses when it has one that differs (`door`, `12
/// (kitchen)`). Regions not in the table are named by their number. O(1) a lookup.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RegionNames(HashMap<RegionId, String>);

impl RegionNames {
    /// No names: every region by its number.
    pub fn new() -> Self {
        Self::default()
    }

    /// Names `id` as `name`.
    pub fn insert(&mut self, id: RegionId, name: String) {
        self.0.insert(id, name);
    }

    /// Whether no region has a name of its own.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The name of `id` (its number when it has none).
    pub fn get(&self, id: RegionId) -> String {
        self.0.get(&id).cloned().unwrap_or_else(|| id.to_string())
    }

    /// The name a region with numeric `id`, string id `key` and `name` label gets; `None`
    /// when that is its number.
    pub fn name_of(id: RegionId, key: Option<&str>, name: Option<&str>) -> Option<String> {
        let base = key.map_or_else(|| id.to_string(), str::to_string);
        match name {
            Some(n) if n != base => Some(format!("{base} ({n})")),
            _ => key.map(|_| base),
        }
    }
}

impl ArchComplex {
    /// The name of region `index` in messages: its string id or number, then its `name`
    /// label in parentheses (`door`, `12 (kitchen)`, `7`). O(labels of the region).
    pub fn region_name(&self, index: usize) -> String {
        let r = self.region(index);
        RegionNames::name_of(r.id, self.region_key(index), self.name_label(index)).unwrap_or_else(|| r.id.to_string())
    }

    /// The `name` label of region `index`, when it is a text.
    pub fn name_label(&self, index: usize) -> Option<&str> {
        match self.region_labels(index).get("name") {
            Some(LabelValue::Text(t)) => Some(t),
            _ => None,
        }
    }

    /// The names of every region that has one besides its number ([`ArchComplex::region_name`]).
    /// O(R).
    pub fn region_names(&self) -> RegionNames {
        let mut n = RegionNames::new();
        for (k, r) in self.regions().iter().enumerate() {
            if let Some(name) = RegionNames::name_of(r.id, self.region_key(k), self.name_label(k)) {
                n.insert(r.id, name);
            }
        }
        n
    }
}

fn join_counts(v: &[usize]) -> String {
    v.iter().map(|b| b.to_string()).collect::<Vec<_>>().join(", ")
}

/// The names of `ids`, at most five and how many more.
fn name_list(ids: &[RegionId], n: &dyn Fn(RegionId) -> String) -> String {
    let mut v: Vec<String> = ids.iter().take(5).map(|&i| n(i)).collect();
    if ids.len() > 5 {
        v.push(format!("and {} more", ids.len() - 5));
    }
    v.join(", ")
}

/// [`ArchError::BoundaryOpen`]: where the region is open and what is missing.
fn open_boundary(
    f: &mut fmt::Formatter<'_>,
    n: &dyn Fn(RegionId) -> String,
    id: RegionId,
    dim: usize,
    at: &[RegionId],
    with: Option<RegionId>,
) -> fmt::Result {
    let (faces, face, low) = match dim {
        2 => ("edges", "an edge", "vertices"),
        3 => ("faces", "a face", "edges"),
        _ => ("faces", "a face", "regions"),
    };
    write!(
        f,
        "{dim}-region {} is not closed: its {faces} leave the {low} {} on one of them only, so {face} is missing",
        n(id),
        name_list(at, n)
    )?;
    match (with, dim) {
        (Some(w), _) => write!(
            f,
            "; {} is open at the same place: the face between {} and {} is missing{}",
            n(w),
            n(id),
            n(w),
            if dim == 3 { " (a party wall)" } else { "" }
        ),
        (None, 3) => write!(f, " (a wall, a floor or a roof)"),
        (None, _) => Ok(()),
    }
}

/// An [`ArchError`] displayed with the file's names.
pub struct Named<'a> {
    error: &'a ArchError,
    names: &'a RegionNames,
}

impl ArchError {
    /// The error displayed with regions named by `names` (the file's ids and `name` labels)
    /// instead of their numbers.
    pub fn named<'a>(&'a self, names: &'a RegionNames) -> Named<'a> {
        Named { error: self, names }
    }
}

impl fmt::Display for Named<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = |id: RegionId| self.names.get(id);
        match self.error {
            ArchError::IdsExhausted => {
                write!(f, "no region id is left above the largest id in use ({})", u64::MAX)
            }
            ArchError::DuplicateRegion { id } => write!(f, "duplicate region id {}", n(*id)),
            ArchError::RegionDimension { id, dim, max } => {
                write!(f, "region {} has dimension {dim}, above the complex's dimension {max}", n(*id))
            }
            ArchError::UnknownRegion { from, to, missing } => {
                write!(f, "incidence entry {} -> {} names the unknown region {}", n(*from), n(*to), n(*missing))
            }
            ArchError::DuplicateEntry { from, to } => write!(f, "duplicate incidence entry {} -> {}", n(*from), n(*to)),
            ArchError::Cycle { cycle } => {
                let c: Vec<String> = cycle.iter().map(|&i| n(i)).collect();
                write!(f, "the incidence graph has a cycle: {}", c.join(" -> "))
            }
            ArchError::DimensionNotDecreasing { from, to, from_dim, to_dim } => write!(
                f,
                "incidence entry {} -> {} goes from dimension {from_dim} to dimension {to_dim}: dimension must decrease",
                n(*from),
                n(*to)
            ),
            ArchError::WeightAcrossGap { from, to, from_dim, to_dim, weight } => write!(
                f,
                "incidence entry {} -> {} crosses from dimension {from_dim} to {to_dim} with weight {weight}: an entry across a gap must be 0",
                n(*from),
                n(*to)
            ),
            ArchError::SquareNotZero { from, to, value } => write!(
                f,
                "the boundary of the boundary of region {} is {value} at region {}, not 0: the partial boundary matrix does not square to zero (AC Def. 3.1)",
                n(*from),
                n(*to)
            ),
            ArchError::Overflow { from } => write!(f, "integer overflow while checking δ² at region {}", n(*from)),
            ArchError::RegionBetti { id, dim, betti, reason } => write!(
                f,
                "region {} of dimension {dim} cannot have the Betti numbers ({}): {reason} (AC Def. 8.1)",
                n(*id),
                join_counts(betti)
            ),
            ArchError::RegionTopologyUnknown { id, dim, betti, boundary, reason } => write!(
                f,
                "region {} ({dim}-region with Betti numbers ({}) and {boundary} boundary component(s)): {reason}; Algorithm 8.16 cannot cellulate it (AC Def. 8.1, Theorem 8.11)",
                n(*id),
                join_counts(betti)
            ),
            ArchError::CannotOrient { id, dim, reason, at } => {
                write!(f, "{dim}-region {} cannot be oriented: {reason}", n(*id))?;
                if let Some(a) = at {
                    write!(f, " at region {}", n(*a))?;
                }
                write!(f, "; give the incidence weights")
            }
            ArchError::BoundaryOpen { id, dim, at, with } => open_boundary(f, &n, *id, *dim, at, *with),
            ArchError::LabelNotFinite { id, name } => {
                write!(f, "region {}: the label `{name}` is not a finite real", n(*id))
            }
        }
    }
}

impl fmt::Display for ArchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.named(&RegionNames::new()).fmt(f)
    }
}

impl std::error::Error for ArchError {}
