//! The homology of one image cut across several processes (the `gmap-mpi` binary runs it
//! on MPI ranks): every process reads only its slab of the memory-mapped file, reduces it
//! apart, and sends what is left to process 0, which glues the slabs and finishes.
//!
//! The image is cut along its slowest axis (the last of [`Image::memory_shape`]) into one
//! slab of consecutive layers per process ([`gmap_core::parallel::split_ranges`]):
//!
//! * dimension 3: the one-pass route's blocks ([`gmap_homology::cubical::pass::block_pass`]:
//!   union-finds of the set and of its complement, χ; a block past the first also reads the
//!   last layer of the one before, the shared layer), merged by
//!   [`gmap_homology::cubical::pass::merge_blocks`]: the groups of `gmap homology`'s one-pass
//!   route, free by Alexander duality;
//! * other dimensions: the slab's cubical complex reduced with its cells on the cuts kept
//!   ([`gmap_homology::cubical::blocks`]), glued along the cut cells and finished by
//!   [`gmap_homology::homology_z`]: exact over `Z`, torsion included, the groups of the
//!   cubical complex of the whole image.
//!
//! **Failures.** The steps run in the same order on every process, and after each the
//! processes [`agree`]: a process that failed (a file it cannot read, a slab over its
//! `--max-memory`, a panic) reports its message, and every process returns the message of
//! the lowest failing rank, so all of them stop with the same error and none waits for a
//! message that will not come.
//!
//! **Traffic.** Each process sends one message to process 0 (its slab's summary or reduced
//! complex, [`RankReport::bytes_sent`]) and a few hundred bytes of agreement and figures;
//! process 0 sends one status to each. [`Transport`] is all the messaging the route needs,
//! so [`run`] is the same code whatever carries the bytes; [`run_in_process`] computes the
//! slabs one after the other in this process, through the same messages (the tests without
//! MPI).

use std::ops::Range;
use std::path::Path;
use std::time::Instant;

use gmap_homology::cubical::blocks::{block_complex, glue, BlockComplex};
use gmap_homology::cubical::pass::{block_pass, merge_blocks, BlockSummary, BYTES_PER_LAYER_CUBE};
use gmap_homology::homology::Coefficients;
use gmap_homology::{homology_z, Homology};
use gmap_ops::import::{Image, Level};
use serde_json::json;

use crate::error::{err, Error, ErrorKind, Result};
use crate::options::Method;
use crate::report::Report;

/// The messaging [`run`] needs between `size()` processes numbered `0..size()`. Every
/// process calls the same methods in the same order (collective calls).
pub trait Transport {
    /// This process's number.
    fn rank(&self) -> usize;
    /// The number of processes.
    fn size(&self) -> usize;
    /// Process 0 receives every process's bytes (its own included) in rank order; the
    /// others receive `None`.
    fn gather(&self, bytes: Vec<u8>) -> Option<Vec<Vec<u8>>>;
    /// Every process receives process 0's bytes (what the others pass is ignored).
    fn broadcast(&self, bytes: Vec<u8>) -> Vec<u8>;
}

/// How the slabs are computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SlabRoute {
    /// dimension 3: the one-pass route's blocks
    OnePass,
    /// other dimensions: each slab's cubical complex, reduced with its cut cells kept
    Complex,
}

impl SlabRoute {
    /// `"one-pass blocks"` or `"slab complexes"`.
    pub fn name(self) -> &'static str {
        match self {
            SlabRoute::OnePass => "one-pass blocks",
            SlabRoute::Complex => "slab complexes",
        }
    }
}

/// What one process did: its layers, time, memory and traffic.
#[derive(Clone, Debug, PartialEq)]
pub struct RankReport {
    /// the process's number
    pub rank: usize,
    /// its layers of the slowest axis (its own; a one-pass block past the first reads the
    /// layer before them too)
    pub layers: Range<usize>,
    /// seconds from the start to its message being ready
    pub seconds: f64,
    /// its peak resident memory (`VmHWM`, mapped pages read included), where readable;
    /// process 0's is taken after gluing and finishing
    pub peak_rss: Option<u64>,
    /// the bytes of its message to process 0
    pub bytes_sent: u64,
    /// the cells of its reduced slab (the slab-complex route)
    pub cells_sent: Option<u64>,
}

