//! `gmap tm check FILE` and `gmap tm views FILE [--cell NAME]`: the TM model's edit check
//! and views (facade `gmap::tm`).

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Subcommand};

/// What `gmap tm` does.
#[derive(Subcommand, Debug)]
pub enum TmCommand {
    /// The topological edit check (TM 7:5, 7:6): every defect, cells by the file's names;
    /// an open model is also checked closed by its exterior cell. Exit 1 when it fails.
    Check(TmFile),
    /// The view of every (n-1)-cell with the n-cells on its near and far sides (for a wall,
    /// its two rooms), or with --cell one cell's view (a 1-cell: its section) cell by cell.
    Views(TmViewsArgs),
}

#[derive(Args, Debug)]
pub struct TmArgs {
    #[command(subcommand)]
    command: TmCommand,
}

#[derive(Args, Debug)]
pub struct TmFile {
    /// the model: an architectural complex (.json) or a G-map (.gmap, .moka, .off, meshes)
    file: PathBuf,
    #[command(flatten)]
    snap: super::SnapArg,
}

#[derive(Args, Debug)]
pub struct TmViewsArgs {
    /// the model: an architectural complex (.json) or a G-map (.gmap, .moka, .off, meshes)
    file: PathBuf,
    /// one cell, by its name, its string id or its number
    #[arg(long)]
    cell: Option<String>,
    #[command(flatten)]
    snap: super::SnapArg,
}

/// Runs `gmap tm …`: prints the report; the exit code is 1 for an error or a failed check.
pub fn run(a: TmArgs) -> ExitCode {
    let done = match a.command {
        TmCommand::Check(f) if f.snap.snap.is_some() => super::open_snapped(&f.file, None, f.snap)
            .and_then(|i| gmap::tm_check(&i))
            .map(|c| (c.to_text(), c.passes())),
        TmCommand::Check(f) => gmap::tm_check_file(&f.file).map(|c| (c.to_text(), c.passes())),
        TmCommand::Views(v) => super::open_snapped(&v.file, None, v.snap)
            .and_then(|i| gmap::tm_views(&i, v.cell.as_deref()))
            .map(|t| (t, true)),
    };
    match done {
        Ok((text, ok)) => {
            print!("{text}");
            if ok {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            }
        }
        Err(e) => {
            eprintln!("error: {}", e.to_string().replace('\n', " "));
            ExitCode::from(1)
        }
    }
}
