//! `mpirun -n K gmap-mpi IMAGE.npy`: the integer homology of one image cut across K MPI
//! ranks (`gmap::distributed`). Every rank reads only its slab of the memory-mapped image;
//! rank 0 prints the groups (`gmap homology`'s text or JSON, with the ranks' figures). A
//! failure on any rank ends every rank with the same message (`error: …` on stderr, exit
//! code 1).
//!
//! The messages between ranks are byte strings: a length (u64), then chunks of at most
//! 2^30 bytes (MPI counts are `int`).

use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use gmap::distributed::{run, DistributedOptions, Transport};
use mpi::topology::SimpleCommunicator;
use mpi::traits::*;

/// The integer homology of one image (.npy, DIPHA's .complex) cut across the MPI ranks.
#[derive(Parser, Debug)]
#[command(name = "gmap-mpi", version, about)]
struct Cli {
    /// the image (.npy or DIPHA's .complex)
    image: PathBuf,
    /// print a JSON object (`gmap homology --json`'s, with a section "mpi": one object per rank)
    #[arg(long)]
    json: bool,
    /// the cubical set: the values <= T (default: the non-zero values)
    #[arg(long)]
    level: Option<f64>,
    /// the memory each rank may use, in bytes with an optional K, M, G or T suffix (powers
    /// of 1024); a rank whose estimated cost is larger stops every rank. Default: half the
    /// physical memory
    #[arg(long, value_parser = parse_max_memory)]
    max_memory: Option<u64>,
}

fn parse_max_memory(text: &str) -> Result<u64, String> {
    gmap::core::resources::parse_size(text).map_err(|e| e.to_string())
}

/// The world communicator as a [`Transport`].
struct World(SimpleCommunicator);

const CHUNK: usize = 1 << 30;

impl World {
    fn send(&self, to: i32, bytes: &[u8]) {
        let p = self.0.process_at_rank(to);
        p.send(&(bytes.len() as u64));
        for c in bytes.chunks(CHUNK) {
            p.send(c);
        }
    }

    fn receive(&self, from: i32) -> Vec<u8> {
        let p = self.0.process_at_rank(from);
        let (len, _) = p.receive::<u64>();
        let mut out = vec![0u8; len as usize];
        for c in out.chunks_mut(CHUNK) {
            p.receive_into(c);
        }
        out
    }
}

impl Transport for World {
    fn rank(&self) -> usize {
        self.0.rank() as usize
    }

    fn size(&self) -> usize {
        self.0.size() as usize
    }

    fn gather(&self, bytes: Vec<u8>) -> Option<Vec<Vec<u8>>> {
        if self.0.rank() != 0 {
            self.send(0, &bytes);
            return None;
        }
        let mut all = Vec::with_capacity(self.size());
        all.push(bytes);
        for r in 1..self.0.size() {
            all.push(self.receive(r));
        }
        Some(all)
    }

    fn broadcast(&self, bytes: Vec<u8>) -> Vec<u8> {
        let root = self.0.process_at_rank(0);
        let mut len = bytes.len() as u64;
        root.broadcast_into(&mut len);
        let mut out = if self.0.rank() == 0 { bytes } else { vec![0u8; len as usize] };
        for c in out.chunks_mut(CHUNK) {
            root.broadcast_into(c);
        }
        out
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let Some(universe) = mpi::initialize() else {
        eprintln!("error: MPI could not be initialised (or was already)");
        return ExitCode::FAILURE;
    };
    let world = World(universe.world());
    if let Some(bytes) = cli.max_memory {
        gmap::core::resources::set_max_memory(bytes);
    }
    let mut options = DistributedOptions::default();
    options.level = cli.level;
    match run(&world, &cli.image, &options) {
        Ok(Some(d)) => {
            if cli.json {
                println!("{}", serde_json::to_string_pretty(&d.to_json()).expect("a JSON value prints"));
            } else {
                print!("{}", d.to_text());
            }
            ExitCode::SUCCESS
        }
        Ok(None) => ExitCode::SUCCESS,
        Err(e) => {
            // one write: the ranks' lines reach mpirun's stderr whole, not interleaved
            let _ = std::io::stderr().write_all(format!("error: {e}\n").as_bytes());
            ExitCode::FAILURE
        }
    }
}