impl RankReport {
    fn to_json(&self) -> serde_json::Value {
        json!({
            "rank": self.rank,
            "layers": [self.layers.start, self.layers.end],
            "seconds": self.seconds,
            "peak_rss_bytes": self.peak_rss,
            "bytes_sent": self.bytes_sent,
            "cells_sent": self.cells_sent,
        })
    }

    fn from_json(v: &serde_json::Value) -> Option<RankReport> {
        let n = |k: &str| v.get(k).and_then(serde_json::Value::as_u64);
        let layers = v.get("layers")?.as_array()?;
        Some(RankReport {
            rank: n("rank")? as usize,
            layers: layers.first()?.as_u64()? as usize..layers.get(1)?.as_u64()? as usize,
            seconds: v.get("seconds")?.as_f64()?,
            peak_rss: n("peak_rss_bytes"),
            bytes_sent: n("bytes_sent")?,
            cells_sent: n("cells_sent"),
        })
    }
}

/// What process 0 returns: the groups, as `gmap homology` reports them, and what each
/// process did.
#[derive(Clone, Debug)]
pub struct Distributed {
    /// the groups (kind `cubical set`, cellular, over `Z`)
    pub report: Report,
    /// how the slabs were computed
    pub route: SlabRoute,
    /// one per process, in rank order
    pub ranks: Vec<RankReport>,
    /// seconds from the start to the groups, on process 0
    pub seconds: f64,
}

impl Distributed {
    /// `gmap homology --json`'s object with a section `"mpi"`: the route, the number of
    /// processes, the time and one object per process (`rank`, `layers`, `seconds`,
    /// `peak_rss_bytes`, `bytes_sent`, `cells_sent`).
    pub fn to_json(&self) -> serde_json::Value {
        let mut v = self.report.to_json();
        v["mpi"] = json!({
            "route": self.route.name(),
            "processes": self.ranks.len(),
            "seconds": self.seconds,
            "ranks": self.ranks.iter().map(RankReport::to_json).collect::<Vec<_>>(),
        });
        v
    }

    /// `gmap homology`'s text, then a line for the route and one per process.
    pub fn to_text(&self) -> String {
        use std::fmt::Write as _;
        let mut out = self.report.to_text();
        let _ = writeln!(out, "{} processes, {}, {:.3} s", self.ranks.len(), self.route.name(), self.seconds);
        for r in &self.ranks {
            let peak = r.peak_rss.map_or("?".to_string(), |b| format!("{:.1} MB", b as f64 / 1e6));
            let cells = r.cells_sent.map(|c| format!(", {c} cells")).unwrap_or_default();
            let _ = writeln!(
                out,
                "rank {}: layers {}..{}, {:.3} s, peak {peak}, sent {} bytes{cells}",
                r.rank, r.layers.start, r.layers.end, r.seconds, r.bytes_sent
            );
        }
        out
    }
}

/// The options of [`run`].
#[derive(Clone, Copy, Debug, Default)]
#[non_exhaustive]
pub struct DistributedOptions {
    /// the image's cubical set: the values `≤ T` (default: the non-zero values)
    pub level: Option<f64>,
}

/// Runs on every process: the groups of the image at `path` cut across the processes of
/// `t`. Process 0 returns `Some` of the groups and the figures, the others `None`; a failure
/// anywhere is every process's `Err`, with the message of the lowest failing rank.
pub fn run(t: &dyn Transport, path: &Path, o: &DistributedOptions) -> Result<Option<Distributed>> {
    let start = Instant::now();
    let file = path.display().to_string();
    let level = o.level.map_or(Level::Nonzero, Level::AtMost);
    // every process reads the header (the map costs no data) and makes the same plan
    let opened = guarded(|| {
        let img = Image::read(path).map_err(|e| Error::from_source(ErrorKind::Parse, e))?;
        let plan = Plan::new(&img, t.size()).map_err(|e| e.context(file.clone()))?;
        Ok((img, plan))
    });
    let (img, plan) = agree(t, opened)?;
    let rank = t.rank();
    let message = guarded(|| plan.block(&img, level, rank).map_err(|e| e.context(file.clone())));
    let (message, cells_sent) = agree(t, message)?;
    let figures = plan.figures(rank, start, &message, cells_sent);
    let messages = t.gather(message);
    let figures = t.gather(figures);
    drop(img);
    let done = match (messages, figures) {
        (Some(messages), Some(figures)) => {
            guarded(|| Ok(Some(finish(&plan, &messages, &figures, start).map_err(|e| e.context(file.clone()))?)))
        }
        _ => Ok(None),
    };
    agree(t, done)
}

