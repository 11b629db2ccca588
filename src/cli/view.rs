//! `gmap view FILE [-o OUT.html] [--generators] [--color-by LABEL]`: one self-contained HTML
//! page of the input (`gmap::view`), written to `OUT.html` (default: the input's name with
//! `.html`).

use std::path::PathBuf;

use clap::Args;

use super::Limits;

#[derive(Args, Debug)]
pub(super) struct ViewArgs {
    #[arg(help = super::input_help("the input file"))]
    file: PathBuf,
    /// the page to write (default: FILE with the extension .html, in the current folder)
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// compute the homology generators and draw each in its own colour
    #[arg(long)]
    generators: bool,
    /// the label that colours the cells (default: the first text label of the highest
    /// dimension with labels)
    #[arg(long)]
    color_by: Option<String>,
    #[command(flatten)]
    limits: Limits,
    #[command(flatten)]
    snap: super::SnapArg,
}

pub(super) fn view(a: ViewArgs, quiet: bool) -> gmap::Result<String> {
    let progress = gmap::Progress::stderr("gmap view", quiet);
    progress.stage("reading");
    let input = super::open_snapped(&a.file, a.limits.max_darts, a.snap)?;
    let mut o = gmap::ViewOptions::default();
    (o.generators, o.color_by) = (a.generators, a.color_by);
    progress.stage("building the page");
    let page = gmap::view(&input, &o);
    progress.finish();
    let out = a.output.unwrap_or_else(|| PathBuf::from(a.file.file_stem().unwrap_or_default()).with_extension("html"));
    gmap::core::io::write_atomic(&out, page?.as_bytes())
        .map_err(|e| gmap::Error::new(gmap::ErrorKind::Write, format!("{}: {e}", out.display())))?;
    Ok(format!("wrote {}\n", out.display()))
}
