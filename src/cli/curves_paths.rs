//! `gmap curves contractible|freely-homotopic|homotopic|simple FILE PATH…`: homotopy tests
//! of paths on a surface (facade `gmap::homotopy`).

use clap::Args;

use super::CurvesFile;
use gmap::homotopy::{PathSpec, Paths};

/// A question about one path.
#[derive(Args, Debug)]
pub struct OnePath {
    #[command(flatten)]
    pub file: CurvesFile,
    /// the path: darts (for each step, a dart of its edge at the vertex it leaves),
    /// separated by spaces or commas; vertex numbers with --vertices
    pub path: String,
    /// read the path as the vertices it passes (consecutive ones joined by one edge)
    #[arg(long)]
    pub vertices: bool,
}

/// A question about two paths.
#[derive(Args, Debug)]
pub struct TwoPaths {
    #[command(flatten)]
    pub file: CurvesFile,
    /// the first path (as for `gmap curves contractible`)
    pub p: String,
    /// the second path
    pub q: String,
    /// read the paths as the vertices they pass
    #[arg(long)]
    pub vertices: bool,
}

/// The question asked.
#[derive(Clone, Copy, Debug)]
pub enum Question {
    Contractible,
    Free,
    Fixed,
    Simple,
}

fn spec(text: &str, vertices: bool) -> gmap::Result<PathSpec> {
    let items: Result<Vec<u64>, _> =
        text.split(|c: char| c == ',' || c.is_whitespace()).filter(|s| !s.is_empty()).map(str::parse::<u64>).collect();
    let items = items
        .map_err(|e| gmap::Error::new(gmap::ErrorKind::Usage, format!("path {text:?}: {e}; give whole numbers")))?;
    Ok(if vertices { PathSpec::Vertices(items) } else { PathSpec::Darts(items) })
}

fn answer(what: &str, yes: bool, json: bool) -> String {
    if json {
        format!("{{\"{what}\":{yes}}}\n")
    } else {
        format!("{}: {}\n", what.replace('_', " "), if yes { "yes" } else { "no" })
    }
}

/// Runs one question.
pub fn one(q: Question, a: &OnePath) -> gmap::Result<String> {
    let input = gmap::open_with(&a.file.file, &gmap::OpenOptions::max_darts(a.file.max_darts))?;
    let paths = Paths::new(&input)?;
    let p = spec(&a.path, a.vertices)?;
    Ok(match q {
        Question::Simple => answer("homotopic_to_simple_cycle", paths.is_homotopic_to_simple_cycle(&p)?, a.file.json),
        _ => answer("contractible", paths.is_contractible(&p)?, a.file.json),
    })
}

/// Runs a question about two paths.
pub fn two(q: Question, a: &TwoPaths) -> gmap::Result<String> {
    let input = gmap::open_with(&a.file.file, &gmap::OpenOptions::max_darts(a.file.max_darts))?;
    let paths = Paths::new(&input)?;
    let (p, r) = (spec(&a.p, a.vertices)?, spec(&a.q, a.vertices)?);
    Ok(match q {
        Question::Fixed => {
            answer("homotopic_with_fixed_endpoints", paths.are_homotopic_with_fixed_endpoints(&p, &r)?, a.file.json)
        }
        _ => answer("freely_homotopic", paths.are_freely_homotopic(&p, &r)?, a.file.json),
    })
}