/// The slabs of `path` computed one after the other in this process, as `processes`
/// processes would: the same groups and figures as [`run`] on that many (the messages go
/// through their bytes too). What the tests without MPI run.
pub fn run_in_process(path: &Path, processes: usize, o: &DistributedOptions) -> Result<Distributed> {
    let start = Instant::now();
    let file = path.display().to_string();
    let level = o.level.map_or(Level::Nonzero, Level::AtMost);
    let img = Image::read(path).map_err(|e| Error::from_source(ErrorKind::Parse, e))?;
    let plan = Plan::new(&img, processes.max(1)).map_err(|e| e.context(file.clone()))?;
    let mut messages = Vec::with_capacity(processes);
    let mut figures = Vec::with_capacity(processes);
    for rank in 0..plan.ranges.len() {
        let t0 = Instant::now();
        let (m, cells_sent) = plan.block(&img, level, rank).map_err(|e| e.context(file.clone()))?;
        figures.push(plan.figures(rank, t0, &m, cells_sent));
        messages.push(m);
    }
    finish(&plan, &messages, &figures, start).map_err(|e| e.context(file))
}

/// Every process learns whether any failed: process 0 collects the outcomes and sends back
/// the first failure (lowest rank), which every process returns as `rank R: message`; else
/// each keeps its value.
pub fn agree<T>(t: &dyn Transport, mine: Result<T>) -> Result<T> {
    let word = match &mine {
        Ok(_) => Vec::new(),
        Err(e) => {
            let mut w = vec![kind_code(e.kind())];
            w.extend(format!("rank {}: {e}", t.rank()).into_bytes());
            w
        }
    };
    let first = t.gather(word).and_then(|all| all.into_iter().find(|w| !w.is_empty())).unwrap_or_default();
    let first = t.broadcast(first);
    match (mine, first.split_first()) {
        (Ok(v), None) => Ok(v),
        (Err(e), None) => Err(e),
        (_, Some((&code, text))) => Err(Error::new(kind_of(code), String::from_utf8_lossy(text).into_owned())),
    }
}

const KINDS: [ErrorKind; 7] = [
    ErrorKind::Parse,
    ErrorKind::Unsupported,
    ErrorKind::Limit,
    ErrorKind::Precondition,
    ErrorKind::Usage,
    ErrorKind::Write,
    ErrorKind::Compute,
];

fn kind_code(k: ErrorKind) -> u8 {
    KINDS.iter().position(|&x| x == k).unwrap_or(KINDS.len() - 1) as u8
}

fn kind_of(code: u8) -> ErrorKind {
    KINDS.get(code as usize).copied().unwrap_or(ErrorKind::Compute)
}

/// `f`, with a panic turned into an error (so that a process that panics still takes part
/// in the agreement and the others stop too).
fn guarded<T>(f: impl FnOnce() -> Result<T>) -> Result<T> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or_else(|p| {
        let why = p
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| p.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic".to_string());
        Err(err!(Compute, "internal error: {why}"))
    })
}

/// The cut of an image: its shape fastest axis first, the route, each process's layers.
struct Plan {
    shape: Vec<usize>,
    route: SlabRoute,
    ranges: Vec<Range<usize>>,
}

impl Plan {
    fn new(img: &Image, processes: usize) -> Result<Plan> {
        let shape = img.memory_shape();
        let d = shape.len();
        if shape.contains(&0) {
            return Err(err!(Usage, "an empty image (shape {:?}) has no cubes to cut", img.shape()));
        }
        let n = shape[d - 1];
        if processes > n {
            return Err(err!(
                Usage,
                "{processes} processes for an image of {n} layers along its slowest axis: at most {n}"
            ));
        }
        let route = if d == 3 { SlabRoute::OnePass } else { SlabRoute::Complex };
        Ok(Plan { shape, route, ranges: gmap_core::parallel::split_ranges(n, processes) })
    }

