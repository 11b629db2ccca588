//! What the facade (`gmap::homology`) does not take: a cubical set borrowed from a numpy
//! array (read in place, without the copy a `CubicalSet` would make), and a report read
//! back from its JSON (how results cross process boundaries). Both give the facade's
//! [`gmap::Report`], so the rest of the package sees one result type.

use gmap::{CellName, Chain, HomologyOptions, NamedGenerator, Report};
use gmap_homology::generators::generators;
use gmap_homology::{homology_z, homology_zp, Homology, Natural};

use crate::errors::{Failure, Kind, Res};

/// A cubical set given by its bitmap: `bits[x_0 + s_0 (x_1 + …)]` non-zero for a cube
/// (axis 0 fastest), the box's minimal vertex at the origin. `reversed`: the caller's axes
/// are those of `shape` in reverse order (a C-ordered numpy array), so cube coordinates are
/// given back reversed.
pub struct Cubes<'a> {
    pub shape: &'a [usize],
    pub bits: &'a [u8],
    pub reversed: bool,
}

/// The homology of a borrowed cubical set, as the facade computes that of a `CubicalSet`:
/// with generators in dimension ≤ 3, from union-finds and a sweep over the grid
/// (`gmap::report::cubical_generators`); in one pass over the cubes where that applies
/// (dimension ≤ 3, no generators:
/// `gmap_homology::cubical::pass`, O(cubes) time, memory O(one layer), the array never copied
/// whole; periodic: `gmap_homology::cubical::torus`, a union-find over the whole box), else the cubical complex of the closure after collapses of free
/// faces (`periodic`: the box a torus), with the facade's checks of the options.
pub fn cubical_array(c: &Cubes<'_>, o: &HomologyOptions) -> Res<Report> {
    if let Some(p) = o.field {
        if !gmap_homology::is_prime(p) || p >= 1 << 31 {
            return Err(Failure::input(format!("--field {p}: the field must be Z/P for a prime P below 2^31")));
        }
    }
    if o.method == gmap::Method::Simplicial {
        return Err(Failure::new(
            Kind::Precondition,
            "a cubical set has no simplicial counterpart here; use --method cellular",
        ));
    }
    if o.via.is_some() {
        return Err(Failure::input("--via direct applies to simplicial complexes (.facets, .lex)"));
    }
    let report = |groups, generators| Report {
        kind: "cubical set",
        dimension: c.shape.len(),
        method: gmap::Method::Cellular,
        route: None,
        field: o.field,
        groups,
        generators,
        note: None,
        space: None,
    };
    // dimension ≤ 3, no generators: the facade's one pass over the cubes,
    // read from the array a layer at a time
    let bits = c.bits;
    let one_pass =
        gmap::route::cubical_one_pass(c.shape, |s, out| out.copy_from_slice(&bits[s..s + out.len()]), o, "the array")
            .map_err(Failure::from)?;
    if let Some(groups) = one_pass {
        return Ok(report(groups, None));
    }
    // dimension ≤ 3 with generators: the facade's cycles from union-finds and a sweep
    // (the cells' axes given back in the caller's order)
    if let Some((groups, gens)) =
        gmap::report::cubical_generators(c.shape, c.bits, &[], c.reversed, o, "the array").map_err(Failure::from)?
    {
        return Ok(report(groups, Some(gens)));
    }
    crate::objects::check_complex_memory(c.shape)?;
    let cc = gmap_homology::cubical::cubical_complex_with(c.shape, c.bits, o.periodic, true)?;
    let groups = match o.field {
        Some(p) => homology_zp(&cc.chain, p),
        None => homology_z(&cc.chain),
    }?;
    let gens = if o.generators {
        let g = generators(&cc.chain, o.field)?;
        let name = |k: usize, j: u32| {
            let coords = cc.coordinates(k, j as usize);
            let mut min: Vec<i64> = coords.iter().map(|&x| (x / 2) as i64).collect();
            let mut extent: Vec<u8> = coords.iter().map(|&x| (x % 2) as u8).collect();
            if c.reversed {
                min.reverse();
                extent.reverse();
            }
            CellName::Cube { min: min.into(), extent: extent.into() }
        };
        Some(
            g.into_iter()
                .map(|x| NamedGenerator {
                    dim: x.dim,
                    chain: Chain::Named(x.chain.iter().map(|&(cell, k)| (name(x.dim, cell), k)).collect()),
                    order: x.order,
                })
                .collect(),
        )
    } else {
        None
    };
    Ok(report(groups, gens))
}

