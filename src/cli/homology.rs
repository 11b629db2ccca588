//! `gmap homology FILE [--method cellular|simplicial] [--field P] [--json] [--generators]`.

use std::io::IsTerminal;
use std::path::PathBuf;

use anyhow::{bail, Context, Result};
use gmap_core::DenseMap;
use gmap_homology::arch::{ArchComplex, ZeroWeightRule};
use gmap_homology::{
    cellular_complex, homology_z, homology_zp, is_prime, simplicial_complex_with_simplices, ChainComplex, Homology,
};
use serde_json::json;

use super::load::{load, Loaded};
use super::Method;

/// Options of `gmap homology`.
pub struct Options {
    pub file: PathBuf,
    pub method: Method,
    pub field: Option<u64>,
    pub json: bool,
    pub generators: bool,
    pub simplify: bool,
    pub topological: bool,
    pub max_darts: Option<u64>,
    pub periodic: bool,
}

/// When the command started (for the elapsed times of the progress lines).
static START: std::sync::OnceLock<std::time::Instant> = std::sync::OnceLock::new();

/// Prints a stage message on stderr when it is a terminal (docs/FORMATS.md §1: progress only
/// there), with the time elapsed since the start: `gmap homology: [  0.41 s] reducing…`.
fn progress(msg: &str) {
    if std::io::stderr().is_terminal() {
        let t = START.get_or_init(std::time::Instant::now).elapsed().as_secs_f64();
        eprintln!("gmap homology: [{t:7.2} s] {msg}…");
    }
}

/// A chain complex with a printable name for each generator (for `--generators`).
struct Named {
    chain: ChainComplex,
    names: Vec<Vec<String>>,
}

fn cellular(map: &DenseMap, file: &str) -> Result<Named> {
    progress("checking C1 and C2 and building the border operator");
    let c = cellular_complex(map)
        .with_context(|| format!("{file}: the cellular method does not apply (use --method simplicial)"))?;
    let names = c.reps.iter().map(|r| r.iter().map(|d| format!("cell of dart {d}")).collect()).collect();
    Ok(Named { chain: c.chain, names })
}

fn simplicial(map: &DenseMap) -> Named {
    progress("building the simplicial counterpart");
    let s = simplicial_complex_with_simplices(map);
    let names = s
        .simplices
        .iter()
        .map(|v| {
            v.iter()
                .map(|x| {
                    let labels: Vec<String> =
                        (0..32).filter(|i| x.labels & (1 << i) != 0).map(|i| i.to_string()).collect();
                    format!("simplex {{{}}} of dart {}", labels.join(","), x.dart)
                })
                .collect()
        })
        .collect();
    Named { chain: s.chain, names }
}

/// The chain complex of an architectural complex (`.json`): the completion by zero of its
/// partial boundary matrix (AC Def. 3.9), after Algorithm 8.16 with `--topological`.
fn complex(x: ArchComplex, o: &Options, file: &str) -> Result<Named> {
    if o.method == Method::Simplicial {
        bail!("{file}: an architectural complex has no simplicial counterpart; use --method cellular");
    }
    let x = if o.topological {
        let t = x.topological(ZeroWeightRule::Closed).with_context(|| format!("{file}: Algorithm 8.16"))?;
        for op in &t.operators {
            progress(&format!("Algorithm 8.16: {op}"));
        }
        t.complex
    } else {
        x
    };
    let names = (0..=x.dim())
        .map(|k| x.regions_of_dim(k).iter().map(|&r| format!("region {}", x.region(r as usize).id)).collect())
        .collect();
    Ok(Named { chain: x.chain_complex(), names })
}

fn compute(c: &ChainComplex, field: Option<u64>) -> Result<Homology> {
    progress(&format!(
        "reducing {} cells ({} matrix entries): collapses, coreductions, then elimination",
        c.counts().iter().sum::<usize>(),
        (1..c.counts().len()).map(|k| c.boundary(k).nnz()).sum::<usize>()
    ));
    Ok(match field {
        Some(p) => homology_zp(c, p)?,
        None => homology_z(c)?,
    })
}

/// The map reduced by `--simplify`, or the map itself where the reduction could change the
/// groups. Removals and contractions keep the homology only when the cells are homology
/// balls (conditions C1 and C2, docs/DESIGN.md): where they fail (a segment with open ends, a
/// map of loose darts), simplifying would merge components and lose classes, so it is skipped,
/// with the reason on stderr when stderr is a terminal. As a guard, a reduction that changes
/// the number of components is dropped too. Either way the groups are those without
/// `--simplify`.
pub fn simplified(map: DenseMap) -> DenseMap {
    progress("checking C1 and C2 before simplifying");
    if let Err(e) = gmap_homology::check_preconditions(&map) {
        note(&format!("--simplify skipped: the cells are not all homology balls ({e})"));
        return map;
    }
    progress("simplifying by removals and contractions of cells");
    let small = gmap_ops::euler::simplify(&map).0;
    if small.component_count() != map.component_count() {
        note("--simplify skipped: the reduction changed the number of components");
        return map;
    }
    small
}