    /// Process `rank`'s [`RankReport`] as the bytes it sends: `message` made since `start`.
    fn figures(&self, rank: usize, start: Instant, message: &[u8], cells_sent: Option<u64>) -> Vec<u8> {
        let r = RankReport {
            rank,
            layers: self.ranges[rank].clone(),
            seconds: start.elapsed().as_secs_f64(),
            peak_rss: gmap_core::resources::peak_rss(),
            bytes_sent: message.len() as u64,
            cells_sent,
        };
        r.to_json().to_string().into_bytes()
    }

    /// Process `rank`'s message (its block's summary or its reduced slab) and, for a slab,
    /// the number of cells it holds.
    fn block(&self, img: &Image, level: Level, rank: usize) -> Result<(Vec<u8>, Option<u64>)> {
        let fill = |s: usize, out: &mut [u8]| img.presence(level, s, out);
        let r = self.ranges[rank].clone();
        let limit = |e: gmap_homology::cubical::CubicalError| Error::from_source(ErrorKind::Limit, e);
        match self.route {
            SlabRoute::OnePass => {
                let pp = (self.shape[0] + 2) as u64 * (self.shape[1] + 2) as u64;
                gmap_core::resources::check_memory(
                    "the layers of the one-pass cubical homology",
                    pp.checked_mul(BYTES_PER_LAYER_CUBE),
                )
                .map_err(|e| Error::from_source(ErrorKind::Limit, e))?;
                // a block past the first starts with the last layer of the one before
                let from = if rank == 0 { 0 } else { r.start - 1 };
                let b = block_pass(&self.shape, from..r.end, rank > 0, &fill).map_err(limit)?;
                Ok((b.to_bytes(), None))
            }
            SlabRoute::Complex => {
                let b = block_complex(&self.shape, r, &fill).map_err(limit)?;
                Ok((b.to_bytes(), Some(b.cell_count() as u64)))
            }
        }
    }
}

/// Process 0: the groups from every process's message, and the figures.
fn finish(plan: &Plan, messages: &[Vec<u8>], figures: &[Vec<u8>], start: Instant) -> Result<Distributed> {
    let bad = |e: gmap_homology::cubical::CubicalError| Error::from_source(ErrorKind::Compute, e);
    let d = plan.shape.len();
    let groups = match plan.route {
        SlabRoute::OnePass => {
            let blocks = messages
                .iter()
                .map(|m| BlockSummary::from_bytes(&plan.shape, m).map_err(bad))
                .collect::<Result<Vec<_>>>()?;
            for (rank, (b, r)) in blocks.iter().zip(&plan.ranges).enumerate() {
                if b.layers.end != r.end {
                    return Err(err!(Compute, "rank {rank} sent the block of layers {:?}, not ..{}", b.layers, r.end));
                }
            }
            let one = merge_blocks(&plan.shape, &blocks);
            Homology {
                coefficients: Coefficients::Integers,
                betti: one.betti.iter().map(|&b| usize::try_from(b).unwrap_or(usize::MAX)).collect(),
                torsion: vec![Vec::new(); d + 1],
            }
        }
        SlabRoute::Complex => {
            let blocks =
                messages.iter().map(|m| BlockComplex::from_bytes(m).map_err(bad)).collect::<Result<Vec<_>>>()?;
            let whole = glue(&plan.shape, &blocks).map_err(bad)?;
            homology_z(&whole).map_err(Error::from)?
        }
    };
    let mut ranks = figures
        .iter()
        .map(|f| {
            serde_json::from_slice(f)
                .ok()
                .and_then(|v| RankReport::from_json(&v))
                .ok_or_else(|| err!(Compute, "a process's figures could not be read"))
        })
        .collect::<Result<Vec<_>>>()?;
    if let Some(r0) = ranks.first_mut() {
        r0.peak_rss = gmap_core::resources::peak_rss();
    }
    let report = Report {
        kind: "cubical set",
        dimension: d,
        method: Method::Cellular,
        route: None,
        field: None,
        groups,
        generators: None,
        note: None,
        space: None,
    };
    Ok(Distributed { report, route: plan.route, ranks, seconds: start.elapsed().as_secs_f64() })
}