/// Reverses the axes of the cubes named by a report's generators (a set whose numpy axes
/// are the reverse of its storage's).
pub fn reverse_cube_axes(r: &mut Report) {
    for g in r.generators.iter_mut().flatten() {
        g.chain.reverse_cube_axes();
    }
}

/// A report read back from its JSON object ([`Report::to_json`]); `None` when the object is
/// not one.
pub fn report_from_json(v: &serde_json::Value) -> Option<Report> {
    use gmap_homology::Coefficients;
    let nat = |x: &serde_json::Value| -> Option<Natural> { x.to_string().parse().ok() };
    let (coefficients, field) = match v["coefficients"].as_str()? {
        "Z" => (Coefficients::Integers, None),
        s => {
            let p: u64 = s.strip_prefix("Z/")?.parse().ok()?;
            (Coefficients::Field(p), Some(p))
        }
    };
    let betti = v["betti"].as_array()?.iter().map(|b| b.as_u64().map(|b| b as usize)).collect::<Option<Vec<_>>>()?;
    let torsion = v["torsion"]
        .as_array()?
        .iter()
        .map(|t| t.as_array().and_then(|t| t.iter().map(nat).collect::<Option<Vec<_>>>()))
        .collect::<Option<Vec<_>>>()?;
    let method = match v["method"].as_str()? {
        "simplicial" => gmap::Method::Simplicial,
        _ => gmap::Method::Cellular,
    };
    let route = match v.get("route").and_then(|r| r.as_str()) {
        Some("direct") => Some(gmap::Via::Direct),
        Some("gmap") => Some(gmap::Via::Gmap),
        _ => None,
    };
    let cell = |c: &serde_json::Value| -> Option<CellName> {
        if let Some(a) = c.as_array() {
            return Some(CellName::Simplex(a.iter().map(|x| x.as_u64()).collect::<Option<Vec<_>>>()?));
        }
        if let Some(r) = c.get("region") {
            let name = c.get("name").and_then(|n| n.as_str()).map(str::to_string);
            return Some(match (r.as_u64(), r.as_str()) {
                (Some(id), _) if name.is_none() => CellName::Region(id),
                (Some(id), _) => CellName::NamedRegion { id, key: None, name },
                (None, key) => CellName::NamedRegion { id: 0, key: Some(key?.to_string()), name },
            });
        }
        if let Some(cube) = c.get("cube") {
            let min = cube.as_array()?.iter().map(|x| x.as_i64()).collect::<Option<Vec<_>>>()?;
            let extent =
                c["extent"].as_array()?.iter().map(|x| x.as_u64().map(|e| e as u8)).collect::<Option<Vec<_>>>()?;
            return Some(CellName::Cube { min: min.into(), extent: extent.into() });
        }
        let dart = c.get("dart")?.as_u64()? as u32;
        let simplex = match c.get("simplex") {
            Some(s) => Some(s.as_array()?.iter().map(|x| x.as_u64().map(|x| x as u32)).collect::<Option<Vec<_>>>()?),
            None => None,
        };
        let point = match c.get("point") {
            Some(p) => {
                let p = p.as_array()?;
                Some([p.first()?.as_f64()?, p.get(1)?.as_f64()?, p.get(2)?.as_f64()?])
            }
            None => None,
        };
        Some(CellName::Dart { dart, point, simplex })
    };
    let generators = match v.get("generators") {
        Some(g) => Some(
            g.as_array()?
                .iter()
                .map(|x| {
                    let chain = x["chain"].as_array()?;
                    Some(NamedGenerator {
                        dim: x["dim"].as_u64()? as usize,
                        order: nat(&x["order"])?,
                        chain: Chain::Named(
                            chain
                                .iter()
                                .map(|e| Some((cell(&e["cell"])?, e["coefficient"].as_i64()?)))
                                .collect::<Option<Vec<_>>>()?,
                        ),
                    })
                })
                .collect::<Option<Vec<_>>>()?,
        ),
        None => None,
    };
    let kind = match (route, generators.as_ref().and_then(|g| g.iter().flat_map(|x| x.chain.first()).next())) {
        (Some(_), _) => "simplicial complex",
        (None, Some((CellName::Cube { .. }, _))) => "cubical set",
        (None, Some((CellName::Region(_) | CellName::NamedRegion { .. }, _))) => "architectural complex",
        _ => "map",
    };
    Some(Report {
        kind,
        dimension: v["dimension"].as_u64()? as usize,
        method,
        route,
        field,
        groups: Homology { coefficients, betti, torsion },
        generators,
        note: None,
        space: None,
    })
}