/// A note on stderr when it is a terminal (nothing otherwise: the output stays the same).
fn note(msg: &str) {
    if std::io::stderr().is_terminal() {
        eprintln!("gmap homology: {msg}");
    }
}

pub fn run(o: &Options) -> Result<()> {
    if let Some(p) = o.field {
        if !is_prime(p) || p >= 1 << 31 {
            bail!("--field {p}: the field must be Z/P for a prime P below 2^31");
        }
    }
    START.get_or_init(std::time::Instant::now);
    let file = o.file.display().to_string();
    progress(&format!("reading {file}"));
    let loaded = load(&o.file, o.max_darts)?;
    if o.periodic && !matches!(loaded, Loaded::Cubical(_)) {
        bail!("{file}: --periodic applies to cubical sets (.cub, .pbm)");
    }
    let (dim, named) = match loaded {
        Loaded::Cubical(set) => {
            progress("building the cubical complex");
            let (chain, names) = super::cubical::complex(&set, o, &file)?;
            (set.dim(), Named { chain, names })
        }
        Loaded::Map(map) => {
            if o.topological {
                bail!("{file}: --topological applies to architectural complexes (.json), not to G-maps");
            }
            let map = if o.simplify { simplified(map) } else { map };
            let named = match o.method {
                Method::Cellular => cellular(&map, &file)?,
                Method::Simplicial => simplicial(&map),
            };
            (map.dim(), named)
        }
        Loaded::Complex(x) => {
            if o.simplify {
                bail!("{file}: --simplify applies to G-maps, not to architectural complexes (.json)");
            }
            (x.dim(), complex(x, o, &file)?)
        }
    };
    let h = compute(&named.chain, o.field).with_context(|| file.clone())?;
    let method = match o.method {
        Method::Cellular => "cellular",
        Method::Simplicial => "simplicial",
    };
    let gens = if o.generators {
        progress("computing generators and lifting them to the input's cells");
        Some(gmap_homology::generators::generators(&named.chain, o.field).with_context(|| file.clone())?)
    } else {
        None
    };
    if o.json {
        let mut v = json!({
            "dimension": dim,
            "method": method,
            "coefficients": h.coefficients.to_string(),
            "betti": h.betti,
            "torsion": h.torsion,
            "euler_characteristic": h.euler_characteristic(),
        });
        if let Some(g) = &gens {
            let list: Vec<_> = g
                .iter()
                .map(|x| {
                    json!({
                        "dimension": x.dim,
                        "order": x.order,
                        "chain": x.chain.iter().map(|&(cell, coef)| json!({
                            "cell": named.names[x.dim][cell as usize],
                            "index": cell,
                            "coefficient": coef,
                        })).collect::<Vec<_>>(),
                    })
                })
                .collect();
            v["generators"] = json!(list);
        }
        outln!("{v}")?;
    } else {
        outln!("dimension {dim}, method {method}, coefficients {}", h.coefficients)?;
        for k in 0..h.betti.len() {
            outln!("H_{k} = {}", h.group_string(k))?;
        }
        outln!("euler characteristic {}", h.euler_characteristic())?;
        if let Some(g) = &gens {
            for x in g {
                let order = match (x.order, o.field) {
                    (0, None) => "Z".to_string(),
                    (0, Some(p)) => format!("Z/{p}"),
                    (t, _) => format!("Z/{t}"),
                };
                let terms: Vec<String> = x
                    .chain
                    .iter()
                    .map(|&(cell, coef)| format!("{coef:+} [{}]", named.names[x.dim][cell as usize]))
                    .collect();
                outln!("generator of H_{} ({order}): {}", x.dim, terms.join(" "))?;
            }
        }
    }
    Ok(())
}

/// The `homology` column of `gmap demo`: integer homology written as `(Z, Z + Z/2, 0)`, by
/// the cellular method where C1 and C2 hold, else by the simplicial one (marked `*`).
pub fn demo_homology(m: &DenseMap) -> String {
    let cell = cellular_complex(m).ok().map(|c| homology_z(&c.chain));
    match cell {
        Some(Ok(h)) => h.to_string(),
        Some(Err(e)) => format!("error: {e}"),
        None => match homology_z(&gmap_homology::simplicial_complex(m)) {
            Ok(h) => format!("{h}*"),
            Err(e) => format!("error: {e}"),
        },
    }
}

/// The `cellular = simplicial` column of `gmap demo`: `yes`, `NO`, or `n/a` with the
/// condition that keeps the cellular method from applying.
pub fn demo_agreement(m: &DenseMap) -> String {
    let s = homology_z(&gmap_homology::simplicial_complex(m));
    match cellular_complex(m) {
        Err(gmap_homology::PreconditionError::C1(_)) => "n/a (C1)".to_string(),
        Err(gmap_homology::PreconditionError::C2 { .. }) => "n/a (C2)".to_string(),
        Ok(c) => match (homology_z(&c.chain), s) {
            (Ok(a), Ok(b)) if a == b => "yes".to_string(),
            _ => "NO".to_string(),
        },
    }
}
